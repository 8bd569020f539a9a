#!/usr/bin/env python3
"""Conformal vs Hertzian contact at the flange root of an S1002 wheel on a 60E1 rail (1:40).

One wheelset pose (lateral shift 6.25 mm towards the left rail, yaw 2 mrad, 10 kN per wheel, 20 m/s): the left
wheel touches its rail near the flange root, where wheel and rail are conformal. The script solves the left
wheel with the Hertz model (ellipse at the rigid contact point, FASTSIM) and with the conformal model (extended
Kik-Piotrowski in curvilinear rail coordinates, curved-patch FASTSIM), prints the patch forces side by side and
plots the pressure and the tangential traction of both in the (x, s) coordinates of the patch (the patch's
2-D grid, patch["grid"]).

    python3 examples/conformal_vs_hertz.py [--output-dir DIR] [--lateral-mm 6.25] [--yaw-mrad 2]

Writes DIR/conformal_vs_hertz.png (matplotlib, Agg backend). Needs the `conforma` package (pip install, or
PYTHONPATH=build-dir/python).
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


def solve(track, model, lateral_m, yaw_rad):
    wheel = conforma.contact(track, lateral_m=lateral_m, yaw_rad=yaw_rad, model=model, load_N=10e3, speed_m_s=20.0,
                             side="left", fields=True)[0]
    if wheel["status"] != "ok" or not wheel["patches"]:
        sys.exit(f"{model}: no converged contact at y = {lateral_m * 1e3} mm ({wheel['status']})")
    return wheel


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default=os.environ.get("CONFORMA_OUTPUT_DIR", "."))
    parser.add_argument("--lateral-mm", type=float, default=6.25)
    parser.add_argument("--yaw-mrad", type=float, default=2.0)
    args = parser.parse_args()
    out_dir = pathlib.Path(args.output_dir)
    out_dir.mkdir(parents=True, exist_ok=True)

    track = conforma.Track("S1002", "60E1")
    y, yaw = args.lateral_mm * 1e-3, args.yaw_mrad * 1e-3
    wheels = {m: solve(track, m, y, yaw) for m in ("hertz", "conformal")}

    print(f"S1002 / 60E1 1:40, y = {args.lateral_mm} mm, yaw = {args.yaw_mrad} mrad, left wheel, 10 kN")
    print(f"{'model':10s} {'patch':>5s} {'angle[rad]':>10s} {'alpha_c[deg]':>12s} {'Fn[N]':>9s} {'Fx[N]':>9s} "
          f"{'Fs[N]':>9s} {'Mz[Nm]':>8s} {'pmax[MPa]':>9s} {'area[mm2]':>9s}")
    for model, wheel in wheels.items():
        for j, p in enumerate(wheel["patches"]):
            print(f"{model:10s} {j:5d} {p['contact_angle_rad']:10.4f} {p['alpha_c_deg']:12.2f} {p['fn_N']:9.1f} "
                  f"{p['fx_N']:9.1f} {p['fy_N']:9.1f} {p['mz_Nm']:8.3f} {p['pmax_Pa'] * 1e-6:9.1f} "
                  f"{p['area_m2'] * 1e6:9.2f}")
        print(f"{model:10s} total lateral force on the wheel {wheel['lateral_force_N']:9.1f} N")

    # the main patch (largest normal force) of each model
    mains = {m: max(w["patches"], key=lambda p: p["fn_N"]) for m, w in wheels.items()}
    fig, axes = plt.subplots(2, 3, figsize=(14, 8), constrained_layout=True)
    pmax = max(p["pmax_Pa"] for p in mains.values()) * 1e-6
    for row, (model, p) in enumerate(mains.items()):
        g = p["grid"]  # the fields as 2-D arrays over (s, x); outside the contact area masked out here
        x_mm, s_mm, outside = g["x_m"] * 1e3, g["s_m"] * 1e3, ~g["in_contact"]
        pressure = np.ma.masked_where(outside, g["pressure_Pa"] * 1e-6)
        mesh = axes[row, 0].pcolormesh(x_mm, s_mm, pressure, shading="nearest", cmap="viridis", vmin=0, vmax=pmax)
        fig.colorbar(mesh, ax=axes[row, 0], label="pressure [MPa]")
        axes[row, 0].set_title(f"{model}: pressure, Fn = {p['fn_N'] / 1e3:.2f} kN")
        tau = np.ma.masked_where(outside, np.hypot(g["traction_x_Pa"], g["traction_s_Pa"]) * 1e-6)
        mesh = axes[row, 1].pcolormesh(x_mm, s_mm, tau, shading="nearest", cmap="magma", vmin=0, vmax=0.3 * pmax)
        if g["adhesion"].any():
            axes[row, 1].contour(x_mm, s_mm, g["adhesion"].astype(float), levels=[0.5], colors="cyan", linewidths=1)
        fig.colorbar(mesh, ax=axes[row, 1], label="|traction| [MPa] (cyan: adhesion boundary)")
        axes[row, 1].set_title(f"{model}: traction (Fx {p['fx_N'] / 1e3:.2f}, Fs {p['fy_N'] / 1e3:.2f} kN)")
        for ax in axes[row, :2]:
            ax.set_xlabel("x along the track [mm]")
            ax.set_ylabel("s along the rail profile [mm]")
        # across the patch: the grid column nearest to the patch's middle along x (strips outside it: no contact)
        j = int(np.argmin(np.abs(x_mm - 0.5 * (x_mm.min() + x_mm.max()))))
        cut = g["in_contact"][:, j]
        axes[0, 2].plot(s_mm[cut], g["pressure_Pa"][cut, j] * 1e-6, ".-", label=model)
        axes[1, 2].plot(s_mm[cut], g["traction_x_Pa"][cut, j] * 1e-6, ".-", label=f"{model} x")
        axes[1, 2].plot(s_mm[cut], g["traction_s_Pa"][cut, j] * 1e-6, "x--", label=f"{model} s")
    axes[0, 2].set_title("pressure across the patch (middle along x)")
    axes[0, 2].set_ylabel("pressure [MPa]")
    axes[1, 2].set_title("tangential traction across the patch")
    axes[1, 2].set_ylabel("traction [MPa]")
    for ax in axes[:, 2]:
        ax.set_xlabel("s along the rail profile [mm]")
        ax.legend()
    fig.suptitle(f"S1002 on 60E1 (1:40), y = {args.lateral_mm} mm, yaw = {args.yaw_mrad} mrad: Hertz vs conformal")
    path = out_dir / "conformal_vs_hertz.png"
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
