#!/usr/bin/env python3
"""Plots of `conforma compare`: DIR/<model>/{steps.csv, wheel_step_NNN.csv, wear_step_NNN.csv} -> DIR/*.png.

usage: plot_compare.py DIR hertz,kp,conformal
Run with a python3 that has matplotlib (python3-matplotlib); conforma uses $CONFORMA_PYTHON or python3 on PATH.
"""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_profile(path):
    ys, zs = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or line.startswith("y"):
                continue
            y, z = line.strip().split(",")[:2]
            ys.append(float(y))
            zs.append(float(z))
    return ys, zs


def normal_distance(first, second, spacing_mm=0.1):
    """Signed distance from `first` to `second` along the outward normals of `first` (left of the tangent, as
    Profile::normal), sampled every spacing_mm of arc length: > 0 where `second` lies inside `first` (deeper). The
    quantity of report.md's model differences (MeasureWheelWear, src/simulation/wear_simulation.cpp)."""
    import numpy as np

    def resample(ys, zs):
        p = np.column_stack([ys, zs])
        s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(p, axis=0).T))])
        t = np.arange(0.0, s[-1], spacing_mm)
        return np.column_stack([np.interp(t, s, p[:, 0]), np.interp(t, s, p[:, 1])])

    a, b = resample(*first), resample(*second)
    tangent = np.gradient(a, axis=0)
    tangent /= np.linalg.norm(tangent, axis=1)[:, None]
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]])
    seg0, seg = b[:-1], np.diff(b, axis=0)
    out = np.empty(len(a))
    for k, q in enumerate(a):  # nearest point of the second polyline
        t = np.clip(((q - seg0) * seg).sum(axis=1) / (seg * seg).sum(axis=1), 0.0, 1.0)
        c = seg0 + t[:, None] * seg
        j = np.argmin(((c - q) ** 2).sum(axis=1))
        out[k] = np.dot(q - c[j], normal[k])
    return a[:, 0], out


def read_steps(path):
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def read_wear(path):
    s, rate = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or line.startswith("s_mm"):
                continue
            a, b, _ = line.strip().split(",")
            s.append(float(a))
            rate.append(float(b))
    return s, rate


def z_on_face(ys, zs, y):
    """z of the profile at y on the part after the flange tip (single-valued there), linear interpolation."""
    tip = max(range(len(zs)), key=lambda i: zs[i])
    for i in range(tip, len(ys) - 1):
        if ys[i] <= y <= ys[i + 1] and ys[i + 1] > ys[i]:
            t = (y - ys[i]) / (ys[i + 1] - ys[i])
            return zs[i] + t * (zs[i + 1] - zs[i])
    return None


def main():
    out = sys.argv[1]
    models = [m for m in sys.argv[2].split(",") if m]
    data = {}
    for m in models:
        d = os.path.join(out, m)
        profiles = sorted(glob.glob(os.path.join(d, "wheel_step_*.csv")))
        data[m] = {
            "steps": read_steps(os.path.join(d, "steps.csv")),
            "profiles": [read_profile(p) for p in profiles],
            "wear": [read_wear(p) for p in sorted(glob.glob(os.path.join(d, "wear_step_*.csv")))],
        }
    # profile evolution and zooms
    for name, xlim, ylim in (("profiles", (-72, 62), (-3, 30)), ("tread_zoom", (-15, 45), (-1.6, 1.2)),
                             ("flange_zoom", (-45, -22), (0, 22))):
        fig, axes = plt.subplots(1, len(models), figsize=(5.5 * len(models), 4.2), squeeze=False)
        for ax, m in zip(axes[0], models):
            st = data[m]["steps"]
            n = len(data[m]["profiles"])
            for i, (ys, zs) in enumerate(data[m]["profiles"]):
                km = st[i]["km"] if i < len(st) else float("nan")
                ax.plot(ys, zs, color=plt.cm.viridis(i / max(1, n - 1)), lw=0.9, label=f"{i}: {km:.0f} km")
            ax.set_xlim(*xlim)
            ax.set_ylim(*ylim)
            ax.set_title(f"{m}: wheel profile evolution")
            ax.set_xlabel("y [mm]")
            ax.set_ylabel("z [mm] (+ larger radius)")
            ax.grid(alpha=0.3)
            if name != "profiles":
                ax.legend(fontsize=6, ncol=2)
        fig.tight_layout()
        fig.savefig(os.path.join(out, name + ".png"), dpi=120)
        plt.close(fig)
    # Sd, Sh, qR against km
    fig, axes = plt.subplots(1, 3, figsize=(15, 4))
    for key, ax in zip(("sd_mm", "sh_mm", "qr_mm"), axes):
        for m in models:
            st = data[m]["steps"]
            ax.plot([r["km"] for r in st], [r[key] for r in st], "o-", ms=3, label=m)
        ax.set_xlabel("km")
        ax.set_ylabel(key.replace("_mm", " [mm]"))
        ax.grid(alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "dimensions.png"), dpi=120)
    plt.close(fig)
    # model differences: the normal distance the report uses (MeasureWheelWear), and km per step
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.2))
    ref = models[0]
    for m in models[1:]:
        n = min(len(data[m]["profiles"]), len(data[ref]["profiles"]))
        for i in range(1, n):
            y, d = normal_distance(data[ref]["profiles"][i], data[m]["profiles"][i])
            axes[0].plot(y, d, color=plt.cm.viridis(i / max(1, n - 1)), lw=0.9, label=f"{m} vs {ref}, step {i}")
    axes[0].set_xlabel("y of the first model's profile [mm]")
    axes[0].set_ylabel("normal distance [mm] (> 0: second model deeper)")
    axes[0].set_title("profile difference between the models (same step)")
    axes[0].grid(alpha=0.3)
    axes[0].legend(fontsize=6)
    width = 0.8 / len(models)
    for k, m in enumerate(models):
        st = [r for r in data[m]["steps"] if r["step"] > 0]
        axes[1].bar([r["step"] + (k - (len(models) - 1) / 2) * width for r in st], [r["step_km"] for r in st], width,
                    label=m)
    axes[1].set_xlabel("step")
    axes[1].set_ylabel("km of the step (0.4 mm cap)")
    axes[1].grid(alpha=0.3)
    axes[1].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "model_difference.png"), dpi=120)
    plt.close(fig)
    # wear rate distribution of the first step
    fig, ax = plt.subplots(figsize=(7, 4))
    for m in models:
        if data[m]["wear"]:
            s, rate = data[m]["wear"][0]
            ax.plot(s, rate, lw=1, label=m)
    ax.set_xlabel("wheel arc length s [mm] (0 at the flange back)")
    ax.set_ylabel("wear rate [mm per km] (mean of all wheels)")
    ax.set_title("wheel wear distribution, step 1")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "wear_rate.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
