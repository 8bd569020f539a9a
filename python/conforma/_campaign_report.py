"""`conforma campaign report DIR`: DIR/report.md (status counts, the result table, the spread of each output over
the cases that share a parameter value) and one PNG per varied numeric parameter: each kept steps.csv column
(Sd, qR, ...) of the last step against the parameter, one colour per model, the mean over the other parameters
(e.g. the seeds) as a line and their minimum-maximum as a band."""
import csv
import json
import math
import pathlib

from ._campaign_spec import CampaignError


def _float(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def read_results(folder):
    folder = pathlib.Path(folder)
    meta_path, table = folder / "campaign.json", folder / "results.csv"
    if not meta_path.is_file() or not table.is_file():
        raise CampaignError(f"{folder}: not a campaign folder (no campaign.json and results.csv; "
                            "conforma campaign run FILE --out DIR makes one)")
    meta = json.loads(meta_path.read_text())
    with open(table, newline="") as f:
        rows = list(csv.DictReader(f))
    return meta, rows


def spread(rows, parameter, column, model):
    """[(value, mean, min, max, n)] of `column` over the ok / partial rows of `model`, grouped by `parameter`."""
    groups = {}
    for r in rows:
        x, y = _float(r.get(parameter)), _float(r.get(column))
        if r["model"] == model and r["status"] != "failed" and x is not None and y is not None:
            groups.setdefault(x, []).append(y)
    return [(x, sum(ys) / len(ys), min(ys), max(ys), len(ys)) for x, ys in sorted(groups.items())]


def _plot(folder, meta, rows, parameter, columns, models):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(columns), figsize=(4.2 * len(columns), 3.6), squeeze=False)
    for ax, column in zip(axes[0], columns):
        for i, model in enumerate(models):
            s = spread(rows, parameter, column, model)
            if not s:
                continue
            colour = f"C{i}"
            xs = [p[0] for p in s]
            ax.plot(xs, [p[1] for p in s], "-o", color=colour, label=model, ms=4)
            if any(p[4] > 1 for p in s):
                ax.fill_between(xs, [p[2] for p in s], [p[3] for p in s], color=colour, alpha=0.2)
        ax.set_xlabel(parameter)
        ax.set_ylabel(f"{column} (last step)")
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.suptitle(f"campaign {meta['name']}: mean over the other parameters, band: min-max", fontsize=9)
    fig.tight_layout()
    name = f"plot_{parameter.replace('.', '_')}.png"
    fig.savefig(folder / name, dpi=110)
    plt.close(fig)
    return name


def write_report(folder, plots=True):
    """Writes DIR/report.md and the plots; returns the path of report.md."""
    folder = pathlib.Path(folder)
    meta, rows = read_results(folder)
    params, columns = meta["parameters"], meta["columns"]
    models = sorted({r["model"] for r in rows})
    counts = {s: len({r["case_id"] for r in rows if r["status"] == s}) for s in ("ok", "partial", "failed")}
    md = [f"# Campaign {meta['name']}", "",
          f"{meta['command']} of {meta['base']}; {meta['cases']} cases "
          f"({counts['ok']} ok, {counts['partial']} partial, {counts['failed']} failed; "
          f"{meta['cases'] - sum(counts.values())} not run yet); varied: {', '.join(params) or 'nothing'}; "
          f"models: {', '.join(models)}.", ""]
    failed = [r for r in rows if r["status"] == "failed"]
    if failed:
        md += ["## Failed cases", ""] + [f"- {r['case_id']} ({r['model']}): {r['error']}" for r in failed] + [""]
    md += ["## Results (last step of each case)", "",
           "| case | model | status | " + " | ".join(params + columns) + " |",
           "|---" * (3 + len(params) + len(columns)) + "|"]
    for r in rows:
        md.append(f"| {r['case_id']} | {r['model']} | {r['status']} | "
                  + " | ".join(r.get(c, "") for c in params + columns) + " |")
    md.append("")
    numeric = [p for p in params if any(_float(r.get(p)) is not None for r in rows)]
    plotted = [c for c in columns if c in ("sd_mm", "qr_mm")] or [c for c in columns if c != "km"][:2]
    for p in numeric:
        md += [f"## Against {p}", "", "mean [min, max] (n cases) of the other parameters' combinations", "",
               f"| {p} | model | " + " | ".join(plotted) + " |", "|---" * (2 + len(plotted)) + "|"]
        for model in models:
            per_col = {c: spread(rows, p, c, model) for c in plotted}
            for i, s in enumerate(per_col[plotted[0]] if plotted else []):
                cells = []
                for c in plotted:
                    x, mean, lo, hi, n = per_col[c][i]
                    cells.append(f"{mean:.4g} [{lo:.4g}, {hi:.4g}] ({n})")
                md.append(f"| {s[0]:g} | {model} | " + " | ".join(cells) + " |")
        if plots and plotted:
            md += ["", f"![{p}]({_plot(folder, meta, rows, p, plotted, models)})"]
        md.append("")
    (folder / "report.md").write_text("\n".join(md) + "\n")
    return folder / "report.md"
