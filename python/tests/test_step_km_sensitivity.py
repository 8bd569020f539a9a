"""scripts/step_km_sensitivity.py on two hand-made runs: the step-km change and the profiles' drift are what the files
say, and runs that cannot be compared are refused with exit 1."""
import pathlib
import subprocess
import sys

from conftest import SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "step_km_sensitivity.py"
HEADER = "rail_step,step,km,step_km\n"


def write_run(folder: pathlib.Path, step_kms, profile_offsets_um):
    folder.mkdir()
    km, rows = 0.0, ["0,0,0,0\n"]
    for i, s in enumerate(step_kms, start=1):
        km += s
        rows.append("0,%d,%g,%g\n" % (i, km, s))
    (folder / "steps.csv").write_text(HEADER + "".join(rows))
    for step, offset in enumerate(profile_offsets_um):
        lines = ["# wheel profile (test)\n", "y_mm,z_mm\n"]
        lines += ["%g,%.9f\n" % (y, 0.001 * y * y + (offset * 1e-3 if y == 10 else 0.0)) for y in range(-20, 41)]
        (folder / ("wheel_step_%03d.csv" % step)).write_text("".join(lines))


def run(a, b):
    return subprocess.run([sys.executable, str(SCRIPT), str(a), str(b)], capture_output=True, text=True)


def test_change_and_drift_are_read_from_the_runs(tmp_path):
    write_run(tmp_path / "a", [1000.0, 2000.0], [0.0, 0.0])
    write_run(tmp_path / "b", [1000.0, 2100.0], [0.0, 3.0])  # step 2 starts from profiles 3 um apart at y = 10 mm
    out = run(tmp_path / "a", tmp_path / "b")
    assert out.returncode == 0, out.stderr
    lines = out.stdout.strip().splitlines()
    assert lines[1] == "1,1000.000,1000.000,+0.00,0.000"
    step2 = lines[2].split(",")
    assert step2[3] == "+5.00"
    assert abs(float(step2[4]) - 3.0) < 0.01  # the 3 um bump, found on the 0.05 mm grid at y = 10 mm
    assert lines[-1] == "largest |change|: 5.00 %"


def test_runs_with_different_steps_are_refused(tmp_path):
    write_run(tmp_path / "a", [1000.0, 2000.0], [0.0, 0.0])
    write_run(tmp_path / "b", [1000.0], [0.0])
    out = run(tmp_path / "a", tmp_path / "b")
    assert out.returncode == 1
    assert "different steps" in out.stdout
