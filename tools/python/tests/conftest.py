"""Shared helpers: the built program (IMPACTBENCH_CLI, set by ctest) run on the same input as
the module, and the repository's test data (IMPACTBENCH_TEST_DATA_DIR)."""

import csv
import os
import subprocess
from pathlib import Path

import pytest

CLI = os.environ.get("IMPACTBENCH_CLI", "")
DATA = Path(os.environ.get("IMPACTBENCH_TEST_DATA_DIR", Path(__file__).parents[3] / "tests/data"))


def run_cli(*args, check=True):
    """(exit code, stdout, stderr) of the program with these arguments."""
    if not CLI:
        pytest.skip("IMPACTBENCH_CLI is not set (ctest sets it to the built program)")
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True,
                          env={**os.environ, "OPENBLAS_NUM_THREADS": "1"})
    if check and done.returncode != 0:
        raise AssertionError(f"impactbench {' '.join(map(str, args))}: exit "
                             f"{done.returncode}: {done.stderr}")
    return done.returncode, done.stdout, done.stderr


def cli_message(*args):
    """(exit code, message) of a refusal: the stderr line without the "impactbench: " prefix
    and the " (see --help)" a usage error of the command line adds."""
    code, _, err = run_cli(*args, check=False)
    assert code != 0, f"the program accepted {args}"
    line = err.strip().splitlines()[-1]
    assert line.startswith("impactbench: ")
    line = line[len("impactbench: "):]
    if line.endswith(" (see --help)"):
        line = line[:-len(" (see --help)")]
    return code, line


def read_csv(path):
    """Header and rows of a CSV the program wrote, as text (parsed by the test)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]
