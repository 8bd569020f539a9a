"""A Python call gives the same forces as the command line (`conforma contact ... --json`), to 1e-12 relative, on
the Manchester A-2.2 left-wheel cases: same profiles, same pose, same creepages, same options both ways.

The inputs are written once as command-line text (mm, mrad as the CLI takes them) and converted to SI in Python
with the same operation the CLI applies (value * 1e-3), so both sides see bit-identical doubles."""
import csv
import json
import subprocess

import pytest

import conforma

REL = 1e-12
KEYS = ["fn_N", "fx_N", "fy_N", "mz_Nm", "vertical_force_N", "lateral_force_N", "pmax_Pa", "area_m2",
        "contact_angle_rad", "xi", "eta", "phi_per_m", "approach_m"]


def manchester_rows(shared_data):
    with open(shared_data / "reference" / "contact_mbench_a22_left.csv") as f:
        return list(csv.DictReader(f))


def close(a, b):
    return abs(a - b) <= REL * max(abs(a), abs(b))


@pytest.fixture(scope="module")
def track_files(shared_data):
    examples = shared_data / "profiles" / "contact" / "examples"
    return str(examples / "MBench_S1002_v3.prw"), str(examples / "MBench_UIC60_v3.prr")


@pytest.mark.parametrize("model", ["conformal", "hertz", "kpec"])
def test_python_contact_equals_cli_on_manchester_left_wheel(model, shared_data, cli, track_files):
    wheel, rail = track_files
    # the CLI's track: --gauge-mm 1435 --gauge-height-mm 14 --flange-back-mm 1360 --flange-back-position-mm -70
    # --r0-mm 460, rail file taken as canted (inclination 0)
    track = conforma.Track(wheel, rail, gauge_m=1435.0 * 1e-3, gauge_height_m=14.0 * 1e-3,
                           flange_back_distance_m=1360.0 * 1e-3, flange_back_position_m=-70.0 * 1e-3,
                           nominal_radius_m=460.0 * 1e-3)
    rows = manchester_rows(shared_data)
    assert len(rows) >= 21
    compared = 0
    worst = 0.0
    for row in rows:
        y_mm = repr(-float(row["y_ws_mm"]))                 # CONTACT's y points right: y_ours = -y_ws
        yaw_mrad = repr(-float(row["yaw_mrad"]))
        roll_mrad = repr(float(row["roll_ws_rad"]) * 1e3)
        xi, eta = row["xi"], row["eta"]
        phi_per_m = repr(float(row["phi_per_mm"]) * 1e3)
        args = [cli, "contact", "--wheel", wheel, "--rail", rail, "--model", model, "--load-N", "10000",
                "--speed", "2", "--mu", "0.3", "--y-mm", y_mm, "--yaw-mrad", yaw_mrad, "--roll-mrad", roll_mrad,
                "--side", "left", "--xi", xi, "--eta", eta, "--phi-per-m", phi_per_m, "--json"]
        out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
        cli_wheel = json.loads(out)["wheels"][0]
        py_wheel = conforma.contact(track, lateral_m=float(y_mm) * 1e-3, yaw_rad=float(yaw_mrad) * 1e-3,
                                    roll_rad=float(roll_mrad) * 1e-3, model=model, load_N=10000.0, speed_m_s=2.0,
                                    mu=0.3, side="left", xi=float(xi), eta=float(eta), phi_per_m=float(phi_per_m),
                                    fields=True)[0]
        assert py_wheel["status"] == cli_wheel["status"] == "ok", (row["case"], cli_wheel["status"])
        assert len(py_wheel["patches"]) == len(cli_wheel["patches"]) >= 1
        for key in ["vertical_force_N", "lateral_force_N", "pressure_vertical_force_N"]:
            assert close(py_wheel[key], cli_wheel[key]), (row["case"], key, py_wheel[key], cli_wheel[key])
        for pp, cp in zip(py_wheel["patches"], cli_wheel["patches"]):
            for key in KEYS:
                a, b = pp[key], cp[key]
                assert close(a, b), (model, row["case"], key, a, b)
                if max(abs(a), abs(b)) > 0:
                    worst = max(worst, abs(a - b) / max(abs(a), abs(b)))
            compared += 1
    assert compared >= 21
    print(f"{model}: {compared} patches compared, largest relative difference {worst:.3g}")
