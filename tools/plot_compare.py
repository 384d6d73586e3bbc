#!/usr/bin/env python3
"""Plots written by `impactbench compare`: trajectories of every engine overlaid, and each
engine's error against the reference over time.

Usage: plot_compare.py DIR SCENARIO COLUMN [COLUMN ...]
Reads DIR/<engine>_trajectory.csv and DIR/<engine>_error.csv for every engine present, writes
DIR/trajectories.png and DIR/errors.png. Run it with the interpreter that has Debian's
python3-matplotlib (/usr/bin/python3); CMake finds it for the impactbench program.
"""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (backend must be chosen first)

from plot_style import REFERENCE_STYLE, line_styles  # noqa: E402



def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: [float(r[i]) for r in body] for i, name in enumerate(header)}


def engines_in(directory, suffix):
    found = {}
    for path in sorted(glob.glob(os.path.join(directory, "*_" + suffix + ".csv"))):
        engine = os.path.basename(path)[: -len("_" + suffix + ".csv")]
        found[engine] = read_columns(path)
    return found


def main(argv):
    if len(argv) < 4:
        sys.stderr.write(__doc__)
        return 2
    directory, scenario, columns = argv[1], argv[2], argv[3:]
    trajectories = engines_in(directory, "trajectory")
    if not trajectories:
        sys.stderr.write(f"plot_compare: no *_trajectory.csv in {directory}\n")
        return 1

    # A coordinate that no engine moves (a ball's x, a sliding block's angle) is left out.
    def varies(column):
        values = [v for data in trajectories.values() for v in data.get(column, [])]
        return values and max(values) - min(values) > 1e-9
    columns = [c for c in columns if varies(c)] or columns[:1]
    # Every engine compared against the reference has an error file; the reference has none
    # and is drawn as the thick black line the others are read against.
    errors = engines_in(directory, "error")
    styles = line_styles([e for e in trajectories if e != "analytic"])
    for engine in trajectories:
        if engine == "analytic":
            styles[engine] = REFERENCE_STYLE
        elif errors and engine not in errors:
            styles[engine] = dict(color="black", linewidth=2.2, linestyle="-")
    fig, axes = plt.subplots(len(columns), 1, figsize=(9, 3.2 * len(columns)), sharex=True,
                             squeeze=False)
    for ax, column in zip(axes[:, 0], columns):
        for engine, data in trajectories.items():
            if column in data:
                ax.plot(data["t"], data[column], label=engine, **styles[engine])
        ax.set_ylabel(column)
        ax.grid(True, alpha=0.3)
    axes[0, 0].set_title(f"{scenario}: trajectories of each engine")
    axes[0, 0].legend(loc="best")
    axes[-1, 0].set_xlabel("t [s]")
    fig.tight_layout()
    fig.savefig(os.path.join(directory, "trajectories.png"), dpi=110)
    plt.close(fig)

    if errors:
        fig, ax = plt.subplots(figsize=(9, 4))
        for engine, data in errors.items():
            positive = [(t, e) for t, e in zip(data["t"], data["error"]) if e > 0]
            if positive:
                ax.semilogy(*zip(*positive), label=engine, **styles.get(engine, {}))
        ax.set_title(f"{scenario}: position error against the reference")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("‖p − p_ref‖ [m] (positions; angles in angle_error)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(loc="best")
        fig.tight_layout()
        fig.savefig(os.path.join(directory, "errors.png"), dpi=110)
        plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
