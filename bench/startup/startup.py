#!/usr/bin/env python3
# bench/startup/startup.py: start-up of qm-atms builds side by side (docs/perf/startup.md). For each command line, whole-process runs of every build, interleaved
# (A, B, A, B, ...) so that the load of the shared machine falls on all alike; prints, per build,
# the median and minimum wall time and the median CPU time (user + sys, from wait4), in ms, and the
# ratio of medians to the first build. With --callgrind, also each run's instruction count under
# valgrind's callgrind (repeatable where wall times are not), and the share spent in the dynamic
# loader's relocation.
# /bin/true is timed alongside as the floor of a process start on this machine (in the same
# interleaving, each command line's own /bin/true median and each build's ratio to it), with the
# median of minor page faults (wait4's ru_minflt) of each.
# Prints numbers; passes or fails nothing (STYLE.md section 8).
#
# Usage: bench/startup/startup.py [--reps N] [--callgrind] [--rules DIR] [--all-alex] [--only NAME] [--args ARGS] QM_ATMS...
#   e.g. bench/startup/startup.py --reps 101 /tmp/old/qm-atms build/cli/qm-atms
#        bench/startup/startup.py --reps 15 --args 'stack200.def' /tmp/old/qm-atms build/cli/qm-atms
#   --args times that one command line (split on spaces) instead of the ones below, e.g. a scene
#   written by build/bench/alex/scene_gen stack 200.
#   Each QM_ATMS is an executable. The laws are given with --rules (default: this tree's rules/) so that every build reads the same.
import argparse
import glob
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))

parser = argparse.ArgumentParser()
parser.add_argument("--reps", type=int, default=51)
parser.add_argument("--callgrind", action="store_true")
parser.add_argument("--rules", default=os.path.join(root, "rules"))
parser.add_argument("--only", help="run only the command lines whose name contains this")
parser.add_argument("--all-alex", action="store_true", help="every scene of scenarios/alex, not only the three below")
parser.add_argument("--args", help="time this command line instead")
parser.add_argument("builds", nargs="+")
a = parser.parse_args()

alex = os.path.join(root, "scenarios", "alex")
metric = os.path.join(root, "scenarios", "metric")
# name -> arguments: --help, Alex scenes of several sizes, a rule program and a metric scene.
commands = [
    ("--help", ["--help"]),
    ("block.def", [os.path.join(alex, "block.def"), "--rules", a.rules]),
    ("gears.def", [os.path.join(alex, "gears.def"), "--rules", a.rules]),
    ("recoil_escapement.def", [os.path.join(alex, "recoil_escapement.def"), "--rules", a.rules]),
    ("run queens6.rules", ["run", os.path.join(root, "scenarios", "rules", "queens6.rules")]),
    ("--emit-def cam.def", ["--emit-def", os.path.join(metric, "cam.def"), "cam=30, follower=0.1"]),
]
if a.all_alex:
    scenes = [(os.path.basename(f), [f, "--rules", a.rules]) for f in sorted(glob.glob(os.path.join(alex, "*.def")))]
    commands = commands[:1] + scenes + [c for c in commands[1:] if not c[0].endswith(".def") or c[0].startswith("--")]
if a.only:
    commands = [c for c in commands if a.only in c[0]]
if a.args:
    commands = [(a.args, a.args.split())]


def spawn(argv):
    start = time.perf_counter()
    pid = os.posix_spawn(argv[0], argv, os.environ, file_actions=[(os.POSIX_SPAWN_OPEN, 1, "/dev/null", os.O_WRONLY, 0),
                                                           (os.POSIX_SPAWN_OPEN, 2, "/dev/null", os.O_WRONLY, 0)])
    _, status, usage = os.wait4(pid, 0)
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime, status, usage.ru_minflt


def instructions(argv):
    """Total instructions under callgrind (every process of the run), and those below _dl_relocate_object."""
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "cg.%p")
        subprocess.run(["valgrind", "--tool=callgrind", "--trace-children=yes", "--callgrind-out-file=" + out] + argv,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        total = reloc = 0
        for f in glob.glob(os.path.join(d, "cg.*")):
            text = open(f, errors="replace").read()
            m = re.search(r"^summary:\s+(\d+)", text, re.M) or re.search(r"^totals:\s+(\d+)", text, re.M)
            total += int(m.group(1)) if m else 0
            ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", f], capture_output=True, text=True).stdout
            for line in ann.splitlines():
                if "_dl_relocate_object" in line:
                    reloc += int(line.split()[0].replace(",", ""))
                    break
        return total, reloc


print("# %d runs each, interleaved; load at start %s; %s" % (a.reps, " ".join(open("/proc/loadavg").read().split()[:3]),
                                                            time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())))
true_runs = []
for name, args in commands:
    runs = {b: [] for b in a.builds}
    own_true = []
    for b in a.builds:  # a warm-up run each
        spawn([b] + args)
    for rep in range(a.reps):
        order = a.builds if rep % 2 == 0 else a.builds[::-1]
        for b in order:
            runs[b].append(spawn([b] + args))
        own_true.append(spawn(["/bin/true"]))
    true_runs += own_true
    true_med = statistics.median(r[0] * 1000 for r in own_true)
    print("\n## %s   (load now %s; /bin/true median %.2f ms, %d minor faults)" % (
        name, " ".join(open("/proc/loadavg").read().split()[:3]), true_med, statistics.median(r[3] for r in own_true)))
    base = None
    for b in a.builds:
        wall = [r[0] * 1000 for r in runs[b]]
        cpu = [r[1] * 1000 for r in runs[b]]
        bad = sum(1 for r in runs[b] if r[2] != 0)
        med = statistics.median(wall)
        base = base or med
        line = "%-44s wall median %7.2f ms (min %6.2f) | cpu median %6.2f ms | x%.2f | /bin/true x%.2f | %d faults" % (
            b, med, min(wall), statistics.median(cpu), med / base, med / true_med, statistics.median(r[3] for r in runs[b]))
        if bad:
            line += "  (%d non-zero exits!)" % bad
        if a.callgrind:
            total, reloc = instructions([b] + args)
            line += " | %6.1f M instructions, %5.1f M in _dl_relocate_object" % (total / 1e6, reloc / 1e6)
        print(line)
wall = [r[0] * 1000 for r in true_runs]
print("\n/bin/true: wall median %.2f ms (min %.2f), %d runs" % (statistics.median(wall), min(wall), len(wall)))
