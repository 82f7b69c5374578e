#!/usr/bin/python3
"""Draws every figure slamkit asks for with one Python start: matplotlib is imported once,
then each figure is drawn in a child forked from this process, side by side on the cores.

  plot.py REQUEST    REQUEST: a JSON list of figures, each {"figure": KIND, ...} with KIND
                     ate, rpe (plot_trajectory_errors.py), compare (plot_compare.py),
                     history (plot_history.py) or trajectories (plot_trajectories.py) and
                     the fields that module's function reads.
Example: plot.py '[{"figure": "ate", "metrics": "run/metrics.json",
                   "csv": "run/errors.csv", "out": "run", "title": "fr2", "system_name": "x"}]'
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
    "trajectories": ("plot_trajectories", "plot_trajectories"),
}
NO_MATPLOTLIB = 3


def draw(figure):
    module, function = KINDS[figure["figure"]]
    getattr(importlib.import_module(module), function)(figure)


def wait_for_one(running):
    """Waits for one drawing child; returns True when it failed."""
    pid, status = os.wait()
    running.discard(pid)
    return not (os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    figures = json.loads(sys.argv[1])
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError:
        sys.exit(NO_MATPLOTLIB)  # slamkit says so in its own words
    for figure in figures:  # imported here, once, before the children are forked
        importlib.import_module(KINDS[figure["figure"]][0])
    from plot_style import InputMismatch
    # Each figure kind is drawn in a child forked after the imports, as many at once as there
    # are cores: drawing is single-threaded and is 60% of the time (0.6 of 1.0 s on fr2/desk).
    # A child's files are the same as drawn alone: nothing is shared but the imported modules.
    cores = len(os.sched_getaffinity(0))
    running, failed = set(), False
    for figure in figures:
        if len(running) >= cores:
            failed |= wait_for_one(running)
        sys.stdout.flush(), sys.stderr.flush()
        pid = os.fork()
        if pid == 0:
            code = 0
            try:
                draw(figure)
            except OSError as error:  # a file it cannot read or write: one line says which
                what = error.strerror or str(error)
                if error.filename:
                    what = "%s: %s" % (error.filename, what)
                print("plot.py: no %s figure: %s" % (figure["figure"], what), file=sys.stderr)
                code = 1
            except InputMismatch as error:  # the inputs' fault: the message says what to do
                print("plot.py: no %s figure: %s" % (figure["figure"], error), file=sys.stderr)
                code = 1
            except BaseException:  # a defect: the traceback says where
                traceback.print_exc()
                code = 1
            sys.stdout.flush(), sys.stderr.flush()
            os._exit(code)
        running.add(pid)
    while running:
        failed |= wait_for_one(running)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
