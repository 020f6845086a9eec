#!/bin/sh
# bench/geometry/vocabulary_sweep.sh BUILD-DIR [OUT]: the exhaustive sweep of vocabulary stability
# whose method docs/ACCURACY.md describes ("Topology against grid and drawing"). For each scene,
# every grid from the coarsest that resolves its parts to 4 times finer (both axes scaled
# together), then 56 drawings (scaled 1e-3..1e3, turned by quarter turns, moved). One thread:
# minutes, not to be run in CI.
set -eu
build=${1:?usage: vocabulary_sweep.sh BUILD-DIR [OUT]}
out=${2:-/dev/stdout}
here=$(cd "$(dirname "$0")" && pwd)
scenes=$here/../../scenarios/metric
bench=$build/bench/geometry/geometry_vocabulary_stability_bench
{
  echo "# $(date -u +%Y-%m-%dT%H:%MZ) $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo '?')"
  for s in "$here/scenes/tilted_cam.def" "$here/scenes/tilted_follower.def" "$scenes/cam.def" "$scenes/scotch_yoke.def" "$scenes/gear_train.def"; do
    echo "== $(basename "$s") grids"; "$bench" "$s"
    echo "== $(basename "$s") drawings"; "$bench" "$s" --transforms
  done
  echo "== ratchet.def grids"; "$bench" "$scenes/ratchet.def"
  echo "== ratchet.def drawings"; "$bench" "$scenes/ratchet.def" --transforms
  echo "== escapement.def grids from 128"; "$bench" "$scenes/escapement.def" --grid 128 128
  echo "== escapement.def drawings"; "$bench" "$scenes/escapement.def" --transforms
} > "$out"
