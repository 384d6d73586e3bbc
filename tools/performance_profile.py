#!/usr/bin/python3
"""Dolan–Moré performance profile of the friction solvers from a Google Benchmark output.

Reads the CSV (--benchmark_out_format=csv) or JSON written by bench/friction_bench or
bench/fclib_bench. Benchmark names are <family>/<solver>/<problem...>[/iterations:N]; each
distinct <family>/<problem...> is one problem. The cost of a solver on a problem is its CPU
time when it converged (counter converged = 1) and infinite otherwise. With r_ps = t_ps / min_s t_ps the profile is
    rho_s(tau) = |{p : r_ps <= tau}| / |problems|,
the fraction of problems a solver solves within a factor tau of the best one (Dolan & Moré,
Math. Program. 91, 2002). Problems no solver converged on are counted in the denominator.

Usage: performance_profile.py RESULTS.csv|RESULTS.json OUT.png [--title TEXT]
"""
import argparse
import csv
import io
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)


def read_rows(path):
    """Benchmark rows as dicts with name, cpu_time, time_unit and the counters."""
    with open(path, encoding="utf-8") as handle:
        text = handle.read()
    if text.lstrip().startswith("{"):
        return json.loads(text).get("benchmarks", [])
    start = text.find("name,")
    if start < 0:
        raise ValueError(f"{path}: no CSV header starting with 'name,'")
    return list(csv.DictReader(io.StringIO(text[start:])))


def seconds(row):
    """CPU time of the single timed solve (the benchmarks run one iteration each)."""
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[row.get("time_unit", "ns")]
    return float(row["cpu_time"]) * scale


def split_name(name):
    parts = [p for p in name.split("/") if not p.startswith("iterations:")]
    if len(parts) < 3:
        raise ValueError(f"benchmark name '{name}' is not <family>/<solver>/<problem>")
    return parts[1], "/".join([parts[0]] + parts[2:])


def costs_by_problem(rows):
    costs = {}
    solvers = []
    for row in rows:
        if str(row.get("error_occurred", "")).lower() == "true":
            continue
        solver, problem = split_name(row["name"])
        if solver not in solvers:
            solvers.append(solver)
        converged = float(row.get("converged") or 0.0) >= 0.5
        costs.setdefault(problem, {})[solver] = seconds(row) if converged else math.inf
    return costs, solvers


def profile(costs, solvers):
    """Per solver, the sorted performance ratios (inf for failures) over all problems."""
    ratios = {s: [] for s in solvers}
    for by_solver in costs.values():
        best = min(by_solver.values(), default=math.inf)
        for solver in solvers:
            cost = by_solver.get(solver, math.inf)
            ratios[solver].append(cost / best if math.isfinite(best) and best > 0 else math.inf)
    return {s: sorted(r) for s, r in ratios.items()}


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results")
    parser.add_argument("output")
    parser.add_argument("--title", default="Performance profile (solve time, converged to tol)")
    args = parser.parse_args(argv)
    try:
        costs, solvers = costs_by_problem(read_rows(args.results))
    except (OSError, ValueError, KeyError) as error:
        print(f"performance_profile: {error}", file=sys.stderr)
        return 1
    if not costs:
        print(f"performance_profile: {args.results} holds no benchmark rows", file=sys.stderr)
        return 1
    ratios = profile(costs, solvers)
    finite = [r for rs in ratios.values() for r in rs if math.isfinite(r)]
    tau_max = max(2.0, max(finite, default=2.0) * 1.5)
    figure, axes = plt.subplots(figsize=(7, 4.5))
    count = len(costs)
    for solver in solvers:
        taus = [1.0] + [r for r in ratios[solver] if math.isfinite(r)] + [tau_max]
        fractions = [0.0] + [(k + 1) / count for k in range(len(taus) - 2)]
        fractions.append(fractions[-1])
        axes.step(taus, fractions, where="post", label=solver)
        solved = sum(math.isfinite(r) for r in ratios[solver])
        best = sum(r == 1.0 for r in ratios[solver])
        print(f"{solver:12s} solved {solved}/{count}, fastest on {best}")
    axes.set_xscale("log", base=2)
    axes.set_xlim(1.0, tau_max)
    axes.set_ylim(0.0, 1.02)
    axes.set_xlabel("tau (time ratio to the fastest solver)")
    axes.set_ylabel("fraction of problems solved within tau")
    axes.set_title(args.title)
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(loc="lower right")
    figure.tight_layout()
    figure.savefig(args.output, dpi=120)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
