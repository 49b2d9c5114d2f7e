#!/usr/bin/env bash
# The design card's cross-compiled controller module, for real: the aarch64 build of
# safecell-controller, run under qemu-aarch64 (qemu-user passes its sockets through), against the
# host's coprocessor over loopback UDP in the real protocol, in the closed-loop validation's
# simulated time (so qemu's pace does not matter). It must accept the maps, slow or stop its
# simulated robot for the people walking in (no contact while moving), and with its look-ahead
# switched off (the negative control) the same scenarios must show contacts while moving.
# Run by .ci/run after the host and aarch64 builds.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."

safecell=build/host/coprocessor/cli/safecell
controller=build/aarch64/controller/host/safecell-controller-emulated
for program in "$safecell" "$controller"; do
  [[ -x "$program" ]] || { echo "aarch64 closed loop: $program missing (build host and aarch64)" >&2; exit 2; }
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Scenario 2 of seed 1 moves as a robot program (the look-ahead alone protects the person, who
# walks straight at the robot); scenario 3 with the gross-motion service.
args=(validate --closed-loop --seed 1 --first 2 --scenarios 2 --task-pool 2 --max-seconds 15
      --json --controller-program "$controller")
total() {  # total KEY FILE: the run's total (the report's last object, its keys sorted)
  grep -o "\"$1\": [0-9]*" "$2" | tail -1 | grep -o '[0-9]*$'
}
failed() {  # failed WHAT LOG
  echo "aarch64 closed loop: $1; the run's output:" >&2
  cat "$2" >&2
  exit 1
}

"$safecell" "${args[@]}" --out "$out/run" >"$out/run.json" 2>"$out/run.log" ||
  failed "the run failed" "$out/run.log"
[[ "$(total contacts_while_moving "$out/run.json")" == 0 ]] ||
  failed "contacts while moving" "$out/run.json"
[[ "$(total controller_cycles "$out/run.json")" -gt 1000 ]] || failed "no cycles" "$out/run.json"
[[ $(( $(total stops "$out/run.json") + $(total slowdowns "$out/run.json") )) -gt 0 ]] ||
  failed "the robot never slowed or stopped" "$out/run.json"
echo "aarch64 closed loop: no contact while moving in $(total controller_cycles "$out/run.json") cycles"

status=0
"$safecell" "${args[@]}" --negative-control look-ahead-off --out "$out/control" \
  >"$out/control.json" 2>"$out/control.log" || status=$?
if [[ $status -ne 1 || "$(total contacts_while_moving "$out/control.json")" == 0 ]]; then
  failed "the negative control (look-ahead off) found no contact (exit $status)" "$out/control.json"
fi
echo "aarch64 closed loop: negative control: $(total contacts_while_moving "$out/control.json") samples in contact while moving"
