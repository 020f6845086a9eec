#!/bin/sh
# tests/fuzz/geometry_fuzz_run.sh BUILD-FUZZ SECONDS [WORK]: the fuzzing record of the geometry
# targets (issue 19 item 7; docs/METRIC_SCENE_FORMAT.md, "Fuzzing results"): the metric scene
# reader and the place cache, one after the other, each for SECONDS on one worker (the machine is
# shared; a plain libFuzzer run is one process), from a copy of the seed corpus in WORK (default a fresh temporary folder), so the seeds
# in the tree stay as they are. Prints each target's last status line; a finding leaves its
# crash-* or leak-* file in WORK and makes the script exit non-zero.
# Build: CC=clang CXX=clang++ cmake -S . -B build-fuzz -DQM_BUILD_FUZZ=ON -DQM_BUILD_TESTS=OFF
#        -DQM_BUILD_BENCH=OFF && cmake --build build-fuzz --target geometry_metric_scene_fuzz geometry_place_cache_fuzz
set -eu
build=${1:?usage: geometry_fuzz_run.sh BUILD-FUZZ SECONDS [WORK]}
seconds=${2:?usage: geometry_fuzz_run.sh BUILD-FUZZ SECONDS [WORK]}
work=${3:-$(mktemp -d)}
here=$(cd "$(dirname "$0")" && pwd)
status=0
for target in geometry_metric_scene geometry_place_cache; do
  mkdir -p "$work/$target"
  cp -n "$here/corpus/$target"/* "$work/$target/" 2>/dev/null || true
  len=4096
  [ "$target" = geometry_place_cache ] && len=16384
  ( cd "$work" && "$build/tests/fuzz/${target}_fuzz" "$work/$target" -max_total_time="$seconds" -max_len=$len \
      > "$work/$target.log" 2>&1 ) || status=1
  echo "$target: $(grep -E '^(#[0-9]+|Done)' "$work/$target.log" | tail -2 | tr '\n' ' ')"
done
ls "$work" | grep -E '^(crash|leak|timeout|oom)-' && status=1
echo "work folder: $work"
exit $status
