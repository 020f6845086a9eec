#!/bin/sh
# bench/envision/outputs.sh: writes every output of `qm-atms envision` that a change to the
# envisioner's speed must leave byte-identical (text, --json, --table for every bundled mechanism
# that envisions, and the questions that run a state's engine with labelled forces: --next,
# --previous, --why-not, --without), one file each, into OUT_DIR, with each command's exit status.
# Compare two runs (an old and a new binary) with `diff -r OLD_DIR NEW_DIR`. Not a test: a tool for
# refactoring the envisioner without changing what it finds (docs/perf/envision.md).
# Usage: bench/envision/outputs.sh QM_ATMS OUT_DIR [CACHE_DIR]   (run from the source tree's root)
set -u
bin=$1
out=$2
cache=${3:-build/envision-outputs-cache}
mkdir -p "$out" "$cache"
run() {  # NAME ARGS...: stdout, stderr and the exit status of one command
    name=$1
    shift
    "$bin" envision "$@" --cache "$cache" >"$out/$name.out" 2>"$out/$name.err"
    echo "$?" >"$out/$name.status"
}
for f in scenarios/clock/*.def scenarios/metric/*.def; do
    base=$(basename "$(dirname "$f")")-$(basename "$f" .def)
    run "$base.text" "$f"
    run "$base.json" "$f" --json
    run "$base.table" "$f" --table
done
run q-next scenarios/metric/escapement.def --next 'scape-wheel/pallets-28 - -'
run q-previous scenarios/metric/escapement.def --previous 'scape-wheel/pallets-28 - -'
run q-why-not scenarios/clock/ratchet.def --why-not '#13 -> ratchet-wheel/pawl-2 + 0'
run q-why-not-states scenarios/clock/ratchet.def --why-not '#13 -> #14'
run q-without scenarios/clock/cam.def --without 'Force follower'
run q-next-clock scenarios/clock/clock.def --next '1:#100'
run q-why-not-clock scenarios/clock/clock.def --why-not '1:#100 -> 1:#101'
