"""ATE RMSE of each entry of a regression suite over slamkit versions, from the history files
`slamkit regress` appends to (the suite's tracked results/history.csv, then the run's own):
ate_history.png / .svg.

Versions are placed in the order they first appear in the files; a version run several times
shows its latest value."""
import csv

from plot_style import new_figure, save


def plot_history(request):
    """Request: histories (history.csv files, oldest first), suite (the 'suite' column), out,
    formats, dpi."""
    versions, series = [], {}
    for history in request["histories"]:
        with open(history, newline="") as f:
            for row in csv.DictReader(f):
                if row["suite"] != request["suite"] or not row.get("ate_rmse"):
                    continue
                if row["version"] not in versions:
                    versions.append(row["version"])
                series.setdefault(row["entry"], {})[row["version"]] = 1000 * float(row["ate_rmse"])

    fig, ax = new_figure((max(6.0, 0.9 * len(versions) + 3.0), 4.2))
    for entry, by_version in sorted(series.items()):
        xs = [i for i, v in enumerate(versions) if v in by_version]
        ax.plot(xs, [by_version[versions[i]] for i in xs], marker="o", lw=1.2, label=entry)
    ax.set_xticks(range(len(versions)))
    ax.set_xticklabels(versions, rotation=30, ha="right")
    ax.set_xlim(-0.5, len(versions) - 0.5)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("slamkit version")
    ax.set_ylabel("ATE RMSE [mm]")
    ax.set_title("ATE RMSE over versions: suite %s" % request["suite"])
    if series:
        ax.legend(loc="best", framealpha=0.9)
    save(fig, request["out"], "ate_history", request)
