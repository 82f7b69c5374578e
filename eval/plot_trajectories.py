"""Several evaluated runs of one sequence drawn together, as evo_traj draws them: the
groundtruth and each run's estimate, aligned as its evaluation aligned it (the positions of its
errors.csv), with a legend naming each run.

  trajectories_PL  - plan view in plane PL (xy, xz, yz), equal axis scales;
  trajectories_xyz - x, y and z over time, one panel each.

The runs must have been evaluated against the same groundtruth (metrics.json's
inputs.groundtruth: same poses and span, and same checksum where both have one); otherwise no
figure is drawn and InputMismatch says which runs differ."""
import json
import os

import numpy as np

from plot_style import InputMismatch, new_figure, save
from plot_trajectory_errors import PLANE_AXES, break_gaps, read_csv

AXIS_NAMES = ("x", "y", "z")


def describe(groundtruth):
    """The groundtruth as a message names it: its path, else its poses and span."""
    if groundtruth.get("path"):
        return groundtruth["path"]
    return "%s poses, %s..%s s" % (groundtruth.get("poses"), groundtruth.get("start"),
                                   groundtruth.get("end"))


def same_groundtruth(a, b):
    if any(a.get(key) != b.get(key) for key in ("poses", "start", "end")):
        return False
    # Runs given trajectories in memory (the Python module) have no checksum.
    return "fnv1a64" not in a or "fnv1a64" not in b or a["fnv1a64"] == b["fnv1a64"]


def read_runs(request):
    """[(name, errors.csv rows)] and the first run's sequence title, after checking the runs
    share one groundtruth."""
    runs, first, sequence = [], None, ""
    for name, folder in request["runs"]:
        with open(os.path.join(folder, "metrics.json")) as f:
            metrics = json.load(f)
        groundtruth = metrics.get("inputs", {}).get("groundtruth", {})
        if first is None:
            first = (name, groundtruth)
            sequence = metrics.get("settings", {}).get("title", "")
        elif not same_groundtruth(first[1], groundtruth):
            raise InputMismatch(
                "runs '%s' and '%s' were evaluated against different groundtruth (%s; %s): "
                "trajectories are drawn together only for runs of one sequence"
                % (first[0], name, describe(first[1]), describe(groundtruth)))
        runs.append((name, read_csv(os.path.join(folder, "errors.csv"))))
    return runs, sequence


def groundtruth_track(runs):
    """The groundtruth positions matched by any run, in time order, each once: (t, xyz)."""
    time = np.concatenate([errors["time"] for _, errors in runs])
    xyz = np.concatenate([np.stack([errors["gt_t" + a] for a in AXIS_NAMES], axis=1)
                          for _, errors in runs])
    xyz, first = np.unique(xyz, axis=0, return_index=True)
    order = np.argsort(time[first])
    return time[first][order], xyz[order]


def estimate(errors):
    return errors["time"], np.stack([errors["est_t" + a] for a in AXIS_NAMES], axis=1)


def plot_plane(runs, groundtruth, plane, title, request):
    a, b = PLANE_AXES[plane]
    fig, ax = new_figure((6.4, 5.6))
    t, gt = groundtruth
    _, gt_a, gt_b = break_gaps(t, gt[:, a], gt[:, b])
    ax.plot(gt_a, gt_b, color="0.3", lw=1.2, ls="--", label="groundtruth")
    for name, errors in runs:
        t, est = estimate(errors)
        _, est_a, est_b = break_gaps(t, est[:, a], est[:, b])
        ax.plot(est_a, est_b, lw=1.0, label=name)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("%s [m]" % AXIS_NAMES[a])
    ax.set_ylabel("%s [m]" % AXIS_NAMES[b])
    ax.set_title("Trajectories (%s plane)%s" % (plane, title))
    ax.legend(loc="best", framealpha=0.9)
    save(fig, request["out"], "trajectories_" + plane, request)


def plot_xyz(runs, groundtruth, title, request):
    fig, axes = new_figure((7.0, 6.6), rows=3, sharex=True)
    t_gt, gt = groundtruth
    start = t_gt[0]
    for k, ax in enumerate(axes):
        t, x = break_gaps(t_gt - start, gt[:, k])
        ax.plot(t, x, color="0.3", lw=1.2, ls="--", label="groundtruth")
        for name, errors in runs:
            t_est, est = estimate(errors)
            t, x = break_gaps(t_est - start, est[:, k])
            ax.plot(t, x, lw=1.0, label=name)
        ax.set_ylabel("%s [m]" % AXIS_NAMES[k])
    axes[-1].set_xlabel("time since the first matched pose [s]")
    axes[0].set_title("Position over time%s" % title)
    # Beside the panels, not over a curve: the tight crop keeps it in the file.
    axes[0].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), framealpha=0.9)
    save(fig, request["out"], "trajectories_xyz", request)


def plot_trajectories(request):
    """Request: runs (list of [name, folder]), out, title (optional), planes (list), formats,
    dpi."""
    for plane in request.get("planes", ["xy"]):
        if plane not in PLANE_AXES:
            raise ValueError("unknown plane '%s' (use xy, xz or yz)" % plane)
    runs, sequence = read_runs(request)
    groundtruth = groundtruth_track(runs)
    title = request.get("title") or sequence
    title = " on " + title if title else ""
    for plane in request.get("planes", ["xy"]):
        plot_plane(runs, groundtruth, plane, title, request)
    plot_xyz(runs, groundtruth, title, request)
