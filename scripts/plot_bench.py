#!/usr/bin/env python3
"""Pareto plot of `conforma bench`: median time per patch against error, per model and grid.

usage: plot_bench.py bench.csv out.png
Left: p_max error, right: creep-force error max(|err_fx|, |err_fy|), both against the exact model (BEM with
Blanco-Lorenzo coefficients + Kalker's exact steady-rolling theory, one solve per case). Small dots: every case;
large markers: the worst case per model and grid (the Pareto front of those in black). Rows whose exact reference
did not converge (reference_status != converged) are left out.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path, out):
    rows = [r for r in csv.DictReader(open(path)) if r.get("reference_status", "converged") == "converged"]
    groups = defaultdict(list)
    for r in rows:
        groups[(r["model"], r["grid"])].append(r)
    colors = {"hertz": "tab:blue", "kp": "tab:orange", "kpec": "tab:green", "conformal": "tab:red",
              "conformal_eps055": "tab:purple", "auto": "tab:brown"}
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    panels = [("p_max error vs exact", lambda r: abs(float(r["err_pmax"]))),
              ("creep force error vs exact (max |err_fx|, |err_fy|)",
               lambda r: max(abs(float(r["err_fx"])), abs(float(r["err_fy"]))))]
    for ax, (title, err) in zip(axes, panels):
        points = []
        for (model, grid), rs in sorted(groups.items()):
            c = colors.get(model, "gray")
            times = sorted(float(r["time_us"]) for r in rs)
            errs = [max(err(r), 1e-5) for r in rs]
            ax.scatter([float(r["time_us"]) for r in rs], errs, s=4, color=c, alpha=0.25)
            t_med = times[len(times) // 2]
            e_max = max(errs)
            points.append((t_med, e_max, model, grid))
            ax.scatter([t_med], [e_max], s=60, color=c, edgecolor="k", zorder=3)
            ax.annotate(grid, (t_med, e_max), fontsize=7, xytext=(3, 3), textcoords="offset points")
        front, best = [], float("inf")
        for t, e, _, _ in sorted(points):
            if e < best:
                front.append((t, e))
                best = e
        ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=1, label="Pareto front (worst case)")
        for m, c in colors.items():
            ax.scatter([], [], color=c, label=m)
        ax.axhline(0.10, color="gray", lw=0.8, ls=":")
        ax.axvline(50.0, color="gray", lw=0.8, ls=":")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("median time per patch [us] (load-controlled normal + tangential)")
        ax.set_ylabel("relative error")
        ax.set_title(title)
        ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
