#!/usr/bin/env bash
# What the local sweep executor costs: N points that do almost nothing (the bouncing ball for one
# 1 ms step of Moreau–Jean, its event-driven reference for the same 1 ms) run with 1 worker and
# with 2, each into a fresh folder. Prints the wall time, the rate of each, their ratio, and
# the cost per point with 1 worker beside the engines' own CPU time per point (from the merged
# CSV): the rest is what the sweep adds (process start, scenario load, the point's compare,
# its result file).
# Usage: bench/sweep_overhead.sh [BUILD_DIR (default build/release)] [POINTS (default 200)]
set -euo pipefail
program="$(cd "${1:-build/release}" && pwd)/bin/impactbench"
points="${2:-200}"
[[ "$points" =~ ^[1-9][0-9]*$ ]] || { echo "sweep_overhead: POINTS must be a whole number > 0, got '$points'" >&2; exit 2; }
[ -x "$program" ] || { echo "sweep_overhead: no program at $program" >&2; exit 2; }
work="$(mktemp -d /tmp/impactbench_sweep_overhead.XXXXXX)"
trap 'rm -rf "$work"' EXIT
values="$(/usr/bin/python3 -c "print(', '.join(repr(0.5 + 0.4 * i / $points) for i in range($points)))")"
cat > "$work/spec.toml" <<SPEC
scenarios = ["bouncing_ball"]
engines = ["moreau"]
duration = 0.001
[grid]
set.restitution = [$values]
SPEC
run() {  # jobs → wall seconds
  local start end
  start=$(date +%s.%N)
  "$program" sweep "$work/spec.toml" --out "$work/jobs$1" --jobs "$1" --merge >/dev/null
  end=$(date +%s.%N)
  /usr/bin/python3 -c "print($end - $start)"
}
one=$(run 1)
two=$(run 2)
/usr/bin/python3 - "$work/jobs1/sweep.csv" "$points" "$one" "$two" <<'PY'
import csv, sys
path, n, one, two = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
rows = list(csv.DictReader(open(path, newline="")))
assert len(rows) == n and all(r["status"] == "ok" for r in rows), "a point failed"
engine = sum(float(r["engine_cpu_seconds"]) for r in rows) / n
print(f"points: {n} (bouncing_ball, moreau, one 1 ms step each)")
print(f"1 worker:  {one:.4g} s wall, {n / one:.4g} points/s")
print(f"2 workers: {two:.4g} s wall, {n / two:.4g} points/s")
print(f"rate ratio (2 workers / 1): {one / two:.3g}")
print(f"wall per point, 1 worker: {1e3 * one / n:.4g} ms; engine CPU per point: {1e3 * engine:.3g} ms")
PY
