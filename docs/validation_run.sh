# Sourced by the docs/*_validation.sh scripts (not run on its own): the shared set-up and `run`.
# The sections these scripts write were measured on the default cell as it was at f269248 (arm
# segments on balls of 6 cm, 2 sub-cells per joint, two reduced speeds; until 853d384 the default
# but for a third reduced speed): they derive their cells from it, and pass it
# (`--cell "$base_cell"`, `--baseline-cell "$base_cell"`) where they ran the default cell.
base_cell=docs/validation/cell-arm-segments.yaml

# validation_setup OUT CACHE_PREFIX: strict mode, the repository root as working folder, `safecell`
# (SAFECELL or the host build), `out` (created, its commands.tsv emptied) and a temporary table
# cache `cache`, removed on exit.
validation_setup() {
  set -euo pipefail
  cd "$(dirname "${BASH_SOURCE[0]}")/.."
  safecell=${SAFECELL:-build/host/coprocessor/cli/safecell}
  out=$1
  cache=$(mktemp -d "/tmp/$2.XXXX")
  trap 'rm -rf "$cache"' EXIT
  mkdir -p "$out"
  : > "$out/commands.tsv"
}

# run NAME ARGS...: `safecell ARGS --json` into NAME.json (atomically), its command (the cache
# folder written CACHE) and seconds into commands.tsv. Exit 1 is a finding, not a failure here
# (validate exits 1 when it missed a collision: threshold 3 does); anything else stops the script.
run() {
  local name=$1
  shift
  local start=$SECONDS
  local status=0
  echo "== $name: safecell $*" >&2
  "$safecell" "$@" --json > "$out/$name.json.tmp" || status=$?
  if [ "$status" -gt 1 ]; then exit "$status"; fi
  mv "$out/$name.json.tmp" "$out/$name.json"
  printf '%s\tsafecell %s\t%s\n' "$name" "${*//$cache/CACHE}" "$((SECONDS - start))" \
    >> "$out/commands.tsv"
}

# default_cell_with FILE LINE...: the base cell (above) with each top-level LINE ("key: value") in place
# of the line of its key, into FILE (atomically); stops when a key's line is not there.
default_cell_with() {
  local file=$1
  shift
  cp "$base_cell" "$file.tmp"
  local line
  for line in "$@"; do
    sed -i "s/^${line%%:*}: .*\$/$line/" "$file.tmp"
    grep -qxF "$line" "$file.tmp" || { echo "the default cell has no line '${line%%:*}: ...'" >&2; exit 1; }
  done
  mv "$file.tmp" "$file"
}
