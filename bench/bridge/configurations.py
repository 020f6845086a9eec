#!/usr/bin/env python3
"""Configurations of a metric scene to compare or sweep: one CONFIG per place of every kinematic
pair (its point or inside sample, from `qm-atms --places SCENE --json`), in the CONFIG syntax of
docs/METRIC_SCENE_FORMAT.md (degrees for rotating parts, lengths for sliding ones).

usage: configurations.py QM_ATMS SCENE [--every K] [--cseg-points]
  --every K       keep every K-th place (default 1: all)
  --cseg-points   also every point of each CSEG's polyline but its ends (the exhaustive sweep)
Prints one line per configuration: PAIR-INDEX PLACE-ID KIND CONFIG
"""
import json
import math
import subprocess
import sys


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    qm, scene = args[0], args[1]
    every = int(args[args.index("--every") + 1]) if "--every" in args else 1
    cseg_points = "--cseg-points" in args
    doc = json.loads(subprocess.run([qm, "--places", scene, "--json"], check=True, capture_output=True, text=True).stdout)
    for k, pair in enumerate(doc["pairs"]):
        names = pair["parts"]
        voc = pair["vocabulary"]
        # Each axis' kind (rotation: radians, written in degrees; translation: a length; fixed: not
        # named in a CONFIG) from the text's header: the JSON does not say it.
        kind = [kinds(qm, scene, k, i) for i in range(2)]
        for place in voc["places"][::every]:
            points = place["points"]
            picks = [points[0]] if place["kind"] != "cseg" or not cseg_points else (points[1:-1] or points[:1])
            if place["kind"] == "cseg" and not cseg_points:
                picks = [points[len(points) // 2]]
            for p in picks:
                parts = []
                for i in range(2):
                    if kind[i] == "fixed":
                        continue
                    v = math.degrees(p[i]) if kind[i] == "rotation" else p[i]
                    parts.append(f"{names[i]}={v:.10g}")
                print(k, place["id"], place["kind"], ", ".join(parts))


_kinds = {}


def kinds(qm, scene, k, i):
    """The text header of pair k names each axis' kind: 'q0 = crank: rotation ...; q1 = yoke: translation ...'."""
    if scene not in _kinds:
        text = subprocess.run([qm, "--places", scene], check=True, capture_output=True, text=True).stdout
        _kinds[scene] = [line for line in text.splitlines() if line.startswith("pair ")]
    header = _kinds[scene][k]
    part = header.split("(q0 = ")[1].split("; q1 = ")[i]
    return part.split(": ")[1].split()[0].rstrip(")")


if __name__ == "__main__":
    main()
