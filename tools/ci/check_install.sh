#!/usr/bin/env bash
# Installs a configured build into a temporary prefix and checks the installed package as a user
# would, from another directory: `impactbench list`, a short `run`, and a five-line CMake project
# built against find_package(impactbench).
#   bash tools/ci/check_install.sh [BUILD_DIR]   (default: build/tests)
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build/tests}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
trap 'echo "install check: failed at line $LINENO (see the output above)" >&2' ERR
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
cd "$work"
"$prefix/bin/impactbench" list | grep -qx bouncing_ball
"$prefix/bin/impactbench" run bouncing_ball --engine moreau --duration 0.2 --out "$work/ball.csv" \
  >/dev/null
[ -s "$work/ball.csv" ]
cmake -S "$OLDPWD/tools/ci/consumer" -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix"
cmake --build "$work/consumer"
"$work/consumer/consumer" "$prefix/share/impactbench/scenarios/bouncing_ball.toml"
echo "install check passed: $prefix (list, run, consumer project)"
