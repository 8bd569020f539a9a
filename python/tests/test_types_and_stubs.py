"""The package's type information is true to what it does: the TypedDicts of conforma.types have exactly the keys
the functions return, the stubs (.pyi) declare every public name with the run-time signatures (parameter names,
defaults), py.typed is there; and the run-time files (share/) come with the package."""
import ast
import filecmp
import inspect
import pathlib
import re
import warnings

import pytest

import conforma
from conforma import types

PACKAGE = pathlib.Path(conforma.__file__).resolve().parent
SOURCE = pathlib.Path(__file__).resolve().parents[2]


def keys_of(typed_dict):
    return set(typed_dict.__required_keys__) | set(typed_dict.__optional_keys__)


@pytest.fixture(scope="module")
def wheel():
    return conforma.contact(conforma.Track(), lateral_m=3e-3, model="conformal", side="left")[0]


def test_contact_dicts_have_the_typed_keys(wheel):
    assert set(wheel) == keys_of(types.Wheel)
    assert set(wheel["pose"]) == keys_of(types.Pose)
    patch = wheel["patches"][0]
    assert set(patch) == keys_of(types.Patch)
    assert set(patch["fields"]) == keys_of(types.Fields)
    assert set(patch["grid"]) == keys_of(types.Grid)
    without = conforma.contact(conforma.Track(), lateral_m=3e-3, side="left", fields=False)[0]["patches"][0]
    assert set(patch) - set(without) == set(types.Patch.__optional_keys__) == {"fields", "grid"}


def test_other_dicts_have_the_typed_keys(shared_data):
    assert set(conforma.wheel_dimensions(conforma.s1002())) == keys_of(types.Dimensions)
    assert set(conforma.Track().rigid_equilibrium(0.0)) == keys_of(types.RigidEquilibrium)
    if conforma.has_wear:
        check = conforma.check_scenario(conforma.scenario_path())
        assert set(check) == keys_of(types.ScenarioCheck)
        assert set(check["track_classes"][0]) == keys_of(types.TrackClass)
        d = conforma.load_scenario(conforma.scenario_path("metro_curves"))  # no drive torques: centred allowed
        d["kinematics"] = {"provider": "centred"}
        run = conforma.wear(d, model="hertz", steps=1, base_dir=str(SOURCE / "scenarios"))
        assert set(run) == keys_of(types.WearRun)
        assert set(run["steps"]) == keys_of(types.WearSteps)


