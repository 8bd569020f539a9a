#!/usr/bin/env python3
"""Scatter of `conforma threshold`: conformal-vs-planar difference against the conformity index alpha_c.

usage: plot_threshold.py threshold.csv threshold.json out.png
Markers per situation set; horizontal line: the tolerance; vertical lines: the step-fit threshold per set and for
all sets (threshold.hpp explains the fit); dashed curve: the power-law fit d = c alpha^k of all sets.
"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main(path_csv, path_json, out):
    rows = [r for r in csv.DictReader(open(path_csv)) if r["valid"] == "1"]
    fit = json.load(open(path_json))
    tol = fit["tolerance"]
    colors = {"new": "tab:blue", "worn": "tab:orange", "groove": "tab:green"}
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for s in sorted({r["set"] for r in rows}):
        rs = [r for r in rows if r["set"] == s]
        ax.scatter([float(r["alpha_c_deg"]) for r in rs], [max(float(r["d_max"]), 1e-5) for r in rs], s=12,
                   color=colors.get(s, "gray"), label=s, alpha=0.7)
        t = fit["sets"][s]["threshold_deg"]
        if t is not None:
            ax.axvline(t, color=colors.get(s, "gray"), ls=":", lw=1.2, label=f"{s}: step fit {t:.1f} deg")
    ax.axhline(tol, color="k", lw=0.8, label=f"tolerance {100 * tol:.0f} %")
    t_all = fit["all"]["threshold_deg"]
    if t_all is not None:
        ax.axvline(t_all, color="k", lw=1.5, label=f"all sets: step fit {t_all:.1f} deg")
    ax.axvline(18.0, color="gray", lw=1.0, ls="-.", label="paper 003: 18 deg")
    c, k = fit["all"]["power_law_c"], fit["all"]["power_law_k"]
    if c > 0:
        a = np.logspace(-1, np.log10(max(float(r["alpha_c_deg"]) for r in rows) + 1), 100)
        ax.plot(a, c * a ** k, "k--", lw=1, label=f"power law {c:.2g} alpha^{k:.2f}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("conformity index alpha_c [deg]")
    ax.set_ylabel("max relative difference conformal vs " + fit["against"])
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main(*sys.argv[1:4])
