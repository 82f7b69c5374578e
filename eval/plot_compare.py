"""Comparison of several evaluated runs: box plot of the per-pose ATE of each run, with a
table of the main statistics under it (ate_comparison.png / .svg, or the formats asked for)."""
import json
import os

import numpy as np

from plot_style import new_figure, save


def plot_compare(request):
    """Request: runs (list of [name, folder]), out, title (optional), formats, dpi."""
    names, errors, rows = [], [], []
    sequences = set()
    for name, folder in request["runs"]:
        with open(os.path.join(folder, "metrics.json")) as f:
            metrics = json.load(f)
        data = np.atleast_1d(np.genfromtxt(os.path.join(folder, "errors.csv"), delimiter=",",
                                           names=True))
        names.append(name)
        errors.append(data["ate_m"])
        sequences.add(metrics.get("settings", {}).get("title", ""))
        ate, rpe = metrics["ate"], metrics.get("rpe")
        rows.append([str(ate["pairs"])] +
                    ["%.4f" % ate[k] for k in ("rmse", "mean", "median", "std", "max")] +
                    (["%.4f" % rpe["trans"]["rmse"], "%.3f" % rpe["rot_deg"]["rmse"]]
                     if rpe else ["–", "–"]))

    title = request.get("title") or ", ".join(sorted(s for s in sequences if s))
    fig, ax = new_figure((max(5.5, 1.6 * len(names) + 2.5), 4.8))
    ax.boxplot(errors, labels=names, showmeans=True, whis=(5, 95), flierprops={"markersize": 2},
               meanprops={"marker": "^", "markerfacecolor": "tab:red",
                          "markeredgecolor": "tab:red", "markersize": 5})
    ax.set_ylabel("absolute translational error [m]")
    ax.set_ylim(bottom=0)
    ax.set_title("ATE per run%s\n(box: quartiles, whiskers: 5–95th percentile, ▲ mean)"
                 % (" on " + title if title else ""))
    columns = ["pairs", "RMSE", "mean", "median", "std", "max", "RPE t", "RPE rot"]
    height = 0.075 * (len(names) + 1)
    table = ax.table(cellText=rows, rowLabels=names, colLabels=columns, loc="bottom",
                     bbox=[0.0, -0.2 - height, 1.0, height])
    table.auto_set_font_size(False)
    table.set_fontsize(8)
    ax.text(0.0, -0.24 - height, "ATE statistics and RPE t (translational RMSE) in m, RPE rot "
            "(rotational RMSE) in deg", transform=ax.transAxes, fontsize=8, va="top")
    save(fig, request["out"], "ate_comparison", request)
