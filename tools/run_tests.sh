#!/usr/bin/env bash
# The README's test command: installs what is missing, builds a preset, runs its ctest suite.
#   bash tools/run_tests.sh [tests|release|debug|sanitize]   (default: tests, i.e. release
#   without the benchmark binaries)
set -euo pipefail
preset="${1:-tests}"
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
ctest --preset "$preset"
