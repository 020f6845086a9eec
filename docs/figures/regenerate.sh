#!/usr/bin/env bash
# Regenerates the thesis-like figures of docs/figures/ from the bundled metric scenes
# (scenarios/metric/): each pair's configuration space with its numbered places (Figures
# 9.2-9.20), the mechanism as drawn, and the pair's parts at three sample places (Figures
# 9.11-9.13): its longest CSEG (the main sliding contact), a join (a concave one if there is
# one: two contacts at once), and its largest face (no contact). Then the envisioner's figures
# from scenarios/metric/ and scenarios/clock/: envisionment graphs grouped by behavioural cycle
# (Figures 9.21-9.24; `envision --svg`, laid out by Graphviz's library), and histories drawn state
# by state (Figures 9.25, 9.27, 9.28, 9.32; `draw --history`), each the answer of a described
# behaviour (`envision --path`) of docs/ENVISION.md. Also writes index.md.
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
# The envisioner's figures share one place cache, so that every vocabulary is built once.
cache="$tmp/cache"
{
  echo "## Envisionments (\`qm-atms envision SCENE --svg FILE\`)"
  echo
  echo "Each state a box (\`#ID\` and its name), behavioural cycles as grey clusters, terminal states"
  echo "doubled; transitions red for a collision, blue for a change by force, dashed for an instant."
  echo
} >>"$index"
for scene in metric/cam metric/escapement clock/gear_pair clock/scotch_yoke; do
  name=$(echo "$scene" | tr / -)
  "$qm" envision "scenarios/$scene.def" --cache "$cache" --svg "$out/$name-envisionment.svg" >"$tmp/summary"
  echo "- [$scene]($name-envisionment.svg): $(tail -1 "$tmp/summary" | sed 's/^summary: //')" >>"$index"
done
{
  echo
  echo "## Histories (\`qm-atms draw SCENE --history 'STATE ...' --svg FILE\`)"
  echo
  echo "The states of a described behaviour's path (\`qm-atms envision SCENE --path ...\`), each drawn with"
  echo "its pairs at their places' sample configurations, contacts marked, the parts' motions as orange arrows."
  echo
} >>"$index"
# history NAME SCENE WHAT PATH [AVOID...]: the path's states drawn as a strip.
history() {
  local name=$1 scene=$2 what=$3 path=$4
  shift 4
  local avoid=() note=""
  for a in "$@"; do avoid+=(--avoid "$a"); note+=" \`--avoid '$a'\`"; done
  "$qm" envision "scenarios/$scene.def" --cache "$cache" --path "$path" "${avoid[@]}" >"$tmp/path"
  local ids
  ids=$(sed -n 's/^  \(#[0-9]*\) .*/\1/p' "$tmp/path" | tr '\n' ' ')
  "$qm" draw "scenarios/$scene.def" --cache "$cache" --history "$ids" --columns "${COLUMNS_OF_STRIP:-4}" --svg "$out/$name.svg"
  echo "- [$what]($name.svg): \`--path '$path'\`$note" >>"$index"
}
history clock-ratchet-jam clock/ratchet "the ratchet jams (Figure 9.27)" \
  'ratchet-wheel/pawl:free ratchet-wheel=0 pawl=0 ; #13'
history clock-ratchet-skip clock/ratchet "the ratchet skips, turning backwards (Figure 9.28)" \
  '#209 ; ratchet-wheel/pawl:free pawl=- ; #209' ratchet-wheel=0 ratchet-wheel=-
history clock-scotch_yoke-reverse clock/scotch_yoke "the crank turning, the yoke stops and reverses, twice (Figure 9.32)" \
  'crank/yoke:contact crank=+ yoke=+ ; crank/yoke:contact yoke=- ; crank/yoke:contact yoke=+' crank=0 crank=-
history clock-cam-ride clock/cam "the follower rides the turning cam (9.4)" \
  'cam=+ follower=+ ; cam=+ follower=- ; cam=+ follower=+' cam=0 cam=-
COLUMNS_OF_STRIP=6 history clock-escapement-de-carle clock/escapement "de Carle's cycle of the recoil escapement (9.1.5, Figures 9.21, 9.25)" \
  'scape-wheel/pallets-4 scape-wheel=- pallets=+ ; scape-wheel/pallets:free scape-wheel=- ; scape-wheel/pallets-57 scape-wheel=+ ; scape-wheel/pallets-57 scape-wheel=- pallets=- ; scape-wheel/pallets:free scape-wheel=- ; scape-wheel/pallets-54 scape-wheel=+ ; scape-wheel/pallets-54 scape-wheel=- pallets=+ ; scape-wheel/pallets:free scape-wheel=- ; scape-wheel/pallets-4 scape-wheel=- pallets=+'
echo "regenerate: wrote $(ls "$out"/*.svg | wc -l) figures and $index"
