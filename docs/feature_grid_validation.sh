#!/usr/bin/env bash
# Finer feature cells (issue 15): the default cell with its images cut into 88 x 72 (8 x 8 pixels)
# and 176 x 144 (4 x 4 pixels) feature cells instead of 64 x 64 (11 x 9), validated on the seeds
# of docs/validation.md's 6 cm section at camera thresholds 2 and 3. The 64 x 64 rows are that
# section's default-cell runs (docs/validation/fine-grid/default-validate-seed7-threshold-*.json).
# Writes the cell files, the JSON reports and commands.tsv into docs/validation/feature-grid/;
# then python3 docs/validation_tables.py docs/validation DATE COMMIT > docs/validation.md.
# About 3 minutes on 2 cores (the tables are built first, into a temporary cache).
source "$(dirname "${BASH_SOURCE[0]}")/validation_run.sh"
validation_setup docs/validation/feature-grid safecell-feature-grid
for grid in 88x72 176x144; do
  cell="$out/cell-$grid.yaml"
  default_cell_with "$cell" "feature_grid: {columns: ${grid%x*}, rows: ${grid#*x}}"
  for threshold in 2 3; do
    run "validate-$grid-threshold-$threshold" validate --cell "$cell" --scenes 200 --seed 7 \
      --camera-threshold "$threshold" --lut-cache "$cache"
  done
done
