"""Profiles from Python: generated S1002 and rails, files, NumPy points, Sd/Sh/qR, errors as InputError."""
import subprocess

import numpy as np
import pytest

import conforma


def test_s1002_flange_dimensions_are_the_standard_new_wheel_values():
    d = conforma.wheel_dimensions(conforma.s1002())
    # new S1002 (EN 13715): Sd = 32.5 mm, Sh = 28 mm, qR = 10.8 mm (docs/profiles-and-formats.md)
    assert d["sh_mm"] == pytest.approx(28.0, abs=0.01)
    assert d["sd_mm"] == pytest.approx(32.5, abs=0.05)
    assert d["qr_mm"] == pytest.approx(10.8, abs=0.1)
    assert d["sd_m"] == pytest.approx(d["sd_mm"] * 1e-3)


def test_profile_points_are_a_numpy_curve_with_the_profile_conventions():
    w = conforma.s1002()
    assert w.kind == "wheel"
    pts = w.points()
    assert isinstance(pts, np.ndarray) and pts.ndim == 2 and pts.shape[1] == 2
    assert pts[:, 0].min() == pytest.approx(-0.070, abs=1e-4)  # flange back
    assert w.height_at(0.0) == pytest.approx(0.0, abs=1e-6)     # taping line at z = 0
    assert pts[:, 1].max() == pytest.approx(0.028, abs=2e-5)    # flange tip 28 mm above it
    step = np.hypot(*np.diff(pts, axis=0).T)
    assert np.allclose(step, w.length_m / (len(pts) - 1), rtol=1e-3)  # uniform in arc length
    coarse = w.points(spacing_m=1e-3)
    assert abs(len(coarse) - w.length_m / 1e-3) < 2


def test_rail_section_and_inclination():
    r = conforma.rail("60E1")
    assert r.kind == "rail"
    assert r.height_at(0.0) == pytest.approx(0.0, abs=1e-9)  # top of the head at the origin
    canted = conforma.rail("60E1", inclination_rad=np.arctan(1 / 40))
    assert max(canted.points()[:, 1]) == pytest.approx(0.0, abs=1e-7)
    with pytest.raises(conforma.InputError, match="61E1"):
        conforma.rail("61E1")


def test_simpack_round_trip_keeps_the_curve(tmp_path):
    w = conforma.s1002()
    path = tmp_path / "s1002.prw"
    w.save_simpack(str(path))
    back = conforma.load_profile(str(path))
    assert back.kind == "wheel"
    for y in np.linspace(-0.06, 0.05, 23):
        assert back.height_at(y) == pytest.approx(w.height_at(y), abs=2e-6)
    assert conforma.wheel_dimensions(back)["sd_mm"] == pytest.approx(conforma.wheel_dimensions(w)["sd_mm"], abs=1e-3)


def test_profile_from_points_and_csv(tmp_path):
    y = np.linspace(-0.03, 0.03, 121)
    z = -y**2 / (2 * 0.3)  # a 300 mm crown
    r = conforma.profile_from_points(np.column_stack([y, z]), "rail")
    assert r.height_at(0.01) == pytest.approx(-0.01**2 / 0.6, abs=1e-9)
    path = tmp_path / "crown.csv"
    r.save_csv(str(path))
    back = conforma.load_profile(str(path), kind="rail")
    assert back.height_at(0.02) == pytest.approx(r.height_at(0.02), abs=1e-7)


def test_input_error_is_a_value_error_with_the_same_message_as_the_cli(tmp_path, cli):
    bad = tmp_path / "bad.txt"
    bad.write_text("# y z\n0 0\n1 abc\n2 0\n")
    with pytest.raises(conforma.InputError) as info:
        conforma.load_profile(str(bad), kind="rail")
    assert isinstance(info.value, ValueError)
    message = str(info.value)
    assert str(bad) in message and ":3:" in message  # file:line
    # the command line reports the very same text for the same file
    run = subprocess.run([cli, "contact", "--rail", str(bad), "--json"], capture_output=True, text=True)
    assert run.returncode != 0
    assert message in run.stderr, (message, run.stderr)
    with pytest.raises(ValueError, match="magic"):
        conforma.contact(conforma.Track(), model="magic")