def stub_functions(path):
    """name -> ast.FunctionDef of the module-level functions and of the methods (Class.name) of a .pyi file."""
    tree = ast.parse(path.read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[node.name] = node
        elif isinstance(node, ast.ClassDef):
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    out[f"{node.name}.{item.name}"] = item
    return out


def stub_parameters(fn):
    """[(name, default source or None, keyword_only)] of a stub function, self left out."""
    a = fn.args
    positional = a.posonlyargs + a.args
    defaults = [None] * (len(positional) - len(a.defaults)) + [ast.unparse(d) for d in a.defaults]
    params = [(p.arg, d, False) for p, d in zip(positional, defaults) if p.arg != "self"]
    params += [(p.arg, None if d is None else ast.unparse(d), True) for p, d in zip(a.kwonlyargs, a.kw_defaults)]
    return params


def pybind_parameters(obj):
    """[(name, default repr or None)] from the first line of a pybind11 docstring: name(a: T = default, ...)."""
    line = obj.__doc__.splitlines()[0]
    inner = line[line.index("(") + 1:line.rindex(")")]
    params = []
    for part in re.split(r",\s(?=\w+:)", inner) if inner else []:
        name, _, rest = part.partition(":")
        default = rest.split(" = ", 1)[1] if " = " in rest else None
        if name != "self":
            params.append((name.strip(), default))
    return params


def same_default(stub_default, runtime_default):
    if stub_default == "...":  # a default that depends on the machine (the shared data folder)
        return runtime_default is not None
    return (stub_default is None and runtime_default is None) or \
        (stub_default is not None and runtime_default is not None and
         ast.literal_eval(stub_default) == ast.literal_eval(runtime_default))


def test_core_stub_matches_the_extension_signatures():
    stubs = stub_functions(PACKAGE / "_core.pyi")
    checked = 0
    for name in dir(conforma._core):
        if name.startswith("_"):
            continue
        obj = getattr(conforma._core, name)
        members = [(f"{name}.{m}", getattr(obj, m)) for m in ["__init__"] + dir(obj)
                   if (m == "__init__" or not m.startswith("_")) and callable(getattr(obj, m))
                   and "(self: conforma._core" in (getattr(obj, m).__doc__ or "")] if isinstance(obj, type) else []
        for full, fn in ([(name, obj)] if callable(obj) and not isinstance(obj, type) else []) + members:
            assert full in stubs, f"{full} is not declared in _core.pyi"
            runtime = pybind_parameters(fn)
            declared = [(n, d) for n, d, _ in stub_parameters(stubs[full])]
            assert [n for n, _ in declared] == [n for n, _ in runtime], full
            for (n, sd), (_, rd) in zip(declared, runtime):
                assert same_default(sd, rd), (full, n, sd, rd)
            checked += 1
    assert checked >= 15


def test_public_stub_declares_every_public_name_and_the_wrappers():
    tree = ast.parse((PACKAGE / "__init__.pyi").read_text())
    declared = set()
    for node in tree.body:
        if isinstance(node, ast.ImportFrom):
            declared |= {a.asname for a in node.names if a.asname}
        elif isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            declared.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            declared.add(node.target.id)
    missing = set(conforma.__all__) - declared
    assert not missing, f"public names without a stub: {sorted(missing)}"
    stubs = stub_functions(PACKAGE / "__init__.pyi")
    for name in ["contact", "contact_at_pose", "manchester", "wear"]:
        wrapper = stub_parameters(stubs[name])
        core = [(n, d, False) for n, d, _ in stub_parameters(stub_functions(PACKAGE / "_core.pyi")[name])]
        assert wrapper == core + [("strict", "False", True)], name
        assert inspect.signature(getattr(conforma, name)).parameters["strict"].default is False
    # the table's wrapper method (conforma.ContactLut, a subclass of _core.ContactLut)
    wrapper = stub_parameters(stubs["ContactLut.evaluate"])
    core = [(n, d, False) for n, d, _ in stub_parameters(stub_functions(PACKAGE / "_core.pyi")["ContactLut.evaluate"])]
    assert wrapper == core + [("strict", "False", True)]
    assert inspect.signature(conforma.ContactLut.evaluate).parameters["strict"].default is False
    for name in ["share_dir", "scenario_path", "patch_grid"]:
        runtime = list(inspect.signature(getattr(conforma, name)).parameters)
        assert [n for n, _, _ in stub_parameters(stubs.get(name) or
                                                 stub_functions(PACKAGE / "_grid.pyi")[name])] == runtime


def test_stubs_and_marker_are_in_the_package():
    for name in ["py.typed", "__init__.pyi", "_core.pyi", "_grid.pyi", "_status.pyi"]:
        assert (PACKAGE / name).is_file(), name


def test_share_dir_holds_the_scenarios_and_standard_profiles(monkeypatch, tmp_path):
    share = conforma.share_dir()
    assert share == PACKAGE / "share"
    for rel in ["scenarios/default_metro.yaml", "profiles/S1002.prw", "profiles/60E1.prr",
                "profiles/wear_laws/usfd.csv"]:
        assert filecmp.cmp(share / rel, SOURCE / rel, shallow=False), rel
    assert conforma.scenario_path() == str(share / "scenarios" / "default_metro.yaml")
    assert conforma.scenario_path("default_metro.yaml") == conforma.scenario_path()
    with pytest.raises(conforma.InputError, match="no scenario 'nowhere'.*default_metro"):
        conforma.scenario_path("nowhere")
    monkeypatch.setenv("CONFORMA_SHARE_DIR", str(tmp_path))
    assert conforma.share_dir() == tmp_path
    with pytest.raises(conforma.InputError, match="there are: none"):
        conforma.scenario_path()


def test_loading_a_packaged_profile_file():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        p = conforma.load_profile(str(conforma.share_dir() / "profiles" / "S1002.prw"))
    assert p.kind == "wheel"
    assert conforma.wheel_dimensions(p)["sd_mm"] == pytest.approx(32.5, abs=0.05)
