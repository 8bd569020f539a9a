"""conforma.ContactLut: a table written by `conforma lut build` loads, evaluates like `conforma lut eval --json`, and
refuses a pose outside it; its HDF5 file is readable with h5py when that is installed."""
import json
import subprocess

import pytest

import conforma

ARGS = ["--model", "hertz", "--load-N", "50000"]


@pytest.fixture(scope="module")
def table(cli, tmp_path_factory):
    path = str(tmp_path_factory.mktemp("lut") / "t.h5")
    subprocess.run([cli, "lut", "build", "--out", path, "--model", "hertz", "--y-mm", "-2:2:0.5", "--yaw-mrad", "0,2",
                    "--load-kN", "40,60"], check=True, capture_output=True)
    return path


def test_evaluation_matches_the_command_line(cli, table):
    lut = conforma.ContactLut(table)
    assert lut.model == "hertz" and lut.wheel_profile == "S1002"
    assert len(lut.lateral_m) == 9 and lut.load_N == [40e3, 60e3]
    wheel = lut.evaluate(conforma.Track(), "left", 0.7e-3, 1e-3, load_N=50e3, load_balance="total")
    out = subprocess.run([cli, "lut", "eval", table, "--y-mm", "0.7", "--yaw-mrad", "1", "--side", "left", "--json"]
                         + ARGS, check=True, capture_output=True, text=True).stdout
    ref = json.loads(out)["wheels"][0]
    assert wheel["status"] == ref["status"] == "ok"
    assert len(wheel["patches"]) == len(ref["patches"])
    for a, b in zip(wheel["patches"], ref["patches"]):
        assert a["fn_N"] == pytest.approx(b["fn_N"], rel=1e-12)
        assert a["fy_N"] == pytest.approx(b["fy_N"], rel=1e-9, abs=1e-9)


def test_polach_creep_force_keeps_the_normal_solution_and_bounds_the_creep_force(table):
    lut = conforma.ContactLut(table)
    kw = dict(load_N=50e3, speed_m_s=10.0, lateral_velocity_m_s=0.02, load_balance="pressure")
    f = lut.evaluate(conforma.Track(), "left", 0.7e-3, 1e-3, **kw)
    p = lut.evaluate(conforma.Track(), "left", 0.7e-3, 1e-3, creep_force="polach", **kw)
    assert len(p["patches"]) == len(f["patches"]) >= 1
    for a, b in zip(f["patches"], p["patches"]):
        assert b["fn_N"] == a["fn_N"]  # pressure balance: the creep law does not touch the normal solution
        assert (b["fx_N"] ** 2 + b["fy_N"] ** 2) ** 0.5 <= 0.3 * b["fn_N"] * (1 + 1e-9)
        assert b["fy_N"] == pytest.approx(a["fy_N"], abs=0.25 * 0.3 * a["fn_N"])  # docs/physics-reference.md §7.3
    with pytest.raises(conforma.InputError, match="creep force"):
        lut.evaluate(conforma.Track(), "left", 0.7e-3, creep_force="kalker")


def test_outside_the_table_is_an_input_error(table):
    lut = conforma.ContactLut(table)
    with pytest.raises(conforma.InputError, match="lateral shift y"):
        lut.evaluate(conforma.Track(), "left", 3e-3)
    with pytest.raises(conforma.InputError):
        conforma.ContactLut(table + ".missing")


def test_file_is_self_describing(table):
    h5py = pytest.importorskip("h5py")
    with h5py.File(table, "r") as f:
        model = f.attrs["model"]
        assert (model.decode() if isinstance(model, bytes) else model) == "hertz"
        units = f["left/fn_N"].attrs["units"]
        assert (units.decode() if isinstance(units, bytes) else units) == "N"
        offsets = f["left/node_patch_offset"][:]
        assert len(offsets) == 9 * 2 * 2 + 1 and offsets[-1] == len(f["left/fn_N"])


def test_another_wheel_is_refused(table, shared_data):
    """The table records the geometry it was built for (docs/physics-reference.md §17.1): a track with another wheel
    profile and the same nominal radius is refused, not answered with the table's S1002 forces."""
    lut = conforma.ContactLut(table)
    worn = str(shared_data / "profiles/contact/testbank/profiles/Car7358_0001r.whl")
    with pytest.raises(conforma.InputError, match="another geometry"):
        lut.evaluate(conforma.Track(wheel=worn), "left", 0.7e-3, 1e-3, load_N=50e3)
    assert lut.evaluate(conforma.Track(), "left", 0.7e-3, 1e-3, load_N=50e3)["status"] == "ok"


def test_evaluation_says_whether_it_is_complete(table, monkeypatch):
    """No silent failures (conforma._status): the table's wheel dict carries 'complete' and 'problems' as contact()'s,
    and an incomplete one warns, or raises with strict=True."""
    lut = conforma.ContactLut(table)
    wheel = lut.evaluate(conforma.Track(), "left", 0.7e-3, 1e-3, load_N=50e3)
    assert wheel["complete"] is True and wheel["problems"] == []
    assert set(wheel) == set(conforma.types.Wheel.__required_keys__) | set(conforma.types.Wheel.__optional_keys__)
    # a table answer the core marks not converged (as the total balance does at a force jump, §17.4)
    original = conforma._core.ContactLut.evaluate

    def not_converged(self, *args, **kwargs):
        w = original(self, *args, **kwargs)
        w["status"] = "not_converged"
        return w

    monkeypatch.setattr(conforma._core.ContactLut, "evaluate", not_converged)
    with pytest.warns(conforma.IncompleteResultWarning, match="ContactLut.evaluate: incomplete result"):
        wheel = lut.evaluate(conforma.Track(), "left", 0.7e-3, 1e-3, load_N=50e3)
    assert wheel["complete"] is False and "not_converged" in wheel["problems"][0]
    with pytest.raises(conforma.IncompleteResultError):
        lut.evaluate(conforma.Track(), "left", 0.7e-3, 1e-3, load_N=50e3, strict=True)
