#!/usr/bin/env python3
"""Compares two qm-atms builds on every bundled scene, byte for byte (standard output, standard error
and exit status), for a change that must not change behaviour (docs/PERFORMANCE.md, "Same
outputs"). The commands:
  - scenarios/alex/*.def, text and --json, and with --kinematic, text and --json;
  - every metric scene (scenarios/metric/*.def, scenarios/clock/*.def): --emit-def and the text and
    --json analysis as drawn, and --emit-def, text and --json analysis at one configuration per
    place of every kinematic pair (bench/bridge/configurations.py, from the BEFORE build's --places);
  - `--why` on every object's motions in every situation of scenarios/alex/*.def: every
    translation of a 2-D scene (the zero and the six axis directions of a 3-D one) and every
    rotation (the zero and the six axis turns in 3-D), text, and --json for the first object;
  - `check` of the rules folder.
usage: compare_outputs.py BEFORE-QM-ATMS BEFORE-RULES AFTER-QM-ATMS AFTER-RULES OUT-DIR [--every K] [--jobs J]
                          [--before-root DIR]
  Run from the source tree's root. --every K keeps every K-th place of scenarios/clock/ (default 4).
  --before-root DIR: run the BEFORE build from DIR (default: here), e.g. a folder whose `rules`
  links to the old laws and whose `scenarios` and `bench` link to this tree's, so that both builds
  are given the same relative paths (`rules`) and print the same locations.
  Writes OUT-DIR/differences.txt and prints the counts.
"""
import concurrent.futures
import glob
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run(binary, rules, args, cwd=None):
    if args[0] == "check":
        full = [binary, "check", rules]
    else:
        full = [binary] + args + (["--rules", rules] if args[0] != "--emit-def" else [])
    r = subprocess.run(full, capture_output=True, cwd=cwd)
    return r.returncode, r.stdout, r.stderr


def configurations(binary, scene, every):
    out = subprocess.run([sys.executable, os.path.join(HERE, "..", "bridge", "configurations.py"), binary, scene, "--every",
                          str(every)], check=True, capture_output=True, text=True).stdout
    return [line.split(" ", 3)[3] for line in out.splitlines()]


def directions(dims, rotation):
    if dims == 2 and not rotation:
        return [f"({a} {b})" for a in "+0-" for b in "+0-"]
    if dims == 2:
        return ["(+)", "(0)", "(-)"]
    out = ["(0 0 0)"]
    for i in range(3):
        for s in "+-":
            v = ["0"] * 3
            v[i] = s
            out.append("(" + " ".join(v) + ")")
    return out


def why_commands(binary, rules, scene, root):
    code, out, _ = run(binary, rules, [scene, "--json"], root)
    if code != 0:
        return []
    doc = json.loads(out)
    dims = doc["dimensions"]
    commands = []
    for situation in range(1, len(doc["situations"]) + 1):
        objects = list(doc["situations"][situation - 1]["freedom"])
        for k, o in enumerate(objects):
            for kind, rotation in (("Translational-Motion", False), ("Rotational-Motion", True)):
                for d in directions(dims, rotation):
                    c = [scene, "--why", f"{kind} ({o} {d})", "--situation", str(situation)]
                    commands.append(c)
                    if k == 0:
                        commands.append(c + ["--json"])
    return commands


def main():
    args = sys.argv[1:]
    if len(args) < 5:
        sys.exit(__doc__)
    before, before_rules, after, after_rules, out_dir = args[:5]
    every = int(args[args.index("--every") + 1]) if "--every" in args else 4
    jobs = int(args[args.index("--jobs") + 1]) if "--jobs" in args else 2
    root = args[args.index("--before-root") + 1] if "--before-root" in args else None
    os.makedirs(out_dir, exist_ok=True)
    commands = [["check"]]
    alex = sorted(glob.glob("scenarios/alex/*.def"))
    for s in alex:
        commands += [[s], [s, "--json"], [s, "--kinematic"], [s, "--kinematic", "--json"]]
    for s in alex:
        commands += why_commands(before, before_rules, s, root)
    for s in sorted(glob.glob("scenarios/metric/*.def")) + sorted(glob.glob("scenarios/clock/*.def")):
        commands += [["--emit-def", s], [s], [s, "--json"]]
        for c in configurations(before, s, every if s.startswith("scenarios/clock/") else 1):
            commands += [["--emit-def", s, c], [s, "--config", c], [s, "--config", c, "--json"]]

    def both(c):
        return run(before, before_rules, c, root), run(after, after_rules, c)

    differ = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool, \
            open(os.path.join(out_dir, "differences.txt"), "w") as report:
        for i, (c, (a, b)) in enumerate(zip(commands, pool.map(both, commands))):
            if (i + 1) % 200 == 0:
                print(f"{i + 1} of {len(commands)} compared, {len(differ)} differ", flush=True)
            if a != b:
                differ.append(c)
                report.write("=== " + " ".join(repr(x) for x in c) + "\n")
                for tag, r in (("before", a), ("after", b)):
                    report.write(f"--- {tag}: exit {r[0]}\n")
                    report.write(r[1].decode(errors="replace") + r[2].decode(errors="replace"))
    print(f"{len(commands)} commands, {len(differ)} differ")
    for c in differ:
        print("differs:", " ".join(repr(x) for x in c))


if __name__ == "__main__":
    main()
