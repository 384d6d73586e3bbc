#!/usr/bin/env python3
"""Plots of `impactbench validate`'s outputs (docs/real-tosses.md), written beside them:

  error_over_time.png      position and rotation error against time since the run's start:
                           median over tosses (line) and 90th percentile (dashed), per engine
  error_distribution.png   the per-toss mean position and rotation errors over tosses, as
                           empirical cumulative distributions, per engine
  toss_trajectory.png      one toss: the recorded centre (x, y, z) and the cube's turn from
                           its first recorded orientation, with every engine's run over it

Usage: plot_validation.py DIR   (DIR holds per_toss.csv, error_over_time.csv and
toss_trajectory.csv). Run with the interpreter that has Debian's python3-matplotlib
(/usr/bin/python3).
"""
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_style import line_styles  # noqa: E402

# The recording: drawn over the engines, in a style no engine takes.
DATA_STYLE = dict(color="black", linewidth=1.8, linestyle="-", marker=".", markersize=3)


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def plot_error_over_time(rows, png):
    series = defaultdict(list)
    for row in rows:
        series[row["engine"]].append(row)
    styles = line_styles(series)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, metric, label in ((axes[0], "position", "position error [cube sides]"),
                              (axes[1], "rotation", "rotation error [rad]")):
        for engine, points in sorted(series.items()):
            t = [float(p["time_s"]) + 0.5 * float(p["bin_width_s"]) for p in points]
            style = dict(styles[engine])
            ax.plot(t, [float(p[metric + "_median"]) for p in points],
                    **dict(style, linestyle="-"), label=f"{engine} median")
            ax.plot(t, [float(p[metric + "_p90"]) for p in points],
                    **dict(style, linestyle="--", linewidth=0.9), label=f"{engine} p90")
        ax.set_xlabel("time since the run's start [s]")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7, ncol=2)
    fig.suptitle("Error against time, over tosses")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def plot_distribution(rows, png):
    values = defaultdict(lambda: defaultdict(list))
    for row in rows:
        if row["status"] == "scored":
            for metric in ("position", "rotation"):
                values[row["engine"]][metric].append(float(row[metric]))
    styles = line_styles(values)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, metric, label in ((axes[0], "position", "mean position error [cube sides]"),
                              (axes[1], "rotation", "mean rotation error [rad]")):
        for engine, by_metric in sorted(values.items()):
            xs = sorted(by_metric[metric])
            ys = [(i + 1) / len(xs) for i in range(len(xs))]
            ax.step(xs, ys, where="post", **styles[engine], label=f"{engine} ({len(xs)} tosses)")
        ax.set_xlabel(label)
        ax.set_ylabel("fraction of scored tosses at or below")
        ax.set_ylim(0, 1)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("Per-toss errors over tosses (failed runs are not in the curves)")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def turn_from(q0, q):
    """Angle of the rotation from orientation q0 to q (unit quaternions, w first) [rad]."""
    dot = abs(sum(a * b for a, b in zip(q0, q)))
    return 2.0 * math.acos(min(1.0, dot))


def plot_trajectory(rows, png):
    runs = defaultdict(list)
    for row in rows:
        runs[row["source"]].append(row)
    data = runs.pop("data")
    toss = data[0]["toss"]
    q0 = [float(data[0][k]) for k in ("qw", "qx", "qy", "qz")]
    styles = line_styles(runs)
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    panels = [("x", "x [m]"), ("y", "y [m]"), ("z", "z [m]"),
              (None, "turn from the first pose [rad]")]
    for ax, (column, label) in zip(axes.flat, panels):
        for source, points in [("data", data)] + sorted(runs.items()):
            t = [float(p["t"]) for p in points]
            if column:
                y = [float(p[column]) for p in points]
            else:
                y = [turn_from(q0, [float(p[k]) for k in ("qw", "qx", "qy", "qz")]) for p in points]
            style = DATA_STYLE if source == "data" else styles[source]
            ax.plot(t, y, **style, label="recording" if source == "data" else source)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("time since the toss's first sample [s]")
    axes[0][0].legend(fontsize=8)
    fig.suptitle(f"{toss}: the recording and each engine's run from its first sample")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    out = argv[1]
    try:
        per_toss = read_rows(os.path.join(out, "per_toss.csv"))
        over_time = read_rows(os.path.join(out, "error_over_time.csv"))
        trajectory = read_rows(os.path.join(out, "toss_trajectory.csv"))
    except (OSError, csv.Error) as error:
        sys.stderr.write(f"plot_validation: {error}\n")
        return 1
    if not any(row["source"] == "data" for row in trajectory):
        sys.stderr.write(f"plot_validation: {out}/toss_trajectory.csv has no recorded toss\n")
        return 1
    plot_error_over_time(over_time, os.path.join(out, "error_over_time.png"))
    plot_distribution(per_toss, os.path.join(out, "error_distribution.png"))
    plot_trajectory(trajectory, os.path.join(out, "toss_trajectory.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
