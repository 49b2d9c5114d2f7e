#!/usr/bin/env bash
# More cameras against a higher camera threshold (issue 15): the default cell with two or four
# more cameras at the middle of its walls, each looking at the arm like the four in the corners,
# validated on the seed of docs/validation.md's other sections (seed 7, 200 scenes) at the
# thresholds that keep most configurations free; then the eight-camera cell at threshold 5 on
# the main run's 10,000 scenes of seed 11 (on one thread, so that it can run beside other work),
# on the two scenes in which threshold 3 of four cameras missed
# (docs/validation/reach-3-main.json), and in the closed loop. Writes the cell files, the
# JSON reports and commands.tsv into docs/validation/cameras/; then
#   python3 docs/validation_tables.py docs/validation DATE COMMIT > docs/validation.md
# About 50 minutes on 2 cores, 33 of them the 10,000 scenes (the tables are built first, into a
# temporary cache). SAFECELL and SAFECELL_CONTROLLER name the programs (default: the host
# build's).
source "$(dirname "${BASH_SOURCE[0]}")/validation_run.sh"
validation_setup docs/validation/cameras safecell-cameras

# cameras_cell FILE HEIGHT_M NAME:X:Y...: the default cell with a camera NAME at (X, Y, HEIGHT_M)
# for each argument, looking at the same point as the corner cameras, after the last of them.
cameras_cell() {
  local file=$1 height=$2
  shift 2
  cp "$base_cell" "$file.tmp"
  local last='    look_at: {position_m: \[1.95, -1.95, 2.9\], .*'
  grep -qx "$last" "$file.tmp" || { echo "the default cell's cam3 is not where expected" >&2; exit 1; }
  local spec lines=""
  for spec in "$@"; do
    IFS=: read -r name x y <<< "$spec"
    lines+="  - name: $name\n    look_at: {position_m: [$x, $y, $height], target_m: [0, 0, 0.8], "
    lines+="horizontal_fov_deg: 75, size_px: [704, 576]}\n"
  done
  sed -i "/^$last\$/a\\${lines%\\n}" "$file.tmp"
  mv "$file.tmp" "$file"
}

cameras_cell "$out/cell-6-cameras.yaml" 2.9 cam4:0:1.95 cam5:0:-1.95
cameras_cell "$out/cell-8-cameras.yaml" 2.9 cam4:0:1.95 cam5:0:-1.95 cam6:1.95:0 cam7:-1.95:0
cameras_cell "$out/cell-8-cameras-low.yaml" 2.2 cam4:0:1.95 cam5:0:-1.95 cam6:1.95:0 cam7:-1.95:0

for threshold in 3 4; do
  run "validate-6-cameras-threshold-$threshold" validate --cell "$out/cell-6-cameras.yaml" \
    --scenes 200 --seed 7 --camera-threshold "$threshold" --lut-cache "$cache"
done
for threshold in 3 4 5; do
  run "validate-8-cameras-threshold-$threshold" validate --cell "$out/cell-8-cameras.yaml" \
    --scenes 200 --seed 7 --camera-threshold "$threshold" --lut-cache "$cache"
done
for threshold in 4 5; do
  run "validate-8-cameras-low-threshold-$threshold" validate \
    --cell "$out/cell-8-cameras-low.yaml" --scenes 200 --seed 7 --camera-threshold "$threshold" \
    --lut-cache "$cache"
done
for shard in 8024 9710; do
  run "validate-8-cameras-threshold-5-scene-$shard" validate --cell "$out/cell-8-cameras.yaml" \
    --scenes 10000 --seed 11 --shard "$shard/10000" --camera-threshold 5 --lut-cache "$cache"
done
run validate-8-cameras-threshold-5-seed-11 validate --cell "$out/cell-8-cameras.yaml" \
  --scenes 10000 --seed 11 --camera-threshold 5 --threads 1 --lut-cache "$cache"
# The closed loop with the eight cameras at threshold 5: the first 20 scenarios of the seed of the
# separation section's closed-loop rows (four cameras, threshold 2: docs/validation/separation/).
run closed-loop-8-cameras-threshold-5 validate --closed-loop --cell "$out/cell-8-cameras.yaml" \
  --camera-threshold 5 --seed 21 --first 0 --scenarios 20 --out "$cache/closed-loop" \
  --controller-program "${SAFECELL_CONTROLLER:-build/host/controller/host/safecell-controller}"
# The two scenes again with the four corner cameras at threshold 3: the same scenes (the same
# colliding configurations), and the misses of the main run's threshold-3 report.
for shard in 8024 9710; do
  run "validate-4-cameras-threshold-3-scene-$shard" validate --cell "$base_cell" --scenes 10000 \
    --seed 11 --shard "$shard/10000" --camera-threshold 3 --lut-cache "$cache"
done
# The eight cameras' fusion at threshold 5 against the default cell's, the same frames (bench
# --cell), twice.
sed 's/^camera_threshold: .*$/camera_threshold: 5/' "$out/cell-8-cameras.yaml" \
  > "$out/cell-8-cameras-threshold-5.yaml"
grep -qx 'camera_threshold: 5' "$out/cell-8-cameras-threshold-5.yaml" ||
  { echo "no camera_threshold line in $out/cell-8-cameras.yaml" >&2; exit 1; }
for i in 1 2; do
  run "bench-8-cameras-threshold-5-$i" bench --cell "$out/cell-8-cameras-threshold-5.yaml" \
    --baseline-cell "$base_cell" --frames 300 --lut-cache "$cache"
done
