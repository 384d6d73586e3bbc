#!/usr/bin/env python3
"""Plots a sensitivity prediction: the nominal trajectory, a perturbed re-simulation and the
first-order prediction alpha + eps z, for chosen state columns, plus the prediction error
|perturbed - predicted| on a log scale (large only between a nominal and a perturbed event).

Usage: plot_sensitivity.py PREDICTION_CSV OUT_PNG [--gains GAINS_CSV] [--title TEXT]
                           [--epsilon EPS] [COLUMN ...]
PREDICTION_CSV is the file written by `impactbench sensitivity ... --prediction` (columns t,
nominal.<name>..., perturbed.<name>..., predicted.<name>...). GAINS_CSV (the --out file of the
same command) adds the nominal event times as dotted vertical lines. COLUMN names a state (e.g.
box.y); default: every state. Units follow the name's suffix (x, y: m; theta, phi: rad; vx, vy:
m/s; omega: rad/s). Run with /usr/bin/python3 (Debian's python3-matplotlib).
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (backend must be chosen first)

STYLE = {
    "nominal": dict(color="black", linewidth=1.2, linestyle="-"),
    "perturbed": dict(color="tab:blue", linewidth=2.4, linestyle="-", alpha=0.5),
    "predicted": dict(color="tab:red", linewidth=1.2, linestyle="--"),
}
LABEL = {
    "nominal": "nominal $\\alpha(t)$",
    "perturbed": "perturbed run $x_\\varepsilon(t)$",
    "predicted": "first order $\\alpha(t) + \\varepsilon z(t)$",
}
UNITS = {"x": "m", "y": "m", "theta": "rad", "phi": "rad", "vx": "m/s", "vy": "m/s",
         "omega": "rad/s"}


def unit_of(name):
    return UNITS.get(name.rsplit(".", 1)[-1], "")


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or rows[0][0] != "t":
        raise SystemExit(f"plot_sensitivity: {path} is not a prediction CSV (no 't' column)")
    header, data = rows[0], rows[1:]
    return {name: [float(r[i]) for r in data] for i, name in enumerate(header)}


def read_event_times(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames is None or "kind" not in reader.fieldnames:
            raise SystemExit(f"plot_sensitivity: {path} is not a sensitivity gains CSV")
        return sorted({float(r["t"]) for r in reader if r["kind"] == "jump_gain"})


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("prediction_csv")
    parser.add_argument("out_png")
    parser.add_argument("columns", nargs="*")
    parser.add_argument("--gains", help="gains CSV of the same run: marks the event times")
    parser.add_argument("--title", help="figure title")
    parser.add_argument("--epsilon", type=float, help="perturbation size (shown in the legend)")
    args = parser.parse_intermixed_args()

    columns = read_columns(args.prediction_csv)
    states = [c[len("nominal."):] for c in columns if c.startswith("nominal.")]
    chosen = args.columns or states
    unknown = [c for c in chosen if c not in states]
    if unknown:
        raise SystemExit(f"plot_sensitivity: unknown column(s) {unknown}; states: {states}")
    events = read_event_times(args.gains) if args.gains else []
    t = columns["t"]
    fig, axes = plt.subplots(len(chosen), 2, figsize=(11, 2.4 * len(chosen) + 0.6),
                             squeeze=False, sharex=True)
    for row, name in enumerate(chosen):
        unit = unit_of(name)
        ax = axes[row][0]
        for kind, style in STYLE.items():
            label = LABEL[kind]
            if kind != "nominal" and args.epsilon is not None:
                label += f", $\\varepsilon$ = {args.epsilon:g}"
            ax.plot(t, columns[f"{kind}.{name}"], label=label, **style)
        ax.set_ylabel(f"{name} [{unit}]" if unit else name)
        err = axes[row][1]
        error = [abs(p - q) for p, q in zip(columns[f"perturbed.{name}"],
                                              columns[f"predicted.{name}"])]
        if not all(math.isfinite(e) for e in error):
            raise SystemExit(f"plot_sensitivity: non-finite values in column {name}")
        floor = 1e-17
        err.semilogy(t, [max(e, floor) for e in error], color="tab:red", linewidth=1.0)
        err.set_ylabel(f"|error| [{unit}]" if unit else "|error|")
        for a in (ax, err):
            for te in events:
                a.axvline(te, color="grey", linestyle=":", linewidth=0.8)
        if row == 0:
            ax.legend(loc="best", fontsize="small")
            ax.set_title("trajectories" + (" (dotted: nominal events)" if events else ""))
            err.set_title("|perturbed - first-order prediction| (raw, so large only\n"
                          "between a nominal and the perturbed event)", fontsize="medium")
    for ax in axes[-1]:
        ax.set_xlabel("t [s]")
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.out_png, dpi=110)


if __name__ == "__main__":
    main()
