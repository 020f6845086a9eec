#!/usr/bin/env bash
# Regenerates the thesis-like figures of docs/figures/ from the bundled metric scenes
# (scenarios/metric/): each pair's configuration space with its numbered places (Figures
# 9.2-9.20), the mechanism as drawn, and the pair's parts at three sample places (Figures
# 9.11-9.13): its longest CSEG (the main sliding contact), a join (a concave one if there is
# one: two contacts at once), and its largest face (no contact). Also writes index.md.
# Usage: docs/figures/regenerate.sh [QM_ATMS]   (default build/cli/qm-atms)
set -euo pipefail
cd "$(dirname "$0")/../.."
qm=${1:-build/cli/qm-atms}
out=docs/figures
rm -f "$out"/*.svg
index="$out/index.md"
{
  echo "# Figures"
  echo
  echo "Written by \`docs/figures/regenerate.sh\` from \`scenarios/metric/\` (do not edit by hand)."
  echo "Configuration spaces as \`qm-atms --places SCENE --svg DIR\` draws them, mechanisms as drawn"
  echo "(\`qm-atms draw SCENE --svg FILE\`), and each pair's parts at sample places"
  echo "(\`qm-atms draw SCENE --place A--B:ID --svg FILE\`, the place ids of \`--places --json\`)."
  echo
} > "$index"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for scene in cam escapement gear_train ratchet scotch_yoke; do
  def=scenarios/metric/$scene.def
  "$qm" --places "$def" --no-cache --svg "$tmp/$scene" >/dev/null
  "$qm" --places "$def" --no-cache --json >"$tmp/$scene.json"
  "$qm" draw "$def" --svg "$out/$scene-drawn.svg"
  echo "## $scene ($def)" >>"$index"
  echo >>"$index"
  echo "- [as drawn]($scene-drawn.svg)" >>"$index"
  for svg in "$tmp/$scene"/*.svg; do
    pair=$(basename "$svg" .svg)
    cp "$svg" "$out/$scene-$pair-cspace.svg"
    echo "- $pair: [configuration space]($scene-$pair-cspace.svg)" >>"$index"
    # The places to draw: "ID WHAT" lines.
    /usr/bin/env python3 - "$tmp/$scene.json" "$pair" >"$tmp/places" <<'PY'
import json, sys
doc, pair = json.load(open(sys.argv[1])), sys.argv[2]
for p in doc["pairs"]:
    if "--".join(p["parts"]) != pair:
        continue
    places = p["vocabulary"]["places"]
    of = lambda kind: [q for q in places if q["kind"] == kind]
    picks = []
    if of("cseg"):
        picks.append((max(of("cseg"), key=lambda q: len(q["points"])), "its longest CSEG"))
    joins = [q for q in of("join") if q.get("join_kind") == "normal-change"]
    concave = [q for q in joins if q.get("concave")]
    if concave or joins:
        picks.append(((concave or joins)[0], "a concave join" if concave else "a join"))
    if of("face"):
        picks.append((max(of("face"), key=lambda q: q.get("samples", 0)), "its largest face"))
    for q, what in picks:
        print(q["id"], what)
PY
    while read -r id what; do
      file=$scene-$pair-place-$id.svg
      "$qm" draw "$def" --place "$pair:$id" --no-cache --svg "$out/$file"
      echo "  - [place $id]($file), $what" >>"$index"
    done <"$tmp/places"
  done
  echo >>"$index"
done
echo "regenerate: wrote $(ls "$out"/*.svg | wc -l) figures and $index"
