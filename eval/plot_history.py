#!/usr/bin/python3
"""ATE RMSE of each entry of a regression suite over slamkit versions, from the history file
`slamkit regress` appends to (results/history.csv): ate_history.png / .svg.

Versions are placed in the order they first appear in the file; a version run several times
shows its latest value."""
import argparse
import csv

from plot_style import STYLE, plt, save


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--history", required=True, help="history.csv")
    parser.add_argument("--suite", required=True, help="suite name (the 'suite' column)")
    parser.add_argument("--out", required=True)
    parser.add_argument("--pdf", action="store_true")
    args = parser.parse_args()
    plt.rcParams.update(STYLE)

    versions, series = [], {}
    with open(args.history, newline="") as f:
        for row in csv.DictReader(f):
            if row["suite"] != args.suite or not row.get("ate_rmse"):
                continue
            if row["version"] not in versions:
                versions.append(row["version"])
            series.setdefault(row["entry"], {})[row["version"]] = 1000 * float(row["ate_rmse"])

    fig, ax = plt.subplots(figsize=(max(6.0, 0.9 * len(versions) + 3.0), 4.2))
    for entry, by_version in sorted(series.items()):
        xs = [i for i, v in enumerate(versions) if v in by_version]
        ax.plot(xs, [by_version[versions[i]] for i in xs], marker="o", lw=1.2, label=entry)
    ax.set_xticks(range(len(versions)))
    ax.set_xticklabels(versions, rotation=30, ha="right")
    ax.set_xlim(-0.5, len(versions) - 0.5)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("slamkit version")
    ax.set_ylabel("ATE RMSE [mm]")
    ax.set_title("ATE RMSE over versions: suite %s" % args.suite)
    if series:
        ax.legend(loc="best", framealpha=0.9)
    save(fig, args.out, "ate_history", args.pdf)


if __name__ == "__main__":
    main()
