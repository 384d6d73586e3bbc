#!/usr/bin/env bash
# Installs the Debian 12 packages impactbench needs, only those missing. Needs root (apt-get);
# when not root it names the command to run instead of guessing at sudo.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config ccache
  libeigen3-dev libbullet-dev libbox2d-dev libmujoco-dev libode-dev libbenchmark-dev libgtest-dev
  libfclib-dev libsundials-dev libtomlplusplus-dev libmuparser-dev libcli11-dev
  python3-matplotlib python3-dev python3-numpy python3-scipy pybind11-dev python3-pybind11
  python3-pytest
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" -ne 0 ]; then
  echo "impactbench: missing Debian packages; as root, run:" >&2
  echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
  exit 1
fi
echo "impactbench: installing missing packages: ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
