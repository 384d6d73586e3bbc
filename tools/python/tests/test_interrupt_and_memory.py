"""Ctrl-C stops a long run or comparison within a second; 1,000 short runs and 1,000 solves
leave resident memory steady."""

import os
import signal
import subprocess
import sys
import time

import pytest

import impactbench
from conftest import DATA

# Calls of 1e10 steps (hours); a comparison must stop as a whole, not go on to its next engine.
LONG_CALLS = {
    "run": 'impactbench.run("bouncing_ball", engine="moreau", dt=1e-6, duration=1e4, '
           'sample_dt=1.0)',
    "compare": 'impactbench.compare("bouncing_ball", engines=["moreau", "box2d"], dt=1e-6, '
               'duration=1e4, as_frame=False)',
}


@pytest.mark.parametrize("call", sorted(LONG_CALLS))
def test_ctrl_c_interrupts_a_long_call_within_a_second(call):
    script = f"import impactbench\nprint('started', flush=True)\n{LONG_CALLS[call]}\n"
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(0.5)  # inside the call
        assert child.poll() is None
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        _, err = child.communicate(timeout=10)
        elapsed = time.monotonic() - sent
    finally:
        child.kill()
    assert "KeyboardInterrupt" in err
    assert child.returncode != 0
    # The poll runs every 0.1 s; a second leaves room for a loaded machine.
    assert elapsed < 1.0, elapsed


def resident_kib():
    with open("/proc/self/status") as f:
        return next(int(line.split()[1]) for line in f if line.startswith("VmRSS:"))


def resident_growth_kib(call):
    """Resident memory gained over 1,000 calls, after 100 calls of warm-up (allocator pools,
    caches, lazily loaded code)."""
    for _ in range(100):
        call()
    before = resident_kib()
    for _ in range(1000):
        call()
    return resident_kib() - before


def test_a_thousand_runs_do_not_grow_resident_memory():
    def short_run():
        result = impactbench.run("bouncing_ball", engine="moreau", duration=0.05)
        assert result.t.size > 0

    grown = resident_growth_kib(short_run)
    # One run keeps about 51 rows × 8 columns of doubles (3 KiB) plus events and summary; a
    # leak of any of them per run would add > 3 MiB over 1,000 runs. 1 MiB is allocator noise.
    assert grown < 1024, f"resident memory grew by {grown} KiB over 1,000 runs"


def test_a_thousand_solves_do_not_grow_resident_memory():
    # The result's arrays take over the solver's vectors: each array's capsule must free its
    # vector when the array goes.
    problem = impactbench.read_fclib(DATA / "fclib" / "Capsules-i125-1213.hdf5")

    def short_solve():
        result = impactbench.solve_friction(problem["W"], problem["q"], problem["mu"], "nsgs",
                                            max_iter=1)
        assert result.solution.size == result.velocity.size == problem["q"].size == 858

    grown = resident_growth_kib(short_solve)
    # Each solve returns two vectors of 858 doubles (13.4 KiB); a leak of either would add
    # > 6 MiB over 1,000 solves.
    assert grown < 1024, f"resident memory grew by {grown} KiB over 1,000 solves"
