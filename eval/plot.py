#!/usr/bin/python3
"""Draws every figure slamkit asks for in one process, so matplotlib is imported once.

  plot.py REQUEST    REQUEST: a JSON list of figures, each {"figure": KIND, ...} with KIND
                     ate, rpe (plot_trajectory_errors.py), compare (plot_compare.py) or
                     history (plot_history.py) and the fields that module's function reads.
Example: plot.py '[{"figure": "ate", "metrics": "run/metrics.json",
                   "csv": "run/errors.csv", "out": "run", "title": "fr2", "system_name": "x"}]'
With two or more figures and cores, the second half is drawn by a fork of this process made
after the imports, so it starts nothing again and both cores draw.
Exit codes: 0 drawn, 1 a figure failed, 3 no matplotlib (or numpy) in this interpreter.
"""
import importlib
import json
import os
import sys
import traceback

# Which module draws each kind, and its function: only the modules asked for are imported.
KINDS = {
    "ate": ("plot_trajectory_errors", "plot_ate"),
    "rpe": ("plot_trajectory_errors", "plot_rpe"),
    "compare": ("plot_compare", "plot_compare"),
    "history": ("plot_history", "plot_history"),
}
NO_MATPLOTLIB = 3


def draw(figures):
    """Draws the figures; returns 0, or 1 (after a traceback) when one failed."""
    try:
        for figure in figures:
            module, function = KINDS[figure["figure"]]
            getattr(importlib.import_module(module), function)(figure)
    except Exception:  # noqa: BLE001  (any failure is reported the same way)
        traceback.print_exc()
        return 1
    return 0


def draw_on_two_cores(figures):
    """Draws the first half of the figures here and the rest in a fork; returns 0 when all
    were drawn."""
    if len(figures) < 2 or (os.cpu_count() or 1) < 2:
        return draw(figures)
    half = (len(figures) + 1) // 2
    child = os.fork()
    if child == 0:
        os._exit(draw(figures[half:]))
    failed = draw(figures[:half])
    _, status = os.waitpid(child, 0)
    return 1 if failed or os.waitstatus_to_exitcode(status) != 0 else 0


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    figures = json.loads(sys.argv[1])
    try:
        import plot_style  # noqa: F401  (matplotlib, numpy and the backends, once)
    except ImportError:
        sys.exit(NO_MATPLOTLIB)  # slamkit says so in its own words
    for figure in figures:
        importlib.import_module(KINDS[figure["figure"]][0])
    sys.exit(draw_on_two_cores(figures))


if __name__ == "__main__":
    main()
