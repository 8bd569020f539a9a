"""wear(scenario, model) and the scenario as a dict (when the module is built with the wear loop)."""
import pathlib

import numpy as np
import pytest

import conforma

SCENARIO = pathlib.Path(__file__).resolve().parents[2] / "scenarios" / "metro_curves.yaml"

pytestmark = pytest.mark.skipif(not conforma.has_wear, reason="module built without the wear loop")


def test_scenario_dict_round_trips_through_the_reader():
    d = conforma.load_scenario(str(SCENARIO))
    assert d["profiles"]["rail"] == "50E4"  # names stay strings
    checked = conforma.check_scenario(d, base_dir=str(SCENARIO.parent))
    from_file = conforma.check_scenario(str(SCENARIO))
    assert checked == from_file
    assert sum(c["share"] for c in checked["track_classes"]) == pytest.approx(1.0)
    d["update"]["cap_mm"] = "lots"
    with pytest.raises(conforma.InputError, match="cap_mm"):
        conforma.check_scenario(d)


def test_centred_wear_run_removes_the_cap_per_step_and_keeps_the_flange():
    d = conforma.load_scenario(str(SCENARIO))
    d["kinematics"] = {"provider": "centred"}  # centred wheelsets: tread wear only (fast)
    run = conforma.wear(d, model="hertz", steps=2, base_dir=str(SCENARIO.parent))
    t = run["steps"]
    assert run["status"] == "completed" and run["model"] == "hertz"
    assert list(t["step"]) == [0, 1, 2]
    assert t["km"][0] == 0.0 and np.all(np.diff(t["km"]) > 0)
    assert t["max_depth_mm"][1:] == pytest.approx([0.4, 0.4], rel=1e-6)  # the cap of metro_curves.yaml
    # tread wear only: the flange dimensions stay those of the new S1002 to well under the cap
    assert np.all(np.abs(t["sd_mm"] - 32.5) < 0.05)
    assert np.all(np.abs(t["sh_mm"] - t["sh_mm"][0]) < 0.05)
    assert len(run["wheel_profiles"]) == 3
    assert conforma.wheel_dimensions(run["wheel_profiles"][-1])["sd_mm"] == pytest.approx(t["sd_mm"][-1], abs=1e-9)
