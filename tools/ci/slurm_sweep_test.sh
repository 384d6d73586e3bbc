#!/usr/bin/env bash
# The Slurm executor end to end on a real single-node Slurm (start_slurm.sh, as root): a small
# sweep run by the local executor and by a Slurm job array gives the same merged CSV point by
# point (every column but the timings); two results removed, the merge lists them as missing
# and the resubmission runs exactly their shards. Prints `sinfo` and the array job's record.
# Usage: tools/ci/slurm_sweep_test.sh BUILD_DIR (default build/tests)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
program="$(cd "${1:-build/tests}" && pwd)/bin/impactbench"
work="$(mktemp -d /tmp/impactbench_slurm.XXXXXX)"
cleanup() {
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
echo "slurm_sweep_test: passed"
