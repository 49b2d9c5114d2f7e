#!/usr/bin/env bash
# Runs the closed-loop validation for docs/validation.md: `safecell validate --closed-loop` on the
# default cell, the main run split into two shards that run side by side (one per core; each
# scenario's loop is sequential), the negative control (the controller's look-ahead off) on the
# first tenth of the same scenarios, and on those the protective separation turned off. Keeps the
# JSON reports in docs/validation/; then docs/validation_tables.py writes the closed-loop section
# from them. About 45 minutes on 2 cores
# for 1,000 scenarios. Needs a host build and python3.
#
#   bash docs/closed_loop_validation.sh [SCENARIOS]   (default 1000)
#
# SAFECELL and SAFECELL_CONTROLLER name the programs to run (default: the host build's), so that
# copies can run while the build goes on.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

safecell="${SAFECELL:-build/host/coprocessor/cli/safecell}"
scenarios="${1:-1000}"
control=$(( scenarios / 10 < 20 ? 20 : scenarios / 10 ))
half=$(( scenarios / 2 ))
seed=21
out=docs/validation
mkdir -p "$out"
[[ -x "$safecell" ]] || { echo "closed_loop_validation.sh: no $safecell" >&2; exit 2; }

run() {  # run NAME ARGS...: one JSON report (exit 1, contacts while moving, is a result)
  local name="$1"; shift
  local args=(validate --closed-loop --seed "$seed" --json --out "$out/$name.work" "$@")
  [[ -z "${SAFECELL_CONTROLLER:-}" ]] || args+=(--controller-program "$SAFECELL_CONTROLLER")
  echo "closed_loop_validation.sh: $name: safecell ${args[*]}" >&2
  local status=0 start
  start=$(date +%s)
  "$safecell" "${args[@]}" >"$out/$name.json.tmp" 2>"$out/$name.log" || status=$?
  [[ $status -le 1 ]] || { echo "closed_loop_validation.sh: $name failed ($status)" >&2; exit "$status"; }
  mv "$out/$name.json.tmp" "$out/$name.json"
  rm -rf "$out/$name.work" "$out/$name.log"
  printf '%s\t%s\t%s\n' "$name" "safecell ${args[*]}" "$(( $(date +%s) - start ))" \
    >>"$out/closed-loop-commands.tsv"
}

: >"$out/closed-loop-commands.tsv"
printf '%s\t%s\n' "$(date -u +%Y-%m-%d)" "$(git rev-parse --short HEAD)" >"$out/closed-loop-run.tsv"
run closed-loop-1 --first 0 --scenarios "$half" &
first=$!
run closed-loop-2 --first "$half" --scenarios "$(( scenarios - half ))"
wait "$first"
run closed-loop-control --first 0 --scenarios "$control" --negative-control look-ahead-off
# The ablation of the protective separation: the same scenarios without it.
run closed-loop-separation-off --first 0 --scenarios "$control" --negative-control separation-off
echo "closed_loop_validation.sh: done; now python3 docs/validation_tables.py (or validation.sh)" >&2
