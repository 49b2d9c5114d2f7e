#!/usr/bin/env bash
# What the finer votes cost against the default cell (arm segments on balls of 6 cm): every link
# on balls of 4 cm, and links 1-3 with the wrist as one part on balls of 4 cm with 3 sub-cells a
# joint. Each cell's tables built and timed, and its fusion against the default's on the same
# frames of the demo. Writes the JSON reports, the cell files and commands.tsv into
# docs/validation/per-link/; then
#   python3 docs/validation_tables.py docs/validation DATE COMMIT > docs/validation.md
# About 15 minutes on 2 cores; run nothing else beside it (the times are the figures).
source "$(dirname "${BASH_SOURCE[0]}")/validation_run.sh"
validation_setup docs/validation/per-link safecell-per-link

per_link="$out/cell-per-link.yaml"
default_cell_with "$per_link" "robot_parts: per-link" "ball_radius_m: 0.04"
run build-per-link luts build --cell "$per_link" --out "$cache" --force
run build luts build --cell "$base_cell" --out "$cache" --force
run bench-cell bench --cell "$per_link" --baseline-cell "$base_cell" --lut-cache "$cache" \
  --frames 300

links_and_wrist="$out/cell-links-and-wrist.yaml"
default_cell_with "$links_and_wrist" "robot_parts: links-and-wrist" "ball_radius_m: 0.04" \
  "envelope_max_move_m: 0.06"
run build-links-and-wrist luts build --cell "$links_and_wrist" --out "$cache" --force
run bench-cell-links-and-wrist bench --cell "$links_and_wrist" --baseline-cell "$base_cell" \
  --lut-cache "$cache" --frames 300
