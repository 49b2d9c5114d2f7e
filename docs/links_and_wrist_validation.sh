#!/usr/bin/env bash
# The default cell since commit 853d384 (the cameras voting on links 1-3 and the wrist, balls of 4 cm,
# 3 sub-cells per joint) against the one before it (docs/validation/cell-arm-segments.yaml): its
# table build, its fusion on the demo's frames beside the arm segments' (`bench --cell`), and
# three runs of the demo, the two scenes that miss at the reach of 3 in whole cells, then
# `safecell bench`. Reports in docs/validation/links-and-wrist/, which
# docs/validation_tables.py reads ("The default cell votes on links and wrist"); the validation
# runs on the same scenes are docs/validation.sh's. About 8 minutes on 2 cores. The demo runs in
# real time: run nothing else beside it.
source "$(dirname "${BASH_SOURCE[0]}")/validation_run.sh"
validation_setup docs/validation/links-and-wrist safecell-links-and-wrist

run build luts build --out "$cache" --force
run bench-cell bench --cell coprocessor/model/cell/default_cell.yaml --baseline-cell "$base_cell" \
  --lut-cache "$cache" --frames 300
for i in 1 2 3; do
  start=$SECONDS
  echo "== demo-$i: safecell demo --out $cache/demo-$i --lut-cache CACHE" >&2
  "$safecell" demo --out "$cache/demo-$i" --lut-cache "$cache" >&2
  cp "$cache/demo-$i/summary.json" "$out/demo-$i.json.tmp"
  mv "$out/demo-$i.json.tmp" "$out/demo-$i.json"
  printf 'demo-%s\tsafecell demo --out OUT --lut-cache CACHE (summary.json)\t%s\n' "$i" \
    "$((SECONDS - start))" >> "$out/commands.tsv"
done
# The two scenes the default cell misses at the occlusion reach of 3 (reach-3-links-and-wrist-main
# in docs/validation/), drawn in whole cells as the sanitizer build of the tests draws them.
for shard in 6094 7256; do
  run "whole-cells-reach-3-scene-$shard" validate --scenes 10000 --seed 11 --shard "$shard/10000" \
    --occlusion-reach 3 --envelope-max-move 0.18 --lut-cache "$cache"
done
# The project's benchmarks on the default cell (fusion on the typical scene and at 30 % of pixels
# blocked: #15's targets), after the demos so that nothing runs beside them.
run bench bench
