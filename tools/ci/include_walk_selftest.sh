#!/usr/bin/env bash
# Checks include_walk.py on small trees it must refuse and one it must pass: a folder-level
# cycle (lib/a <-> lib/b), an integrator that reaches scenario code through a header of another
# folder, and the same tree without either.
set -uo pipefail
walk="$(dirname "$0")/include_walk.py"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "include walk self-test: $*" >&2; exit 1; }
file() { mkdir -p "$(dirname "$work/$1")"; printf '%s\n' "${@:2}" >"$work/$1"; }

file lib/a/x.hpp '#include "lib/b/y.hpp"'
file lib/b/y.hpp '#pragma once'
file lib/engines/moreau_jean/stepper.cpp '#include "lib/a/x.hpp"'
file solvers/lcp.hpp '#pragma once'
out="$(/usr/bin/python3 "$walk" "$work")" || fail "refused a clean tree: $out"

file lib/b/y.hpp '#include "lib/a/x.hpp"'
out="$(/usr/bin/python3 "$walk" "$work")"
[ $? -eq 1 ] || fail "passed a cycle lib/a <-> lib/b"
grep -q 'cycle among lib/a, lib/b' <<<"$out" || fail "cycle not named: $out"
grep -q 'lib/b/y.hpp:1: lib/a/x.hpp' <<<"$out" || fail "cycle include not printed: $out"

file lib/b/y.hpp '#include "lib/scenario/scenario.hpp"'
file lib/scenario/scenario.hpp '#pragma once'
out="$(/usr/bin/python3 "$walk" "$work")"
[ $? -eq 1 ] || fail "passed an integrator reaching scenario code"
grep -q 'stepper.cpp reaches scenario code' <<<"$out" || fail "reach not named: $out"
grep -q 'lib/b/y.hpp:1: lib/scenario/scenario.hpp' <<<"$out" || fail "chain not printed: $out"
echo "include walk self-test: 3 trees checked"
