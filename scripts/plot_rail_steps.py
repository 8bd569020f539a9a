#!/usr/bin/env python3
"""Rail plots of `conforma wear` with rail steps (paper 003 Fig. 11): DIR/rail_step_NNN_depth.csv,
rail_cumulative_depth.csv, rail_steps.csv -> DIR/rail_step_NNN.png (per rail step: the
depth of every virtual rail and of the averaged rail along the rail before the step, both rails) and
DIR/rail_evolution.png (each rail's depth against the initial rail, and the rail heads with that depth magnified).

usage: plot_rail_steps.py DIR
Run with a python3 that has matplotlib (python3-matplotlib); conforma uses $CONFORMA_PYTHON or python3 on PATH.
"""
import csv
import glob
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SIDES = ("left", "right")
MAGNIFY = 10.0  # depth magnification of the rail-head panels (x20 folds the 0.85 mm gauge-corner wear of
#                 metro_rail_steps over the 13 mm corner radius: a drawing artefact)


def read_rows(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def plot_step(path, steps_row):
    rows = read_rows(path)
    k = int(re.search(r"rail_step_(\d+)_depth", path).group(1))
    virtual = sorted((c for c in rows[0] if c.startswith("virtual_")), key=lambda c: int(c.split("_")[1]))
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    for ax, side in zip(axes, SIDES):
        sr = [r for r in rows if r["side"] == side]
        y = [float(r["y_mm"]) for r in sr]
        n = len(virtual)
        for j, c in enumerate(virtual):
            d = [float(r[c]) * 1e3 for r in sr]
            if any(v != 0.0 for v in d):
                ax.plot(y, d, lw=0.8, color=plt.cm.viridis(j / max(1, n - 1)), label=f"virtual rail {j}")
        ax.plot(y, [float(r["rail_mm"]) * 1e3 for r in sr], "k", lw=2.0, label=f"averaged rail r{k}")
        title = f"{side} rail, rail step {k}"
        if steps_row:
            title += (f": area {float(steps_row[side + '_removed_area_mm2']):.4f} mm², "
                      f"residual {float(steps_row[side + '_area_residual']):.1e}")
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("y on the rail before the step [mm] (gauge side < 0)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("depth removed along the normals [µm]")
    axes[0].legend(fontsize=7)
    if steps_row:
        fig.suptitle(f"wheel sequence on r{k - 1}: {steps_row['wheel_steps']} steps, "
                     f"{float(steps_row['wheel_km']):.0f} km", fontsize=10)
    fig.tight_layout()
    fig.savefig(path.replace("_depth.csv", ".png"), dpi=110)
    plt.close(fig)


def plot_evolution(d):
    rows = read_rows(os.path.join(d, "rail_cumulative_depth.csv"))
    steps = sorted({int(r["new_rail"]) for r in rows})
    fig, axes = plt.subplots(2, 2, figsize=(13, 8))
    for col, side in enumerate(SIDES):
        ax = axes[0][col]
        for k in steps:
            sr = [r for r in rows if r["side"] == side and int(r["new_rail"]) == k]
            ax.plot([float(r["y_mm"]) for r in sr], [float(r["depth_mm"]) for r in sr],
                    color=plt.cm.plasma(k / (max(steps) + 1)), lw=1.0, label=f"r{k}")
        ax.set_title(f"{side} rail: depth against the initial rail", fontsize=10)
        ax.set_xlabel("y [mm]")
        ax.set_ylabel("depth [mm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
        ax = axes[1][col]
        # the worn rails drawn with their depth magnified along the initial rail's outward normals
        import numpy as np
        first = [r for r in rows if r["side"] == side and int(r["new_rail"]) == steps[0]]
        q = np.array([[float(r["y_mm"]), float(r["z_mm"])] for r in first])
        t = np.gradient(q, axis=0)
        t /= np.linalg.norm(t, axis=1)[:, None]
        normal = np.column_stack([-t[:, 1], t[:, 0]])  # left of the tangent: out of the rail (Profile::normal)
        ax.plot(q[:, 0], q[:, 1], "k", lw=1.5, label="r0")
        for k in steps:
            if k != max(steps) and k % 2:
                continue
            dep = np.array([float(r["depth_mm"]) for r in rows if r["side"] == side and int(r["new_rail"]) == k])
            w = q - MAGNIFY * dep[:, None] * normal
            ax.plot(w[:, 0], w[:, 1], lw=1.0, color=plt.cm.plasma(k / (max(steps) + 1)), label=f"r{k}")
        ax.set_xlim(-48, 30)
        ax.set_ylim(-20, 2)
        ax.set_aspect("equal")
        ax.set_title(f"{side} rail head (mounted), depth x{MAGNIFY:g}", fontsize=10)
        ax.set_xlabel("y [mm]")
        ax.set_ylabel("z [mm]")
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "rail_evolution.png"), dpi=110)
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    d = sys.argv[1]
    summary = {}
    if os.path.exists(os.path.join(d, "rail_steps.csv")):
        summary = {int(r["new_rail"]): r for r in read_rows(os.path.join(d, "rail_steps.csv"))}
    paths = sorted(glob.glob(os.path.join(d, "rail_step_*_depth.csv")))
    if not paths:
        sys.exit(f"{d}: no rail_step_*_depth.csv")
    for p in paths:
        k = int(re.search(r"rail_step_(\d+)_depth", p).group(1))
        plot_step(p, summary.get(k))
    plot_evolution(d)


if __name__ == "__main__":
    main()
