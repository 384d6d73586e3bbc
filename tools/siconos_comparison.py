#!/usr/bin/env python3
"""Runs bench/siconos_bench (built only when Siconos Numerics is installed) and writes one CSV
row per problem and solver pair, ours beside Siconos':

  solver, siconos_solver, problem, contacts,
  ours_iterations, ours_residual, ours_converged, ours_seconds,
  siconos_iterations, siconos_residual, siconos_own_error, siconos_converged, siconos_seconds,
  siconos_tolerance (calibrated, see bench/siconos_bench.cpp),
  time_ratio (ours / Siconos, CPU time per solve), solution_difference

time_ratio is left empty unless the pair matches: both converged (our measure ≤ tolerance),
or both stopped at the same iteration limit (then it compares the cost of equal sweeps).

Both residuals are OUR measure on each code's solution (natural map for LCP, the FCLIB measure
for friction contact); siconos_own_error is the error Siconos reported. OpenBLAS is limited to
one thread so that Siconos' BLAS calls use one core like our code.

Usage: siconos_comparison.py OUT.csv [--binary build/release/libexec/impactbench/siconos_bench]
                             [--filter REGEX]   (a --benchmark_filter, e.g. 'siconos/nsgs/.*')
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

COUNTERS = ["contacts", "ours_iterations", "ours_residual", "ours_converged", "ours_seconds",
            "siconos_iterations", "siconos_residual", "siconos_own_error", "siconos_converged",
            "siconos_seconds", "siconos_tolerance", "time_ratio", "solution_difference"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out")
    parser.add_argument("--binary", default="build/release/libexec/impactbench/siconos_bench")
    parser.add_argument("--filter", default="")
    args = parser.parse_args()
    if not os.path.exists(args.binary):
        sys.exit(f"{args.binary} does not exist: install libsiconos-numerics-dev and rebuild "
                 "(cmake --build --preset release --target siconos_bench)")
    environment = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    with tempfile.TemporaryDirectory() as folder:
        raw = os.path.join(folder, "siconos.json")
        command = [args.binary, f"--benchmark_out={raw}", "--benchmark_out_format=json"]
        if args.filter:
            command.append(f"--benchmark_filter={args.filter}")
        subprocess.run(command, check=True, env=environment)
        with open(raw) as f:
            runs = json.load(f).get("benchmarks", [])
    temporary = args.out + ".tmp"
    with open(temporary, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["solver", "siconos_solver", "problem"] + COUNTERS)
        for run in runs:
            # siconos/<our solver>/<problem...>[/iterations:1]
            name = re.sub(r"/iterations:\d+$", "", run["name"])
            _, solver, problem = name.split("/", 2)
            row = [solver, run.get("label", ""), problem]
            matched = (run.get("ours_converged") == 1 and run.get("siconos_converged") == 1) or (
                run.get("ours_converged") == 0 and run.get("siconos_converged") == 0
                and run.get("ours_iterations") == run.get("siconos_iterations"))
            for key in COUNTERS:
                value = run.get(key, "")
                if key == "time_ratio" and not matched:
                    value = ""
                if key in ("contacts", "ours_iterations", "siconos_iterations",
                           "ours_converged", "siconos_converged") and value != "":
                    value = int(value)
                row.append(value)
            writer.writerow(row)
    os.replace(temporary, args.out)


if __name__ == "__main__":
    main()
