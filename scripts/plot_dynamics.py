#!/usr/bin/env python3
"""Plot a `conforma dynamics --out` time history against the distance s: lateral shift and yaw of every wheelset
(and the bogie frames and carbodies), Y/Q and the wear number T*gamma of every wheel.

Usage: plot_dynamics.py HISTORY.csv [--out FIGURE.png] [--wheelsets 0,1]
Needs matplotlib (python3-matplotlib).
"""
import argparse
import csv
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", help="time history written by `conforma dynamics --out`")
    ap.add_argument("--out", default="", help="figure file (default: HISTORY.png beside the CSV)")
    ap.add_argument("--wheelsets", default="", help="comma-separated wheelset indices to plot (default: all)")
    args = ap.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with open(args.csv, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit("plot_dynamics: no rows in " + args.csv)
    columns = rows[0].keys()
    wheelsets = sorted({int(c[2:c.index("_")]) for c in columns if c.startswith("ws") and c.endswith("_y_mm")})
    if args.wheelsets:
        wheelsets = [int(w) for w in args.wheelsets.split(",")]

    def col(name):
        return [float(r[name]) if r[name] != "" else float("nan") for r in rows]

    s = col("s_m")
    fig, ax = plt.subplots(4, 1, figsize=(10, 11), sharex=True)
    for j in wheelsets:
        ax[0].plot(s, col("ws%d_y_mm" % j), label="wheelset %d" % j)
        ax[1].plot(s, col("ws%d_psi_mrad" % j), label="wheelset %d" % j)
        for side in ("L", "R"):
            ax[2].plot(s, col("ws%d%s_YQ" % (j, side)), label="ws %d %s" % (j, side))
            ax[3].plot(s, col("ws%d%s_Tgamma_N" % (j, side)), label="ws %d %s" % (j, side))
    for name in sorted(c for c in columns if (c.startswith("bogie") or c.startswith("carbody")) and c.endswith("_y_mm")):
        ax[0].plot(s, col(name), "--", label=name[:-5])
    ax[0].set_ylabel("lateral y, mm")
    ax[1].set_ylabel("yaw psi, mrad")
    ax[2].set_ylabel("Y/Q")
    ax[3].set_ylabel("T gamma, N")
    ax[3].set_xlabel("s of the leading bogie centre, m")
    for a in ax:
        a.grid(True, alpha=0.3)
        a.legend(fontsize=7, ncol=4)
    fig.tight_layout()
    out = args.out or args.csv.rsplit(".", 1)[0] + ".png"
    fig.savefig(out, dpi=120)
    print("plot_dynamics: wrote " + out)


if __name__ == "__main__":
    main()
