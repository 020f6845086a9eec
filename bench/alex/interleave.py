#!/usr/bin/env python3
# bench/alex/interleave.py: whole-process timings of several qm-atms builds on one command line,
# interleaved (build A, build B, A, B, ...) so that the load of a shared machine falls on all alike.
# Prints, per build, the median and minimum wall time and the median and minimum CPU time (user +
# sys, from wait4: less disturbed by other processes than wall time). No memory figure: a child of
# this Python process reports at least Python's own peak; alex_bench and linear_fit.sh measure it.
# Prints numbers; passes or fails nothing (STYLE.md section 8).
#
# Usage: bench/alex/interleave.py REPS 'ARGS' QM_ATMS...
#   e.g. bench/alex/interleave.py 11 'stack200.def' /tmp/old/qm-atms build/cli/qm-atms
#   (ARGS is split on spaces; write a generated scene with build/bench/alex/scene_gen stack 200)
import os
import statistics
import sys
import time

if len(sys.argv) < 4:
    sys.exit("usage: interleave.py REPS 'ARGS' QM_ATMS...")
reps, args, builds = int(sys.argv[1]), sys.argv[2].split(), sys.argv[3:]
runs = {b: [] for b in builds}
for _ in range(reps):
    for b in builds:
        start = time.perf_counter()
        pid = os.posix_spawn(b, [b] + args, os.environ, file_actions=[(os.POSIX_SPAWN_OPEN, 1, "/dev/null", os.O_WRONLY, 0),
                                                                      (os.POSIX_SPAWN_OPEN, 2, "/dev/null", os.O_WRONLY, 0)])
        _, status, usage = os.wait4(pid, 0)
        runs[b].append((time.perf_counter() - start, usage.ru_utime + usage.ru_stime, status))
print("# %s, %d runs each, load %s" % (" ".join(args), reps, " ".join(open("/proc/loadavg").read().split()[:3])))
for b in builds:
    wall = [r[0] for r in runs[b]]
    cpu = [r[1] for r in runs[b]]
    bad = sum(1 for r in runs[b] if r[2] != 0)
    print("%-40s wall median %.4f s (min %.4f) | cpu median %.4f s (min %.4f)%s"
          % (b, statistics.median(wall), min(wall), statistics.median(cpu), min(cpu),
             "  (%d non-zero exits!)" % bad if bad else ""))
