"""Session 25's fuzzing of the Python package: input that crashed the interpreter, asked for gigabytes, came back as
NaN with complete=True or as "no contact", or was silently replaced, is an InputError naming what is wrong."""
import numpy as np
import pytest

import conforma


@pytest.fixture(scope="module")
def track():
    return conforma.Track()


def test_manchester_with_a_bad_grid_is_an_input_error_not_an_abort():
    # the options were validated inside the OpenMP loop: the exception left it and terminated the interpreter
    with pytest.raises(conforma.InputError, match="fastsim_elements"):
        conforma.manchester(fastsim_elements=1)


@pytest.mark.parametrize("velocity, named", [
    ({"yaw_rate_rad_s": 1e300}, "yaw_rate_rad_s"),
    ({"axle_angular_velocity_rad_s": 1e300}, "axle_angular_velocity_rad_s"),
    ({"lateral_velocity_m_s": 1e4}, "lateral_velocity_m_s"),
    ({"speed_m_s": 1e-300, "lateral_velocity_m_s": 1.0}, "lateral_velocity_m_s"),
])
def test_velocities_beyond_any_creepage_are_input_errors(track, velocity, named):
    pose = track.rigid_equilibrium(0.003)
    with pytest.raises(conforma.InputError, match=named):
        conforma.contact_at_pose(track, "left", 0.003, pose["z_m"], model="conformal", **velocity)


def test_poses_beyond_a_wheelset_on_track_are_input_errors(track):
    with pytest.raises(conforma.InputError, match="approach"):
        conforma.contact(track, load_N=-1.0, approach_m=0.03)  # came back as "no contact", complete
    with pytest.raises(conforma.InputError, match="yaw"):
        conforma.contact(track, yaw_rad=3.14)
    with pytest.raises(conforma.InputError, match="yaw_rad"):
        track.rigid_equilibrium(0.0, yaw_rad=1e9)
    with pytest.raises(conforma.InputError, match="side"):
        track.mounted_rail("middle")
    with pytest.raises(conforma.InputError, match="gauge_m"):
        conforma.Track(gauge_m=1435)
    with pytest.raises(TypeError, match="wheel must be a profile name"):  # pybind's bare RuntimeError before
        conforma.Track(5)
    with pytest.raises(conforma.InputError, match="shear_modulus_Pa"):
        conforma.contact(track, shear_modulus_Pa=100.0)
    # a pose within the bounds still solves
    assert conforma.contact(track, lateral_m=0.003, model="hertz", side="left")[0]["complete"]


def test_profile_methods_refuse_nonsense_arguments():
    wheel = conforma.s1002()
    with pytest.raises(conforma.InputError, match="y_m"):
        wheel.height_at(float("nan"))
    for spacing in (1e-10, 1e-12):  # 1.5e9 points, or an overflowed count of 2
        with pytest.raises(conforma.InputError, match="spacing_m"):
            wheel.points(spacing)
    with pytest.raises(conforma.InputError, match="flange back"):
        wheel.dimensions(flange_back_y_m=-0.1)  # Sd 62.5 mm before
    assert wheel.dimensions()["sd_mm"] == pytest.approx(32.5, abs=0.01)


def test_profile_points_are_checked_as_a_file_is(tmp_path):
    # a self-intersecting curve was re-sorted by y into another profile
    loop = np.array([[0.0, 0.0], [0.02, 0.0], [0.02, -0.01], [0.01, 0.005], [0.03, 0.0]])
    with pytest.raises(conforma.InputError, match="self-intersects"):
        conforma.profile_from_points(loop, "rail")
    y = np.linspace(-0.03, 0.03, 121)
    z = -y**2 / (2 * 0.3)
    with pytest.raises(conforma.InputError, match="swapped"):  # a 60 mm crown with y and z exchanged
        conforma.profile_from_points(np.column_stack([z, y]), "rail")
    comma = tmp_path / "comma.csv"
    comma.write_text("".join(f"{a * 1e3:.3f};{b * 1e3:.3f}\n".replace(".", ",") for a, b in zip(y, z)))
    with pytest.raises(conforma.InputError, match="decimal commas"):  # read as a flat profile before
        conforma.load_profile(str(comma), kind="rail")
    bom = tmp_path / "bom.txt"
    bom.write_bytes(b"\xef\xbb\xbf" + "".join(f"{a * 1e3:.4f} {b * 1e3:.4f}\n" for a, b in zip(y, z)).encode())
    assert conforma.load_profile(str(bom), kind="rail").points()[0][0] == pytest.approx(-0.03)  # first point kept


def test_wear_with_a_nan_distance_is_an_input_error():
    with pytest.raises(conforma.InputError, match="total_km"):
        conforma.wear(conforma.scenario_path(), total_km=float("nan"))
