#!/usr/bin/env bash
# Ends what tools/ci/start_slurm.sh started: slurmd, slurmctld and munged (by their pid files).
set -uo pipefail
for pid_file in /run/slurmd.pid /run/slurmctld.pid /run/munge/munged.pid; do
  if [ -s "$pid_file" ]; then
    pid="$(cat "$pid_file")"
    kill "$pid" 2>/dev/null
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  fi
done
exit 0
