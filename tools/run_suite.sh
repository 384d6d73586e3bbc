#!/usr/bin/env bash
# The README's main-job command: installs what is missing, builds the release preset, and runs
# the default benchmark suite on the shipped scenarios. Extra arguments go to `impactbench suite`
# (e.g. --quick, --out DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
cmake --preset release >/dev/null
cmake --build --preset release
./build/release/bin/impactbench suite "$@"
