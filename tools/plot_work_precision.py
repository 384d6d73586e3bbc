#!/usr/bin/env python3
"""Work-precision diagram: error against the engine's CPU time (process CPU time of its stepping,
our recording excluded) for each engine's sweep of step sizes or tolerances.

Usage: plot_work_precision.py CSV PNG TITLE
CSV columns: engine,setting,value,error,engine_cpu_seconds,failure (one row per run; rows with
a failure have no error and are not plotted). Run with the interpreter
that has Debian's python3-matplotlib (/usr/bin/python3).
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_style import marker_formats  # noqa: E402



def main(argv):
    if len(argv) != 4:
        sys.stderr.write(__doc__)
        return 2
    series = defaultdict(list)
    with open(argv[1], newline="") as f:
        for row in csv.DictReader(f):
            if row["failure"]:
                continue
            err, cpu = float(row["error"]), float(row["engine_cpu_seconds"])
            if err > 0 and cpu > 0:
                series[row["engine"]].append((cpu, err, row["setting"], row["value"]))
    if not series:
        sys.stderr.write(f"plot_work_precision: no usable rows in {argv[1]}\n")
        return 1
    fig, ax = plt.subplots(figsize=(7, 5))
    formats = marker_formats(series)
    for engine, points in sorted(series.items()):
        points.sort()
        ax.loglog([p[0] for p in points], [p[1] for p in points], formats[engine],
                  label=f"{engine} ({points[0][2]})")
        for cpu, err, _, value in points:
            ax.annotate(f"{float(value):.3g}", (cpu, err), fontsize=7, alpha=0.7)
    ax.set_xlabel("engine CPU time [s]")
    ax.set_ylabel("error")
    ax.set_title(argv[3])
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
