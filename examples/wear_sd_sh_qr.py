#!/usr/bin/env python3
"""Wear run: flange dimensions Sd, Sh, qR of the wheel against the distance run.

Runs the wear loop (conforma.wear) on a scenario -- by default default_metro.yaml as installed with the package
(conforma.scenario_path(), a copy of the repository's scenarios/default_metro.yaml: S1002 wheels on 50E4
rails at 1:20, a metro vehicle, tangent track and three curve classes) -- and plots Sd, Sh and qR of every wheel
profile step against km, with the worn wheel profiles beside them. Also writes the steps table as CSV with the
units in the column names.

    python3 examples/wear_sd_sh_qr.py [--output-dir DIR] [--scenario FILE] [--model conformal] [--steps 3]

Writes DIR/wear_sd_sh_qr.png and DIR/wear_sd_sh_qr.csv (matplotlib, Agg backend). Needs the `conforma` package
(pip install, or PYTHONPATH=build-dir/python) built with the wear loop; fails with a clear message otherwise. A run
that is incomplete (stopped early, failed contacts) is printed with its problems and warned about
(conforma.IncompleteResultWarning).
"""
import argparse
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import conforma  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default=os.environ.get("CONFORMA_OUTPUT_DIR", "."))
    parser.add_argument("--scenario", default=None,
                        help="scenario YAML file (default: conforma.scenario_path('default_metro'))")
    parser.add_argument("--model", default="", help="hertz, kp, kpec, conformal (default: the scenario's)")
    parser.add_argument("--steps", type=int, default=3, help="wheel profile steps (each removes the cap depth)")
    args = parser.parse_args()
    if not getattr(conforma, "has_wear", False):
        sys.exit("conforma.wear is not available: this build of the Python module has no wear loop "
                 "(include/conforma/wear_simulation.hpp)")
    if args.scenario is None:
        args.scenario = conforma.scenario_path("default_metro")
    out_dir = pathlib.Path(args.output_dir)
    out_dir.mkdir(parents=True, exist_ok=True)

    scenario = conforma.load_scenario(args.scenario)  # the YAML as a dict: could be edited here
    run = conforma.wear(args.scenario, model=args.model, steps=args.steps)
    table = run["steps"]
    if run["status"] != "completed" and len(table["km"]) < 2:
        sys.exit(f"wear run stopped: {run['status']} {run['message']}")
    print(f"scenario {scenario['name']}, model {run['model']}, status {run['status']} {run['message']}")
    for problem in run["problems"]:
        print(f"  incomplete: {problem}")
    print(f"{'step':>4s} {'km':>9s} {'Sd[mm]':>8s} {'Sh[mm]':>8s} {'qR[mm]':>8s} {'tread[mm]':>9s} {'flange[mm]':>10s}")
    for i in range(len(table["km"])):
        print(f"{int(table['step'][i]):4d} {table['km'][i]:9.1f} {table['sd_mm'][i]:8.3f} {table['sh_mm'][i]:8.3f} "
              f"{table['qr_mm'][i]:8.3f} {table['tread_wear_mm'][i]:9.3f} {table['flange_wear_mm'][i]:10.3f}")

    columns = ["step", "km", "step_km", "max_depth_mm", "sd_mm", "sh_mm", "qr_mm", "tread_wear_mm", "flange_wear_mm"]
    csv_path = out_dir / "wear_sd_sh_qr.csv"
    np.savetxt(csv_path, np.column_stack([table[c] for c in columns]), delimiter=",", header=",".join(columns),
               comments="", fmt="%.9g")

    fig, axes = plt.subplots(1, 4, figsize=(17, 4.2), constrained_layout=True)
    for ax, key, label in zip(axes, ["sd_mm", "sh_mm", "qr_mm"], ["Sd (flange thickness)", "Sh (flange height)",
                                                                    "qR (flange slope)"]):
        ax.plot(table["km"], table[key], "o-")
        ax.set_xlabel("distance [km]")
        ax.set_ylabel(f"{label.split()[0]} [mm]")
        ax.set_title(label)
        ax.grid(True, alpha=0.3)
        ax.ticklabel_format(axis="y", useOffset=False)
    ax = axes[3]
    for i, profile in enumerate(run["wheel_profiles"]):
        pts = profile.points(spacing_m=0.5e-3) * 1e3
        ax.plot(pts[:, 0], pts[:, 1], lw=1, label=f"{table['km'][i]:.0f} km")
    ax.set_xlim(-70, 60)
    ax.set_xlabel("y [mm] (flange at negative y)")
    ax.set_ylabel("z [mm] above the taping line")
    ax.set_title("wheel profiles")
    ax.legend(fontsize=7)
    fig.suptitle(f"{scenario['name']}: wheel wear with the {run['model']} contact model")
    png = out_dir / "wear_sd_sh_qr.png"
    fig.savefig(png, dpi=110)
    print(f"wrote {png} and {csv_path}")


if __name__ == "__main__":
    main()
