"""contact(): per patch scalars and NumPy fields with their grid; consistency checks that could fail."""
import math

import numpy as np
import pytest

import conforma


@pytest.fixture(scope="module")
def track():
    return conforma.Track("S1002", "60E1")


@pytest.mark.parametrize("model", ["hertz", "kp", "conformal", "exact"])
def test_fields_integrate_to_the_patch_forces(track, model):
    wheels = conforma.contact(track, lateral_m=3e-3, yaw_rad=2e-3, model=model, speed_m_s=20.0)
    assert [w["side"] for w in wheels] == ["left", "right"]
    for w in wheels:
        assert w["status"] == "ok"
        for p in w["patches"]:
            f = p["fields"]
            n = len(f["x_m"])
            assert n > 50
            for key in ["s_m", "rail_s_m", "wheel_y_m", "area_m2", "pressure_Pa", "traction_x_Pa", "traction_s_Pa",
                        "slip_x", "slip_s", "adhesion", "wear_index_Pa"]:
                assert isinstance(f[key], np.ndarray) and f[key].shape == (n,), key
            assert f["adhesion"].dtype == np.bool_
            fn = np.sum(f["pressure_Pa"] * f["area_m2"])
            assert fn == pytest.approx(p["fn_N"], rel=0.02)  # element-centre sampling of the pressure
            assert np.sum(f["area_m2"]) == pytest.approx(p["area_m2"], rel=0.03)
            fx = np.sum(f["traction_x_Pa"] * f["area_m2"])
            assert fx == pytest.approx(p["fx_N"], rel=1e-6, abs=1e-6 * p["fn_N"])
            # Coulomb bound on every element
            tau = np.hypot(f["traction_x_Pa"], f["traction_s_Pa"])
            assert np.all(tau <= 0.3 * f["pressure_Pa"] * 1.02 + 1.0)
            # adhesion area = area of the adhesion elements
            assert np.sum(f["area_m2"][f["adhesion"]]) == pytest.approx(p["adhesion_area_m2"], rel=1e-9, abs=1e-12)
            # the grid covers the patch: extent along x about its length
            assert np.ptp(f["x_m"]) == pytest.approx(p["length_m"], rel=0.25)


def test_load_control_carries_the_load_and_wheels_mirror_when_centred(track):
    left, right = conforma.contact(track, lateral_m=0.0, model="conformal")
    # total-force balance (issue 15): pressure and creep forces together carry the load
    assert left["vertical_force_N"] == pytest.approx(10e3, rel=1e-5)
    assert right["vertical_force_N"] == pytest.approx(10e3, rel=1e-5)
    pl, pr = left["patches"][0], right["patches"][0]
    assert pl["fn_N"] == pytest.approx(pr["fn_N"], rel=1e-6)
    # track frame: lateral forces of the two wheels cancel, contact points mirror about the track centre
    assert pl["force_track_N"][1] == pytest.approx(-pr["force_track_N"][1], abs=1e-6 * pl["fn_N"])
    assert pl["contact_point_track_m"][1] == pytest.approx(-pr["contact_point_track_m"][1], abs=1e-9)


def test_flange_contact_pushes_the_wheel_towards_the_track_centre(track):
    left = conforma.contact(track, lateral_m=8e-3, model="conformal", side="left", fields=False)[0]
    assert "fields" not in left["patches"][0]
    angles = [p["contact_angle_rad"] for p in left["patches"]]
    assert max(angles) > 0.8  # on the flange
    assert left["lateral_force_N"] < -5e3  # side frame: + towards the field side
    total_y = sum(p["force_track_N"][1] for p in left["patches"])
    assert total_y == pytest.approx(left["lateral_force_N"], rel=1e-12)  # left side: track y = side eta


def test_contact_at_pose_reproduces_the_load_controlled_pose(track):
    loaded = conforma.contact(track, lateral_m=2e-3, yaw_rad=1e-3, model="kp", side="left", fields=False)[0]
    pose = loaded["pose"]
    given = conforma.contact_at_pose(track, "left", pose["y_m"], pose["z_m"], pose["roll_rad"], pose["yaw_rad"],
                                     model="kp", fields=False)
    assert given["vertical_force_N"] == pytest.approx(10e3, rel=1e-3)
    with pytest.raises(conforma.InputError):
        conforma.contact_at_pose(track, "left", math.nan, 0.0)


def test_manchester_runner_carries_the_load(shared_data):
    rows = conforma.manchester("conformal", data_dir=str(shared_data))
    assert len(rows) >= 21
    for r in rows:
        assert r["status"] == "ok"
        assert abs(r["err_fn"]) < 0.05  # 10 kN vertical load vs CONTACT's normal force (contact angle)


def test_exact_model_reports_the_convergence_of_both_solves(track):
    left = conforma.contact(track, lateral_m=3e-3, yaw_rad=2e-3, model="exact", side="left", fields=False)[0]
    assert left["status"] == "ok"
    for p in left["patches"]:
        assert p["model"] == "exact" and p["tangential_status"] in ("ok", "full_slip")
        assert p["normal_iterations"] > 0 and 0.0 <= p["normal_residual"] < 1e-6
        assert p["tangential_iterations"] > 0 and 0.0 <= p["tangential_residual"] < 1e-5
    # a finer element size changes the solution by the discretisation error only
    fine = conforma.contact(track, lateral_m=3e-3, yaw_rad=2e-3, model="exact", side="left", fields=False,
                            exact_element_m=0.1e-3)[0]
    assert fine["patches"][0]["fn_N"] == pytest.approx(left["patches"][0]["fn_N"], rel=2e-3)
    assert fine["patches"][0]["normal_iterations"] > 0
    # the former name of the model is accepted and gives the same solution
    again = conforma.contact(track, lateral_m=3e-3, yaw_rad=2e-3, model="reference", side="left", fields=False)[0]
    assert again["patches"][0]["fx_N"] == left["patches"][0]["fx_N"]
