#!/usr/bin/env bash
# Finer feature cells (issue 15): the default cell with its images cut into 88 x 72 (8 x 8 pixels)
# and 176 x 144 (4 x 4 pixels) feature cells instead of 64 x 64 (11 x 9), validated on the seeds
# of docs/validation.md's 6 cm section at camera thresholds 2 and 3. The 64 x 64 rows are that
# section's default-cell runs (docs/validation/fine-grid/default-validate-seed7-threshold-*.json).
# Writes the cell files, the JSON reports and commands.tsv into docs/validation/feature-grid/;
# then python3 docs/validation_tables.py docs/validation DATE COMMIT > docs/validation.md.
# About 3 minutes on 2 cores (the tables are built first, into a temporary cache).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
safecell=${SAFECELL:-build/host/coprocessor/cli/safecell}
out=docs/validation/feature-grid
cache=$(mktemp -d /tmp/safecell-feature-grid.XXXX)
trap 'rm -rf "$cache"' EXIT
mkdir -p "$out"
: > "$out/commands.tsv"
for grid in 88x72 176x144; do
  cell="$out/cell-$grid.yaml"
  sed "s/^feature_grid: {columns: 64, rows: 64}$/feature_grid: {columns: ${grid%x*}, rows: ${grid#*x}}/" \
    coprocessor/cell/default_cell.yaml > "$cell.tmp"
  grep -q "^feature_grid: {columns: ${grid%x*}, rows: ${grid#*x}}$" "$cell.tmp" ||
    { echo "the default cell's feature_grid line has changed" >&2; exit 1; }
  mv "$cell.tmp" "$cell"
  for threshold in 2 3; do
    name="validate-$grid-threshold-$threshold"
    args=(validate --cell "$cell" --scenes 200 --seed 7 --camera-threshold "$threshold"
          --lut-cache "$cache")
    echo "== $name: safecell ${args[*]}" >&2
    start=$SECONDS
    status=0
    # Exit 1 is a finding (a missed collision), not a failure of the script.
    "$safecell" "${args[@]}" --json > "$out/$name.json.tmp" || status=$?
    if [ "$status" -gt 1 ]; then exit "$status"; fi
    mv "$out/$name.json.tmp" "$out/$name.json"
    printf '%s\tsafecell %s\t%s\n' "$name" "${args[*]//$cache/CACHE}" "$((SECONDS - start))" \
      >> "$out/commands.tsv"
  done
done
