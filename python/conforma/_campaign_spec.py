"""Campaign file (YAML) -> the list of cases, every input error found before any case runs (conforma.campaign).

Layout (README.md "Campaigns")::

    name: friction_smoothing
    base: ../scenarios/default_metro.yaml     # base scenario, relative to the campaign file
    command: wear                             # wear (default) | compare | validate
    models: [hertz, conformal]                # wear: one case per model; compare / validate: all in each case
    steps: 3                                  # --steps of every case (absent: the scenario's)
    args: []                                  # more arguments of the command (validate: --measured FILE ...)
    combine: product                          # product (every combination, the default) | zip (same lengths)
    parameters:                               # scenario keys by dotted path (list items by index)
      friction: [0.25, 0.35]                               # a list
      update.smoothing_mm: {from: 5, to: 9, step: 2}       # a range, both ends included (or count: N instead of step)
      kinematics.dynamic.irregularity.seed: {random: integers, low: 1, high: 99999, count: 4, seed: 7}
      track_classes.3.friction: {random: uniform, low: 0.2, high: 0.4, count: 3, seed: 1}   # also normal: mean, std
    outputs:
      steps_columns: [km, sd_mm, sh_mm, qr_mm]   # steps.csv columns whose last row goes into results.csv
      final_profiles: true                       # keep the wheel (and rail) profiles of the last step
      files: []                                  # more output files to keep (glob patterns in the run's folder)

A case's id is the first 12 hex digits of the SHA-256 of its parameters (dotted path -> value), its model(s), the
command, steps, args and the SHA-256 of the base scenario file: the same case has the same id on every machine and
run, and an edited base scenario gives new ids (old results are not reused for it).
"""
import copy
import hashlib
import itertools
import json
import math
import pathlib
import random
import re

import yaml


class CampaignError(ValueError):
    """A campaign that cannot run (bad file, unknown parameter, empty range, unreachable scheduler); raised before
    any case runs."""


COMMANDS = ("wear", "compare", "validate")
DEFAULT_COLUMNS = ["km", "sd_mm", "sh_mm", "qr_mm", "tread_wear_mm", "flange_wear_mm"]
MAX_CASES = 100000  # cases of one campaign (each a wear, compare or validate run)
_TOP_KEYS = {"name", "base", "command", "models", "steps", "args", "combine", "parameters", "outputs"}
_OUTPUT_KEYS = {"steps_columns", "final_profiles", "files"}
# scenario keys whose text may be a file relative to the scenario's folder (include/conforma/scenario.hpp)
_PATH_KEYS = [("profiles", "wheel"), ("profiles", "rail"), ("wear_law",), ("rail_wear_law",),
              ("track_classes_csv", "file")]


class _Loader(yaml.SafeLoader):
    """The campaign file: numbers as YAML 1.2 reads them, 1e-6 is a number and 1:20 is text (YAML 1.1, PyYAML's
    default, reads them the other way round: text and the base-60 integer 80). The base scenario is NOT read with
    it but as text (yaml.BaseLoader, every scalar a string): the scenario reader (yaml-cpp) gives a scalar its type
    by key, and 50E4 is a rail there, not the number 500000."""


_INT, _FLOAT = "tag:yaml.org,2002:int", "tag:yaml.org,2002:float"
_Loader.yaml_implicit_resolvers = {
    first: [(tag, rx) for tag, rx in resolvers if tag not in (_INT, _FLOAT)]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()}
_Loader.add_implicit_resolver(_INT, re.compile(r"^[-+]?[0-9]+$"), list("-+0123456789"))
_Loader.add_implicit_resolver(
    _FLOAT, re.compile(r"^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?|[-+]?\.(?:inf|Inf|INF)"
                       r"|\.(?:nan|NaN|NAN))$"), list("-+0123456789."))
_Loader.add_constructor(_INT, lambda loader, node: int(loader.construct_scalar(node), 10))


def _load_yaml(text):
    return yaml.load(text, Loader=_Loader)


def _fail(where, message):
    raise CampaignError(f"{where}: {message}")


def _number(value, where, key):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        _fail(where, f"'{key}' must be a finite number, got {value!r}")
    return value


