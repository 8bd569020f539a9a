#!/usr/bin/env python3
"""Plots of `conforma validate`: DIR/validate.csv, DIR/<model>/steps.csv (and, with measured profiles,
DIR/validate_profiles.csv, DIR/measured_profile_N.csv, DIR/<model>/simulated_profile_N.csv) -> DIR/validate_*.png.

usage: plot_validate.py DIR hertz,conformal
Run with a python3 that has matplotlib (python3-matplotlib); conforma uses $CONFORMA_PYTHON or python3 on PATH.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_compare import read_profile  # noqa: E402  (same folder: the profile CSVs of the wear output)

DIMENSIONS = (("Sd", "sd_mm", "Sd (flange thickness)"), ("Sh", "sh_mm", "Sh (flange height)"),
              ("qR", "qr_mm", "qR"))
MARKERS = "os^Dv<>"


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def value(text):
    return float(text) if text not in ("", None) else None


def main():
    out = sys.argv[1]
    models = [m for m in sys.argv[2].split(",") if m]
    rows = read_rows(os.path.join(out, "validate.csv"))
    steps = {m: read_rows(os.path.join(out, m, "steps.csv")) for m in models}
    colours = {m: plt.cm.tab10(i) for i, m in enumerate(models)}
    files = sorted({r["measured_file"] for r in rows})

    # Sd, Sh, qR against km: simulated step series (markers at the step ends set by the cap), measured points,
    # and the simulated values interpolated at the measured km
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.4))
    for (dim, key, title), ax in zip(DIMENSIONS, axes):
        for m in models:
            st = steps[m]
            ax.plot([float(r["km"]) for r in st], [float(r[key]) for r in st], "-", marker=".", ms=4, lw=1.2,
                    color=colours[m], label=f"{m} (step ends)")
            pts = [r for r in rows if r["model"] == m and r["dimension"] == dim and r["simulated_mm"] != ""]
            ax.plot([float(r["km"]) for r in pts], [float(r["simulated_mm"]) for r in pts], "x", ms=8, mew=1.5,
                    color=colours[m], label=f"{m} at measured km")
        for k, f in enumerate(files):
            pts = [r for r in rows if r["model"] == models[0] and r["dimension"] == dim and r["measured_file"] == f]
            ax.plot([float(r["km"]) for r in pts], [float(r["measured_mm"]) for r in pts], MARKERS[k % len(MARKERS)],
                    color="black", mfc="none", ms=8, label=f"measured: {f}")
        ax.set_title(title)
        ax.set_xlabel("km")
        ax.set_ylabel(f"{dim} [mm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "validate_dimensions.png"), dpi=120)
    plt.close(fig)

    # errors (simulated - measured) per measured km
    fig, axes = plt.subplots(1, 3, figsize=(16, 4.2))
    width = 0.8 / max(1, len(models))
    for (dim, _, title), ax in zip(DIMENSIONS, axes):
        kms = sorted({float(r["km"]) for r in rows if r["dimension"] == dim})
        for j, m in enumerate(models):
            xs, es = [], []
            for i, km in enumerate(kms):
                for r in rows:
                    if r["model"] == m and r["dimension"] == dim and float(r["km"]) == km and r["error_mm"] != "":
                        xs.append(i + (j - (len(models) - 1) / 2) * width)
                        es.append(float(r["error_mm"]))
            ax.bar(xs, es, width, color=colours[m], label=m)
        ax.set_xticks(range(len(kms)))
        ax.set_xticklabels([f"{km:.0f}" for km in kms])
        ax.axhline(0.0, color="black", lw=0.8)
        ax.set_title(f"{title}: simulated - measured")
        ax.set_xlabel("measured km")
        ax.set_ylabel("error [mm]")
        ax.grid(alpha=0.3, axis="y")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "validate_errors.png"), dpi=120)
    plt.close(fig)

    # measured profiles against the simulated ones at the same km, zoomed on the worn zone
    prof_csv = os.path.join(out, "validate_profiles.csv")
    if os.path.exists(prof_csv):
        prows = read_rows(prof_csv)
        n = len([r for r in prows if r["model"] == models[0]])
        fig, axes = plt.subplots(2, n, figsize=(6 * n, 7.5), squeeze=False, sharex="col")
        for i, ax in enumerate(axes[0]):
            mp = os.path.join(out, f"measured_profile_{i + 1}.csv")
            ys, zs = read_profile(mp)
            ax.plot(ys, zs, color="black", lw=1.4, label="measured")
            lo, hi = [], []
            for m in models:
                r = [p for p in prows if p["model"] == m][i]
                sp = os.path.join(out, m, f"simulated_profile_{i + 1}.csv")
                if os.path.exists(sp):
                    sy, sz = read_profile(sp)
                    ax.plot(sy, sz, color=colours[m], lw=1.0,
                            label=f"{m}: RMS {value(r['rms_mm']):.3f}, max {value(r['max_mm']):.3f} mm")
                if r["status"] == "measured":
                    lo.append(float(r["zone_y_min_mm"]))
                    hi.append(float(r["zone_y_max_mm"]))
                km = float(r["km"])
            if lo:
                ax.axvspan(min(lo), max(hi), color="0.9", zorder=0, label="worn zone")
                x0, x1 = min(lo) - 5, max(hi) + 5
                ax.set_xlim(x0, x1)
                inside = [z for y, z in zip(ys, zs) if x0 <= y <= x1]
                if inside:
                    pad = 0.05 * (max(inside) - min(inside)) + 0.1
                    ax.set_ylim(min(inside) - pad, max(inside) + pad)
            ax.set_title(f"profile at {km:.0f} km")
            ax.set_ylabel("z [mm] (+ larger radius)")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
            # the distances themselves (sub-mm: invisible on the profiles)
            dax = axes[1][i]
            for m in models:
                dp = os.path.join(out, m, f"profile_distance_{i + 1}.csv")
                if os.path.exists(dp):
                    dy, dd = read_profile(dp)
                    dax.plot(dy, dd, ".", ms=2, color=colours[m], label=m)
            dax.axhline(0.0, color="black", lw=0.8)
            dax.set_xlabel("y [mm]")
            dax.set_ylabel("normal distance [mm] (> 0: simulation wore more)")
            dax.grid(alpha=0.3)
            dax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "validate_profiles.png"), dpi=120)
        plt.close(fig)


if __name__ == "__main__":
    main()
