#!/usr/bin/python3
"""Draws every figure slamkit asks for in one process, so matplotlib is imported once.

  plot.py REQUEST    REQUEST: a JSON list of figures, each {"figure": KIND, ...} with KIND
                     ate, rpe (plot_trajectory_errors.py), compare (plot_compare.py) or
                     history (plot_history.py) and the fields that module's function reads.
Example: plot.py '[{"figure": "ate", "metrics": "run/metrics.json",
                   "csv": "run/errors.csv", "out": "run", "title": "fr2", "system_name": "x"}]'
Exit codes: 0 drawn, 1 a figure failed, 3 no matplotlib (or numpy) in this interpreter.
"""
import importlib
import json
import sys

# Which module draws each kind, and its function: only the modules asked for are imported.
KINDS = {
    "ate": ("plot_trajectory_errors", "plot_ate"),
    "rpe": ("plot_trajectory_errors", "plot_rpe"),
    "compare": ("plot_compare", "plot_compare"),
    "history": ("plot_history", "plot_history"),
}
NO_MATPLOTLIB = 3


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    figures = json.loads(sys.argv[1])
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError:
        sys.exit(NO_MATPLOTLIB)  # slamkit says so in its own words
    for figure in figures:
        module, function = KINDS[figure["figure"]]
        getattr(importlib.import_module(module), function)(figure)


if __name__ == "__main__":
    main()
