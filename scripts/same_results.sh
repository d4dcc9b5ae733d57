#!/usr/bin/env bash
# Checks that two builds of particle-sim give bit-identical results: every preset in every
# stepping mode, the runner's report (all but its wall-clock time) and the saved final state
# compared byte for byte. For a change that must not change behaviour (a refactoring).
#   scripts/same_results.sh OLD_PARTICLE_SIM NEW_PARTICLE_SIM [SECONDS]
# SECONDS of simulated time per run (default 2). Prints one line per run and exits 1 at the
# first difference, 0 when every run agrees.
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 OLD_PARTICLE_SIM NEW_PARTICLE_SIM [SECONDS]" >&2
  exit 2
fi
old=$1 new=$2 seconds=${3:-2}
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
runs=0
for scene in "$root"/assets/scenes/*.json; do
  for mode in discrete substep exact; do
    name=$(basename "$scene" .json)-$mode
    for side in old new; do
      bin=$old
      [[ $side == new ]] && bin=$new
      "$bin" "$scene" --duration "$seconds" --mode "$mode" --report "$work/$side.json" \
        --save "$work/$side-state.json" >/dev/null 2>"$work/$side.err" ||
        { echo "$name: $side failed: $(cat "$work/$side.err")" >&2; exit 1; }
      grep -v '"wall_seconds"' "$work/$side.json" >"$work/$side.report"
    done
    if ! cmp -s "$work/old.report" "$work/new.report"; then
      echo "$name: the reports differ" >&2
      diff "$work/old.report" "$work/new.report" >&2 || true
      exit 1
    fi
    if ! cmp -s "$work/old-state.json" "$work/new-state.json"; then
      echo "$name: the saved states differ" >&2
      exit 1
    fi
    echo "$name: same"
    runs=$((runs + 1))
  done
done
echo "all $runs runs bit-identical ($seconds s each)"
