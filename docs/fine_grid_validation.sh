#!/usr/bin/env bash
# The fine grid of the precision targets (issue 15): the default cell with a max-move of 6 cm
# (16.5 million C-space cells). Builds its tables (timed, peak memory) and checks them against the
# model on 2,000 cells, measures the fusion against the default cell on the demo's frames, and
# validates it against the ground truth beside the default cell (same seeds). Writes the JSON
# reports, the cell file and commands.tsv into docs/validation/fine-grid/; then
#   python3 docs/validation_tables.py docs/validation DATE COMMIT > docs/validation.md
# About 15 minutes on 2 cores and 9 GB of memory; run nothing else beside it (the build time is
# one of the figures).
source "$(dirname "${BASH_SOURCE[0]}")/validation_run.sh"
validation_setup docs/validation/fine-grid safecell-fine-grid

cell="$out/cell.yaml"
sed 's/^m_max_m: 0.18$/m_max_m: 0.06/' "$base_cell" > "$cell.tmp"
grep -q '^m_max_m: 0.06$' "$cell.tmp" || { echo "the default cell's m_max_m line has changed" >&2; exit 1; }
mv "$cell.tmp" "$cell"

# The build, with its peak memory (GNU time's maximum resident set, KB) beside the report.
/usr/bin/time -f '%M' -o "$out/build-peak-rss-kb.txt" \
  "$safecell" luts build --cell "$cell" --out "$cache" --force --verify-cells 2000 --json \
  > "$out/build.json.tmp"
mv "$out/build.json.tmp" "$out/build.json"
printf 'build\tsafecell luts build --cell %s --out CACHE --force --verify-cells 2000\t0\n' \
  "$cell" >> "$out/commands.tsv"
run bench bench --cell "$cell" --baseline-cell "$base_cell" --lut-cache "$cache" --frames 300
for threshold in 2 3; do
  run "validate-seed7-threshold-$threshold" validate --cell "$cell" --scenes 200 --seed 7 \
    --camera-threshold "$threshold" --lut-cache "$cache"
  run "default-validate-seed7-threshold-$threshold" validate --cell "$base_cell" --scenes 200 \
    --seed 7 \
    --camera-threshold "$threshold" --lut-cache "$cache"
done
run validate-seed11 validate --cell "$cell" --scenes 2000 --seed 11 --lut-cache "$cache"
