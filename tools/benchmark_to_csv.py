#!/usr/bin/env python3
"""Flattens a Google Benchmark JSON file (--benchmark_out_format=json) into CSV: one row per
benchmark run, the standard columns then every user counter that appears in any run (empty
where a run lacks it). Google Benchmark's own CSV reporter aborts in that case.

Usage: benchmark_to_csv.py IN.json OUT.csv
"""
import csv
import json
import os
import sys

STANDARD = ["name", "run_name", "iterations", "real_time", "cpu_time", "time_unit",
            "error_occurred", "error_message"]


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    with open(argv[1]) as f:
        runs = json.load(f).get("benchmarks", [])
    counters = []
    for run in runs:
        for key in run:
            if key not in STANDARD and key not in counters and isinstance(run[key], (int, float)) \
                    and key not in ("family_index", "per_family_instance_index", "repetitions",
                                    "repetition_index", "threads"):
                counters.append(key)
    temporary = argv[2] + ".tmp"
    with open(temporary, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(STANDARD + counters)
        for run in runs:
            writer.writerow([run.get(k, "") for k in STANDARD + counters])
    os.replace(temporary, argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
