#!/usr/bin/env bash
# What the needless stops at camera threshold 2 are made of (issue 15): the default cell with a
# max-move of 12 cm, its images cut into 64 x 64 and into 176 x 144 feature cells, validated on
# the seed of docs/validation.md's other sections at thresholds 2 and 3; then, with 176 x 144
# cells at threshold 2, the envelope's two fixed margins taken down one at a time: no padding
# (unsafe, for the measurement only) and balls of 3 and 2 cm instead of 6. Writes the cell files,
# the JSON reports and commands.tsv into docs/validation/envelope/; then
#   python3 docs/validation_tables.py docs/validation DATE COMMIT > docs/validation.md
# About 12 minutes on 2 cores (the tables are built first, into a temporary cache).
source "$(dirname "${BASH_SOURCE[0]}")/validation_run.sh"
validation_setup docs/validation/envelope safecell-envelope
for grid in 64x64 176x144; do
  cell="$out/cell-12cm-$grid.yaml"
  default_cell_with "$cell" "m_max_m: 0.12" "feature_grid: {columns: ${grid%x*}, rows: ${grid#*x}}"
  for threshold in 2 3; do
    run "validate-12cm-$grid-threshold-$threshold" validate --cell "$cell" --scenes 200 --seed 7 \
      --camera-threshold "$threshold" --lut-cache "$cache"
  done
done
run validate-12cm-176x144-padding-0 validate --cell "$out/cell-12cm-176x144.yaml" --scenes 200 \
  --seed 7 --camera-threshold 2 --padding 0 --lut-cache "$cache"
for radius in 0.03 0.02; do
  run "validate-12cm-176x144-balls-$radius" validate --cell "$out/cell-12cm-176x144.yaml" \
    --scenes 200 --seed 7 --camera-threshold 2 --ball-radius "$radius" --lut-cache "$cache"
done
