#!/usr/bin/env python3
"""Plots a sensitivity prediction: the nominal trajectory, a perturbed re-simulation and the
first-order prediction alpha + eps z, for chosen state columns, plus the prediction error
|perturbed - predicted| on a log scale (large only between a nominal and a perturbed event).

Usage: plot_sensitivity.py PREDICTION_CSV OUT_PNG [COLUMN ...]
PREDICTION_CSV is the file written by impactbench::sensitivity::write_prediction_csv_file
(columns t, nominal.<name>..., perturbed.<name>..., predicted.<name>...). COLUMN names a state
(e.g. box.y); default: every state. Run with /usr/bin/python3 (Debian's python3-matplotlib).
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (backend must be chosen first)

STYLE = {
    "nominal": dict(color="black", linewidth=1.2, linestyle="-"),
    "perturbed": dict(color="tab:blue", linewidth=2.4, linestyle="-", alpha=0.5),
    "predicted": dict(color="tab:red", linewidth=1.2, linestyle="--"),
}


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or rows[0][0] != "t":
        raise SystemExit(f"plot_sensitivity: {path} is not a prediction CSV (no 't' column)")
    header, data = rows[0], rows[1:]
    return {name: [float(r[i]) for r in data] for i, name in enumerate(header)}


def main(argv):
    if len(argv) < 3:
        raise SystemExit(__doc__)
    columns = read_columns(argv[1])
    states = [c[len("nominal."):] for c in columns if c.startswith("nominal.")]
    chosen = argv[3:] or states
    unknown = [c for c in chosen if c not in states]
    if unknown:
        raise SystemExit(f"plot_sensitivity: unknown column(s) {unknown}; states: {states}")
    t = columns["t"]
    fig, axes = plt.subplots(len(chosen), 2, figsize=(11, 2.4 * len(chosen)), squeeze=False,
                             sharex=True)
    for row, name in enumerate(chosen):
        ax = axes[row][0]
        for kind, style in STYLE.items():
            ax.plot(t, columns[f"{kind}.{name}"], label=kind, **style)
        ax.set_ylabel(name)
        err = axes[row][1]
        error = [abs(p - q) for p, q in zip(columns[f"perturbed.{name}"],
                                              columns[f"predicted.{name}"])]
        floor = 1e-17
        err.semilogy(t, [max(e, floor) for e in error], color="tab:red", linewidth=1.0)
        err.set_ylabel(f"|error| {name}")
        if row == 0:
            ax.legend(loc="best", fontsize="small")
            ax.set_title("nominal, perturbed, first-order prediction")
            err.set_title("|perturbed - predicted|")
        if not all(math.isfinite(e) for e in error):
            raise SystemExit(f"plot_sensitivity: non-finite values in column {name}")
    for ax in axes[-1]:
        ax.set_xlabel("t [s]")
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)


if __name__ == "__main__":
    main(sys.argv)
