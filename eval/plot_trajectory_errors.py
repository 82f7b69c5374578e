"""Plots of one evaluated run, drawn from the files `slamkit eval ate|rpe` wrote.

  ate: ate_over_time  - absolute translational error over time with RMSE / mean / median
                        lines and a mean +- std band;
       trajectory_PL  - the trajectory in plane PL (xy, xz, yz): groundtruth, the aligned
                        estimate coloured by its error, and the difference segments between
                        matched poses (as evaluate_ate.py --plot draws them).
  rpe: rpe_over_time  - translational and rotational relative error over time.
Each is written as PNG and SVG, or in the request's "formats" (plot_style.save).
"""
import json

import numpy as np
from matplotlib.collections import LineCollection

from plot_style import new_figure, save

PLANE_AXES = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}


def read_csv(path):
    data = np.genfromtxt(path, delimiter=",", names=True)
    return np.atleast_1d(data)


def break_gaps(t, *series):
    """Copies with NaN inserted where the time step exceeds 5x the median step, so lines
    do not bridge stretches without data (e.g. where groundtruth is missing)."""
    if len(t) < 3:
        return (t,) + series
    dt = np.diff(t)
    gaps = np.nonzero(dt > 5 * np.median(dt))[0] + 1
    return tuple(np.insert(np.asarray(x, dtype=float), gaps, np.nan) for x in (t,) + series)


def finish_axes(ax, t, values):
    """Time limits, a zero baseline and headroom for the legend above the data."""
    ax.set_xlim(t[0], t[-1])
    ax.set_ylim(0, 1.4 * np.nanmax(values))
    ax.legend(loc="upper center", ncol=3, framealpha=0.9, columnspacing=1.2)


def stat_lines(ax, stats, unit):
    """Horizontal RMSE / mean / median lines and the mean +- std band."""
    mean, std = stats["mean"], stats["std"]
    ax.axhspan(mean - std, mean + std, color="tab:blue", alpha=0.12,
               label="mean ± std (std %.4f %s)" % (std, unit))
    ax.axhline(stats["rmse"], color="tab:red", lw=1.2,
               label="RMSE %.4f %s" % (stats["rmse"], unit))
    ax.axhline(mean, color="tab:blue", lw=1.2, ls="--", label="mean %.4f %s" % (mean, unit))
    ax.axhline(stats["median"], color="tab:green", lw=1.2, ls=":",
               label="median %.4f %s" % (stats["median"], unit))


def plot_ate_over_time(errors, metrics, request):
    ate = metrics["ate"]
    t, err = break_gaps(errors["time"] - errors["time"][0], errors["ate_m"])
    fig, ax = new_figure((7.0, 3.8))
    ax.plot(t, err, color="0.25", lw=0.8, label="error per pose")
    stat_lines(ax, ate, "m")
    ax.set_xlabel("time since first matched pose [s]")
    ax.set_ylabel("absolute translational error [m]")
    finish_axes(ax, t, err)
    ax.set_title("Absolute trajectory error: %s on %s\n(%d pose pairs, %s alignment)"
                 % (request["system_name"], request["title"], ate["pairs"],
                    ate["alignment"]["method"]))
    save(fig, request["out"], "ate_over_time", request)


def plot_trajectory(errors, metrics, plane, request):
    a, b = PLANE_AXES[plane]
    names = ("x", "y", "z")
    est = np.stack([errors["est_tx"], errors["est_ty"], errors["est_tz"]], axis=1)
    gt = np.stack([errors["gt_tx"], errors["gt_ty"], errors["gt_tz"]], axis=1)
    fig, ax = new_figure((6.4, 5.6))
    # Difference segments between matched poses, below everything else.
    segments = np.stack([est[:, [a, b]], gt[:, [a, b]]], axis=1)
    ax.add_collection(LineCollection(segments, colors="tab:red", linewidths=0.6, alpha=0.6,
                                     label="difference", zorder=1))
    _, gt_a, gt_b = break_gaps(errors["time"], gt[:, a], gt[:, b])
    ax.plot(gt_a, gt_b, color="black", lw=1.0, label="groundtruth", zorder=2)
    sc = ax.scatter(est[:, a], est[:, b], c=errors["ate_m"], cmap="viridis", s=4, zorder=3,
                    label="%s (aligned)" % request["system_name"])
    cbar = fig.colorbar(sc, ax=ax, shrink=0.85, pad=0.02)
    cbar.set_label("absolute translational error [m]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("%s [m]" % names[a])
    ax.set_ylabel("%s [m]" % names[b])
    ax.set_title("Trajectory (%s plane): %s on %s\nATE RMSE %.4f m over %d pairs"
                 % (plane, request["system_name"], request["title"], metrics["ate"]["rmse"],
                    metrics["ate"]["pairs"]))
    ax.legend(loc="best", markerscale=3, framealpha=0.9)
    save(fig, request["out"], "trajectory_" + plane, request)


def plot_rpe_over_time(pairs, metrics, request):
    rpe = metrics["rpe"]
    t, trans, rot = break_gaps(pairs["time_i"] - pairs["time_i"][0], pairs["trans_m"],
                               pairs["rot_deg"])
    fig, (ax_t, ax_r) = new_figure((7.0, 6.0), rows=2, sharex=True)
    ax_t.plot(t, trans, color="0.25", lw=0.8, label="error per pair")
    stat_lines(ax_t, rpe["trans"], "m")
    ax_t.set_ylabel("translational error [m]")
    finish_axes(ax_t, t, trans)
    ax_r.plot(t, rot, color="0.25", lw=0.8, label="error per pair")
    stat_lines(ax_r, rpe["rot_deg"], "deg")
    ax_r.set_ylabel("rotational error [deg]")
    ax_r.set_xlabel("time of the first pose of the pair [s]")
    finish_axes(ax_r, t, rot)
    unit = {"s": "s", "f": "frames", "m": "m", "deg": "deg", "rad": "rad"}[rpe["unit"]]
    ax_t.set_title("Relative pose error over %g %s: %s on %s\n(%d pose pairs, %s convention)"
                   % (rpe["delta"], unit, request["system_name"], request["title"],
                      rpe["pairs"], rpe["convention"]))
    save(fig, request["out"], "rpe_over_time", request)


def read_inputs(request):
    with open(request["metrics"]) as f:
        metrics = json.load(f)
    return read_csv(request["csv"]), metrics


def plot_ate(request):
    """Request: metrics, csv (errors.csv), out, title, system_name, planes (list), formats,
    dpi."""
    errors, metrics = read_inputs(request)
    plot_ate_over_time(errors, metrics, request)
    for plane in request.get("planes", ["xy"]):
        if plane not in PLANE_AXES:
            raise ValueError("unknown plane '%s' (use xy, xz or yz)" % plane)
        plot_trajectory(errors, metrics, plane, request)


def plot_rpe(request):
    """Request: metrics, csv (rpe.csv), out, title, system_name, formats, dpi."""
    pairs, metrics = read_inputs(request)
    plot_rpe_over_time(pairs, metrics, request)
