#!/usr/bin/python3
"""Heatmap of a sweep's ATE over variants (rows) and sequences (columns), from the
ate_table.csv of `slamkit sweep collect` (metres, mean over seeds; empty: no finished run).
Each cell shows the ATE in mm; its colour is the ATE relative to the best variant of that
sequence, so easy and hard sequences share one scale (ate_heatmap.png / .svg)."""
import argparse
import csv
import math

import numpy as np

from plot_style import new_figure, save


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--table", required=True, help="ate_table.csv")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title", default="")
    parser.add_argument("--pdf", action="store_true")
    args = parser.parse_args()

    with open(args.table) as f:
        rows = list(csv.reader(f))
    sequences = rows[0][1:]
    variants = [row[0] for row in rows[1:]]
    ate = np.array([[float(v) if v else math.nan for v in row[1:]] for row in rows[1:]])
    best = np.nanmin(np.where(np.isnan(ate), np.inf, ate), axis=0)
    ratio = ate / np.where(np.isfinite(best) & (best > 0), best, np.nan)

    fig, ax = new_figure((max(5.0, 1.3 * len(sequences) + 3.0),
                          max(2.5, 0.45 * len(variants) + 1.6)))
    # The scale stops at 3x the best: one failed run (15x) would otherwise turn every 2x green.
    worst = float(np.nanmax(ratio)) if np.isfinite(ratio).any() else 1.5
    top = min(3.0, max(1.5, worst))
    image = ax.imshow(np.ma.masked_invalid(ratio), cmap="RdYlGn_r", vmin=1.0, vmax=top,
                      aspect="auto")
    ax.set_facecolor("#dddddd")
    ax.grid(False)
    for i in range(len(variants)):
        for j in range(len(sequences)):
            text = "–" if math.isnan(ate[i, j]) else "%.2f" % (1000 * ate[i, j])
            weight = "bold" if not math.isnan(ate[i, j]) and ate[i, j] == best[j] else "normal"
            # The colour map's ends are dark: white text there.
            shade = min(1.0, (ratio[i, j] - 1.0) / (top - 1.0)) if np.isfinite(ratio[i, j]) else 0.5
            colour = "white" if shade < 0.15 or shade > 0.85 else "black"
            ax.text(j, i, text, ha="center", va="center", fontsize=9, fontweight=weight,
                    color=colour)
    ax.set_xticks(range(len(sequences)), sequences, rotation=30, ha="right")
    ax.set_yticks(range(len(variants)), variants)
    ax.set_xlabel("sequence")
    ax.set_ylabel("variant")
    ax.set_title("ATE RMSE [mm], mean over seeds%s\n(bold: best per sequence)"
                 % (" — " + args.title if args.title else ""))
    fig.colorbar(image, ax=ax, label="ATE / best ATE of the sequence",
                 extend="max" if worst > top else "neither")
    save(fig, args.out, "ate_heatmap",
         {"formats": ["png", "svg"] + (["pdf"] if args.pdf else [])})


if __name__ == "__main__":
    main()