def _clean(x):
    """A computed float rounded to 12 significant digits (0.1 * 3 -> 0.3, not 0.30000000000000004)."""
    return float(f"{x:.12g}")


def _expand_values(spec, where):
    """The values of one parameter: a list, {values: [...]}, a range {from, to, step | count} or a seeded random
    draw {random: uniform | normal | integers, ..., count, seed}."""
    if isinstance(spec, list):
        values = spec
    elif isinstance(spec, dict) and set(spec) == {"values"} and isinstance(spec["values"], list):
        values = spec["values"]
    elif isinstance(spec, dict) and "random" in spec:
        values = _random_values(spec, where)
    elif isinstance(spec, dict) and ("from" in spec or "to" in spec):
        values = _range_values(spec, where)
    elif isinstance(spec, (int, float, str, bool)):
        values = [spec]
    else:
        _fail(where, f"expected a list, {{values: [...]}}, {{from, to, step|count}} or {{random: ...}}, got {spec!r}")
    if not values:
        _fail(where, "no values (an empty list or range): the campaign would have no cases")
    return values


def _check_count(n, where):
    if n > MAX_CASES:  # (count: 1e9 or step: 1e-15 hung before the first case, fuzzing, session 25)
        _fail(where, f"{n} values, more than {MAX_CASES} cases per campaign")


def _range_values(spec, where):
    extra = set(spec) - {"from", "to", "step", "count"}
    if extra or "from" not in spec or "to" not in spec or (("step" in spec) == ("count" in spec)):
        _fail(where, f"a range is {{from, to, step}} or {{from, to, count}}, got {spec!r}")
    a, b = _number(spec["from"], where, "from"), _number(spec["to"], where, "to")
    if "count" in spec:
        n = spec["count"]
        if isinstance(n, bool) or not isinstance(n, int) or n < 0:
            _fail(where, f"'count' must be an integer >= 0, got {n!r}")
        if n == 1 and a != b:
            _fail(where, "count 1 with from != to: which end?")
        _check_count(n, where)
        return [] if n == 0 else [_clean(a + (b - a) * i / (n - 1)) if n > 1 else a for i in range(n)]
    step = _number(spec["step"], where, "step")
    if step == 0:
        _fail(where, "step 0")
    if (b - a) / step < -1e-9:
        _fail(where, f"empty range: from {a} to {b} with step {step}")
    if not math.isfinite((b - a) / step):
        _fail(where, f"a range from {a} to {b} with step {step} is not finite")
    n = int(math.floor((b - a) / step + 1e-9)) + 1
    _check_count(n, where)
    all_int = all(isinstance(v, int) for v in (a, b, step))
    return [a + i * step if all_int else _clean(a + i * step) for i in range(n)]


def _random_values(spec, where):
    kind = spec["random"]
    keys = {"uniform": {"low", "high"}, "normal": {"mean", "std"}, "integers": {"low", "high"}}
    if kind not in keys:
        _fail(where, f"random: '{kind}' is not one of {', '.join(keys)}")
    allowed = keys[kind] | {"random", "count", "seed"}
    if set(spec) - allowed or not keys[kind] <= set(spec) or "seed" not in spec or "count" not in spec:
        _fail(where, f"random: {kind} needs {', '.join(sorted(keys[kind]))}, count and seed; got {sorted(spec)}")
    n, seed = spec["count"], spec["seed"]
    if isinstance(n, bool) or not isinstance(n, int) or n < 0:
        _fail(where, f"'count' must be an integer >= 0, got {n!r}")
    if isinstance(seed, bool) or not isinstance(seed, int):
        _fail(where, f"'seed' must be an integer, got {seed!r}")
    _check_count(n, where)
    rng = random.Random(seed)  # Mersenne Twister: the same draws on every machine and Python 3
    if kind == "integers":
        lo, hi = spec["low"], spec["high"]
        if not all(isinstance(v, int) and not isinstance(v, bool) for v in (lo, hi)) or hi < lo:
            _fail(where, f"random: integers needs integers low <= high, got {lo!r}, {hi!r}")
        return [rng.randint(lo, hi) for _ in range(n)]
    if kind == "uniform":
        lo, hi = _number(spec["low"], where, "low"), _number(spec["high"], where, "high")
        if hi < lo:
            _fail(where, f"random: uniform needs low <= high, got {lo}, {hi}")
        return [_clean(rng.uniform(lo, hi)) for _ in range(n)]
    mean, std = _number(spec["mean"], where, "mean"), _number(spec["std"], where, "std")
    if std < 0:
        _fail(where, f"random: normal needs std >= 0, got {std}")
    return [_clean(rng.gauss(mean, std)) for _ in range(n)]


