#!/usr/bin/env python3
"""Compares two qm-atms builds on every bundled scene: standard output, standard error and exit
status of
  - the text and --json analysis of scenarios/alex/*.def;
  - for every metric scene (scenarios/metric/*.def, scenarios/clock/*.def): --emit-def and the text
    and --json analysis as drawn, and --emit-def, text and --json analysis at one configuration per
    place of every kinematic pair (bench/bridge/configurations.py, from the BEFORE build's --places).
bench/alex/compare_outputs.py runs these commands and more (docs/PERFORMANCE.md, "Same outputs").

usage: compare_outputs.py BEFORE-QM-ATMS BEFORE-RULES AFTER-QM-ATMS AFTER-RULES OUT-DIR [--every K]
  Run from the source tree's root: paths in the outputs are relative to it. --every K keeps every
  K-th place of scenarios/clock/ (default 1: all). Writes OUT-DIR/differences.txt (each differing
  command with both outputs) and prints the counts.
"""
import glob
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def run(binary, rules, args):
    full = [binary] + args + (["--rules", rules] if args[0] != "--emit-def" else [])
    r = subprocess.run(full, capture_output=True)
    return r.returncode, r.stdout, r.stderr


def configurations(binary, scene, every):
    out = subprocess.run([sys.executable, os.path.join(HERE, "configurations.py"), binary, scene, "--every", str(every)],
                         check=True, capture_output=True, text=True).stdout
    return [line.split(" ", 3)[3] for line in out.splitlines()]


def main():
    args = sys.argv[1:]
    if len(args) < 5:
        sys.exit(__doc__)
    before, before_rules, after, after_rules, out_dir = args[:5]
    every = int(args[args.index("--every") + 1]) if "--every" in args else 1
    os.makedirs(out_dir, exist_ok=True)
    commands = []
    for s in sorted(glob.glob("scenarios/alex/*.def")):
        commands += [[s], [s, "--json"]]
    for s in sorted(glob.glob("scenarios/metric/*.def")) + sorted(glob.glob("scenarios/clock/*.def")):
        commands += [["--emit-def", s], [s], [s, "--json"]]
        for c in configurations(before, s, every if s.startswith("scenarios/clock/") else 1):
            commands += [["--emit-def", s, c], [s, "--config", c], [s, "--config", c, "--json"]]
    differ = []
    with open(os.path.join(out_dir, "differences.txt"), "w") as report:
        for args in commands:
            a = run(before, before_rules, args)
            b = run(after, after_rules, args)
            if a != b:
                differ.append(args)
                report.write("=== " + " ".join(repr(x) for x in args) + "\n")
                for tag, r in (("before", a), ("after", b)):
                    report.write(f"--- {tag}: exit {r[0]}\n")
                    report.write(r[1].decode(errors="replace") + r[2].decode(errors="replace"))
    print(f"{len(commands)} commands, {len(differ)} differ")
    for args in differ:
        print("differs:", " ".join(repr(x) for x in args))


if __name__ == "__main__":
    main()
