#!/usr/bin/env bash
# Installs a configured build into a temporary prefix and checks the installed package as a user
# would, from another directory: `impactbench list`, a short `run`, a five-line CMake project
# built against find_package(impactbench), and (when the build has the Python module) `import
# impactbench` under Debian's python3 with only the prefix's package folder on PYTHONPATH.
#   bash tools/ci/check_install.sh [BUILD_DIR]   (default: build/tests)
set -euo pipefail
cd "$(dirname "$0")/../.."
build="${1:-build/tests}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
trap 'echo "install check: failed at line $LINENO (see the output above)" >&2' ERR
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
with_python=no
grep -q '^IMPACTBENCH_BUILD_PYTHON:BOOL=ON' "$build/CMakeCache.txt" && with_python=yes
cd "$work"
"$prefix/bin/impactbench" list | grep -qx bouncing_ball
"$prefix/bin/impactbench" run bouncing_ball --engine moreau --duration 0.2 --out "$work/ball.csv" \
  >/dev/null
[ -s "$work/ball.csv" ]
cmake -S "$OLDPWD/tools/ci/consumer" -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix"
cmake --build "$work/consumer"
"$work/consumer/consumer" "$prefix/share/impactbench/scenarios/bouncing_ball.toml"
checked="list, run, consumer project"
python_dir="$prefix/lib/python3/dist-packages"
if [ "$with_python" = yes ]; then
  env -u IMPACTBENCH_SCENARIOS PYTHONPATH="$python_dir" /usr/bin/python3 -c "
import impactbench
assert impactbench.__file__.startswith('$python_dir'), impactbench.__file__
assert 'bouncing_ball' in impactbench.scenarios()
assert impactbench.describe('bouncing_ball')['file'].startswith('$prefix/share/impactbench/')
assert impactbench.run('bouncing_ball', engine='moreau', duration=0.2).t.size > 0
"
  checked="$checked, python import"
fi
echo "install check passed: $prefix ($checked)"