def _split_path(path):
    return [int(p) if p.isdigit() else p for p in path.split(".")]


def check_parameter_path(scenario, path, where):
    """The dotted path must lead through the base scenario's maps and lists to a key of a map that is there (the
    key itself may be absent: an optional key of the scenario, which the scenario reader then checks)."""
    node, parts = scenario, _split_path(path)
    for depth, part in enumerate(parts):
        last = depth == len(parts) - 1
        here = ".".join(str(p) for p in parts[:depth]) or "the top level"
        if isinstance(node, list):
            if not isinstance(part, int) or part >= len(node):
                _fail(where, f"not a key of the scenario: {here} is a list of {len(node)} items, no item '{part}'")
        elif isinstance(node, dict):
            if isinstance(part, int):
                part = str(part)
            if part not in node and not last:
                _fail(where, f"not a key of the scenario: no '{part}' in {here} (there are: {', '.join(map(str, node))})")
        else:
            _fail(where, f"not a key of the scenario: {here} is a value ({node!r}), not a map")
        if not last:
            node = node[part]


def scalar_text(value):
    """A parameter's value as the text of a scalar of the scenario file."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return repr(value) if isinstance(value, float) else str(value)


class TextDumper(yaml.SafeDumper):
    """Writes the scenario's text scalars as they were (plain where YAML allows): no resolver makes it quote 0.3
    or 50E4 as strings that would look like numbers to YAML 1.1."""


TextDumper.yaml_implicit_resolvers = {}


def dump_scenario(scenario):
    return yaml.dump(scenario, Dumper=TextDumper, sort_keys=False, default_flow_style=False, allow_unicode=True)


def set_parameter(scenario, path, value):
    parts = _split_path(path)
    node = scenario
    for part in parts[:-1]:
        node = node[part if isinstance(node, list) else str(part) if isinstance(part, int) else part]
    last = parts[-1]
    node[last if isinstance(node, list) else str(last) if isinstance(last, int) else last] = value


def _absolute_paths(scenario, folder):
    """Relative file paths of the base scenario made absolute (the generated scenario lives elsewhere); a text that
    is not a file there (a built-in name such as S1002 or usfd) is left as it is."""
    for keys in _PATH_KEYS:
        node = scenario
        for k in keys[:-1]:
            node = node.get(k) if isinstance(node, dict) else None
        if isinstance(node, dict) and isinstance(node.get(keys[-1]), str):
            text = node[keys[-1]]
            if text and not text.startswith(("/", "$")) and (folder / text).is_file():
                node[keys[-1]] = str((folder / text).resolve())


def case_id(record):
    text = json.dumps(record, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def load_campaign(path):
    """Reads and checks a campaign file; returns a dict: name, file, base (path), command, models, steps, args,
    outputs, parameters (path -> values), cases (list of dicts: id, params, models, scenario (dict))."""
    path = pathlib.Path(path)
    where = str(path)
    try:
        doc = _load_yaml(path.read_text())
    except OSError as e:
        _fail(where, f"cannot read the campaign file ({e.strerror})")
    except yaml.YAMLError as e:
        _fail(where, f"not YAML: {e}")
    if not isinstance(doc, dict):
        _fail(where, "expected a map of campaign keys")
    unknown = set(doc) - _TOP_KEYS
    if unknown:
        _fail(where, f"unknown key(s) {', '.join(sorted(unknown))} (known: {', '.join(sorted(_TOP_KEYS))})")
    if "base" not in doc or not isinstance(doc["base"], str):
        _fail(where, "'base' (the base scenario file) is required")
    base = (path.parent / doc["base"]).resolve()
    try:
        base_text = base.read_text()
        scenario = yaml.load(base_text, Loader=yaml.BaseLoader)
    except OSError as e:
        _fail(f"{where}: base", f"cannot read the base scenario {base} ({e.strerror})")
    if not isinstance(scenario, dict):
        _fail(f"{where}: base", f"{base} is not a scenario (a YAML map)")
    _absolute_paths(scenario, base.parent)

    command = doc.get("command", "wear")
    if command not in COMMANDS:
        _fail(f"{where}: command", f"'{command}' is not one of {', '.join(COMMANDS)}")
    models = doc.get("models", [])
    models = [models] if isinstance(models, str) else models
    if not isinstance(models, list) or not all(isinstance(m, str) and m for m in models):
        _fail(f"{where}: models", f"expected a list of model names, got {doc.get('models')!r}")
    steps = doc.get("steps")
    if steps is not None and (isinstance(steps, bool) or not isinstance(steps, int) or steps < 0):
        _fail(f"{where}: steps", f"expected an integer >= 0, got {steps!r}")
    args = doc.get("args", [])
    if not isinstance(args, list):
        _fail(f"{where}: args", "expected a list of command-line arguments")
    args = [str(a) for a in args]
    combine = doc.get("combine", "product")
    if combine not in ("product", "zip"):
        _fail(f"{where}: combine", f"'{combine}' is not product or zip")
    outputs = doc.get("outputs") or {}
    if not isinstance(outputs, dict) or set(outputs) - _OUTPUT_KEYS:
        _fail(f"{where}: outputs", f"known keys: {', '.join(sorted(_OUTPUT_KEYS))}; got {outputs!r}")
    outputs = {"steps_columns": list(outputs.get("steps_columns", DEFAULT_COLUMNS)),
               "final_profiles": bool(outputs.get("final_profiles", True)),
               "files": list(outputs.get("files", []))}

    params = doc.get("parameters") or {}
    if not isinstance(params, dict):
        _fail(f"{where}: parameters", "expected a map of scenario key (dotted path) -> values")
    values = {}
    for key, spec in params.items():
        pwhere = f"{where}: parameter '{key}'"
        if not isinstance(key, str) or not key:
            _fail(pwhere, "a parameter is a dotted scenario key")
        check_parameter_path(scenario, key, pwhere)
        values[key] = _expand_values(spec, pwhere)
    keys = list(values)
    if combine == "zip":
        lengths = {k: len(v) for k, v in values.items()}
        if len(set(lengths.values())) > 1:
            _fail(f"{where}: combine zip", f"the parameters have different lengths {lengths}")
        combos = list(zip(*values.values())) if keys else [()]
    else:
        total = math.prod(len(v) for v in values.values())
        if total > MAX_CASES:  # (10^12 combinations: MemoryError before the first case, fuzzing, session 25)
            _fail(f"{where}: parameters", f"{total} combinations, more than {MAX_CASES} cases per campaign")
        combos = list(itertools.product(*values.values())) if keys else [()]

    base_sha = hashlib.sha256(base_text.encode()).hexdigest()
    per_case_models = [[m] for m in models] if (command == "wear" and models) else [models]
    cases, seen = [], set()
    for combo in combos:
        assignment = dict(zip(keys, combo))
        generated = copy.deepcopy(scenario)
        for k, v in assignment.items():
            set_parameter(generated, k, scalar_text(v))
        for ms in per_case_models:
            record = {"base_sha256": base_sha, "command": command, "models": ms, "steps": steps, "args": args,
                      "params": assignment}
            cid = case_id(record)
            if cid in seen:
                continue  # a repeated value (e.g. the same random draw twice): one case
            seen.add(cid)
            cases.append({"id": cid, "params": assignment, "models": ms, "scenario": generated})
    return {"name": str(doc.get("name") or path.stem), "file": str(path.resolve()), "base": str(base),
            "command": command, "models": models, "steps": steps, "args": args, "outputs": outputs,
            "parameters": values, "cases": cases}
