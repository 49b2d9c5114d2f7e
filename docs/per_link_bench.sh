#!/usr/bin/env bash
# What every link voting on balls of 4 cm costs against the default cell (arm segments on balls
# of 6 cm): both cells' tables built and timed, and the two cells' fusion on the same frames of
# the demo. Writes the JSON reports, the per-link cell file and commands.tsv into
# docs/validation/per-link/; then
#   python3 docs/validation_tables.py docs/validation DATE COMMIT > docs/validation.md
# About 5 minutes on 2 cores; run nothing else beside it (the times are the figures).
source "$(dirname "${BASH_SOURCE[0]}")/validation_run.sh"
validation_setup docs/validation/per-link safecell-per-link

per_link="$out/cell-per-link.yaml"
default_cell_with "$per_link" "robot_parts: per-link" "ball_radius_m: 0.04"
run build-per-link luts build --cell "$per_link" --out "$cache" --force
run build luts build --out "$cache" --force
run bench-cell bench --cell "$per_link" --lut-cache "$cache" --frames 300
