#!/usr/bin/env bash
# The Slurm executor end to end on a real single-node Slurm (start_slurm.sh, as root): a small
# sweep run by the local executor and by a Slurm job array gives the same merged CSV point by
# point (every column but the timings); two results removed, the merge lists them as missing
# and the resubmission runs exactly their shards; a task that Slurm ends at its time limit
# leaves its point listed by the merge, and the resubmission reruns exactly that point. Prints
# `sinfo` and the array jobs' records.
# Usage: tools/ci/slurm_sweep_test.sh BUILD_DIR (default build/tests)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
program="$(cd "${1:-build/tests}" && pwd)/bin/impactbench"
work="$(mktemp -d /tmp/impactbench_slurm.XXXXXX)"
cleanup() {
  local status=$?
  if [ "$status" != 0 ]; then  # the array tasks' own output, which says why a point is missing
    for log in "$work"/*/slurm/task-*.log "$work"/*/logs/*.log; do
      [ -e "$log" ] && { echo "--- $log"; cat "$log"; }
    done
  fi
  bash "$here/stop_slurm.sh"
  rm -rf "$work"
}
trap cleanup EXIT
bash "$here/start_slurm.sh"
cat > "$work/spec.toml" <<'SPEC'
scenarios = ["bouncing_ball", "sliding_block"]
engines = ["moreau", "event"]
duration = 0.5
[grid]
dt = [1e-3, 2e-3]
[slurm]
shards = 3
concurrency = 2
time = "2"
mem = "500M"
SPEC
"$program" sweep "$work/spec.toml" --out "$work/local" --jobs 2 --merge
"$program" sweep "$work/spec.toml" --out "$work/slurm" --executor slurm --wait | tee "$work/submit.txt"
job="$(sed -n 's/^sweep: slurm job \([0-9]*\).*/\1/p' "$work/submit.txt")"
[ -n "$job" ] || { echo "slurm_sweep_test: no job id" >&2; exit 1; }
echo "--- sinfo"
sinfo
echo "--- the array job's record"
scontrol show job "$job" || true
sacct -j "$job" 2>/dev/null || echo "(sacct: no accounting on this single-node Slurm)"

# Point by point: the same rows, equal in every column but the timings.
compare_csv() {
  python3 - "$1" "$2" <<'PY'
import csv, sys
def rows(path):
    with open(path, newline="") as f:
        return {row["id"]: row for row in csv.DictReader(f)}
a, b = rows(sys.argv[1]), rows(sys.argv[2])
if set(a) != set(b):
    sys.exit(f"different points: {sorted(set(a) ^ set(b))}")
checked = 0
for point, row in a.items():
    for column, value in row.items():
        if column.endswith("_seconds"):
            continue
        if b[point][column] != value:
            sys.exit(f"point {point}, {column}: {value} (local) != {b[point][column]} (slurm)")
        checked += 1
print(f"slurm_sweep_test: {len(a)} points, {checked} fields equal (timings apart)")
PY
}
compare_csv "$work/local/sweep.csv" "$work/slurm/sweep.csv"

# Two points lost (as by a failed array task): listed by the merge, rerun alone on resubmission.
ls "$work/slurm/points" | head -2 | while read -r file; do rm "$work/slurm/points/$file"; done
if "$program" merge "$work/spec.toml" --out "$work/slurm" 2> "$work/merge.txt"; then
  echo "slurm_sweep_test: the merge did not report the missing points" >&2
  exit 1
fi
grep -q "^sweep: 2 points have no result:" "$work/merge.txt"
"$program" sweep "$work/spec.toml" --out "$work/slurm" --executor slurm --wait | tee "$work/again.txt"
grep -q "^sweep: submitting 2 points in" "$work/again.txt"
compare_csv "$work/local/sweep.csv" "$work/slurm/sweep.csv"

# A real failed array task: one point (ODE's pivoting step on the pyramid, about a second per
# step, 300 steps) outlasts its task's 1-minute limit and Slurm ends the task. The merge lists
# exactly that point; the resubmission, with a 5 s limit per point, runs exactly its shard and
# records the point as a timeout, while the other point's result is kept.
cat > "$work/slow.toml" <<'SPEC'
scenarios = ["box_pyramid"]
engines = ["ode"]
duration = 0.3
[grid]
option."ode.stepper" = ["quick", "exact"]
[slurm]
shards = 2
time = "1"
SPEC
if "$program" sweep "$work/slow.toml" --out "$work/slow" --executor slurm --wait \
    > "$work/slow.txt" 2> "$work/slow.err"; then
  echo "slurm_sweep_test: a sweep whose task passed its time limit reported success" >&2
  exit 1
fi
cat "$work/slow.txt" "$work/slow.err"
slow_job="$(sed -n 's/^sweep: slurm job \([0-9]*\).*/\1/p' "$work/slow.txt")"
echo "--- the array job with the timed-out task"
scontrol show job "$slow_job" | grep -E "JobId=|JobState=|TimeLimit=|ExitCode="
scontrol show job "$slow_job" | grep -q "JobState=TIMEOUT" || {
  echo "slurm_sweep_test: no task of job $slow_job ended at its time limit" >&2
  exit 1
}
grep -q "^sweep: 1 points have no result:" "$work/slow.err"
missing="$(sed -n 's/^  \([0-9a-f]\{16\}\)  .*/\1/p' "$work/slow.err")"
"$program" sweep "$work/slow.toml" --out "$work/slow" --executor slurm --wait --time-limit 5 \
  | tee "$work/slow_again.txt"
grep -q "^sweep: submitting 1 points in 1 of 2 array tasks" "$work/slow_again.txt"
python3 - "$work/slow/sweep.csv" "$missing" <<'PY'
import csv, sys
rows = {row["options"]: row for row in csv.DictReader(open(sys.argv[1], newline=""))}
exact, quick = rows["stepper=exact"], rows["stepper=quick"]
if exact["id"] != sys.argv[2]:
    sys.exit(f"the merge listed {sys.argv[2]} as missing, not the timed-out point {exact['id']}")
if (exact["status"], quick["status"]) != ("timeout", "ok"):
    sys.exit(f"statuses {exact['status']} (exact) and {quick['status']} (quick), "
             "expected timeout and ok")
print(f"slurm_sweep_test: the timed-out task's point {exact['id']} rerun alone: "
      f"{exact['status']} ({exact['reason']}); the other point kept: {quick['status']}")
PY
echo "slurm_sweep_test: passed"
