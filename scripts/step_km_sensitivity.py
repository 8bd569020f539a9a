#!/usr/bin/env python3
"""Step-to-step sensitivity of two wear runs of the same scenario that differ by a perturbation (e.g. the load
tolerance 1e-6 against 1.1e-6, issue 16 item 5; docs/physics-reference.md §16.7).

usage: step_km_sensitivity.py RUN_A RUN_B
RUN_A, RUN_B: a model's output folder of `conforma compare` or `conforma wear` (steps.csv, wheel_step_NNN.csv).

Prints per wheel step: the step's km in both runs, the relative change (B - A) / A, and the largest vertical
difference |z_B - z_A| of the wheel profiles the step started from (over their common lateral range, 0.05 mm grid):
how far the two runs' profiles had drifted apart before that step. Ends with the largest |change|.
Exit 1 when the runs have different step counts or a step of zero km in RUN_A.
"""
import csv
import os
import sys

import numpy as np


def step_km(run):
    with open(os.path.join(run, "steps.csv")) as f:
        rows = [r for r in csv.DictReader(f)]
    return {int(r["step"]): float(r["step_km"]) for r in rows if int(r["step"]) > 0}


def wheel_profile(run, step):
    path = os.path.join(run, "wheel_step_%03d.csv" % step)
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    rows = list(csv.DictReader(lines))
    return (np.array([float(r["y_mm"]) for r in rows]), np.array([float(r["z_mm"]) for r in rows]))


def profile_difference_um(run_a, run_b, step):
    """max |z_B - z_A| in um over the common lateral range of the two wheel profiles after `step`."""
    ya, za = wheel_profile(run_a, step)
    yb, zb = wheel_profile(run_b, step)
    lo, hi = max(ya.min(), yb.min()), min(ya.max(), yb.max())
    grid = np.arange(lo, hi, 0.05)
    return 1000.0 * float(np.max(np.abs(np.interp(grid, yb, zb) - np.interp(grid, ya, za))))


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    run_a, run_b = argv[1], argv[2]
    km_a, km_b = step_km(run_a), step_km(run_b)
    if sorted(km_a) != sorted(km_b):
        print("step_km_sensitivity: the runs have different steps: %s and %s" % (sorted(km_a), sorted(km_b)))
        return 1
    print("step,km_a,km_b,change_pct,profile_difference_before_um")
    worst = 0.0
    for step in sorted(km_a):
        if not km_a[step] > 0.0:
            print("step_km_sensitivity: step %d of %s has %g km" % (step, run_a, km_a[step]))
            return 1
        change = 100.0 * (km_b[step] - km_a[step]) / km_a[step]
        worst = max(worst, abs(change))
        print("%d,%.3f,%.3f,%+.2f,%.3f" % (step, km_a[step], km_b[step], change,
                                          profile_difference_um(run_a, run_b, step - 1)))
    print("largest |change|: %.2f %%" % worst)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
