#!/bin/sh
# tests/fuzz/fuzz_record.sh: the fuzzing record (docs/FUZZING.md). Runs every
# libFuzzer target of tests/fuzz/ for SECONDS of wall time each, JOBS at a time, each from a copy of
# its seed corpus in WORK (the seeds in the tree stay as they are unless --merge is given), and
# prints one Markdown table row per target: executions, executions per second, coverage (libFuzzer's
# `cov:` edges and `ft:` features), corpus size before and after, and findings (crash-, leak-,
# timeout- and oom- files, kept in WORK/<target>.artifacts/). Not run by ctest: a record is minutes
# to hours of machine time; docs/FUZZING.md says how the recorded runs were made.
#
# Usage: tests/fuzz/fuzz_record.sh BUILD-FUZZ SECONDS [--jobs N] [--work DIR] [--merge] [TARGET...]
#   BUILD-FUZZ  a fuzz build: CC=clang-16 CXX=clang++-16 cmake -S . -B build-fuzz -DQM_BUILD_FUZZ=ON
#               -DQM_BUILD_TESTS=OFF -DQM_BUILD_BENCH=OFF && cmake --build build-fuzz
#   SECONDS     wall time per target (libFuzzer's -max_total_time)
#   --jobs N    targets run at once (default 1: the machines here are shared)
#   --work DIR  where the corpora, logs and findings go (default a fresh temporary folder)
#   --merge     afterwards, add to the tree's seed corpus (tests/fuzz/corpus/<target>/) the inputs
#               that reach coverage the seeds do not (libFuzzer's -merge=1: a minimal set, not all)
#   TARGET      scene_text, engine_rules, geometry_metric_scene, geometry_place_cache,
#               cli_query_text (default: all of them)
# Exit status: 0 when no target found anything, 1 when one did, 2 for a usage error.
set -eu
usage="usage: $0 BUILD-FUZZ SECONDS [--jobs N] [--work DIR] [--merge] [TARGET...]"
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
build=$(cd "$1" && pwd)
seconds=$2
shift 2
case $seconds in ''|*[!0-9]*) echo "$0: SECONDS must be a whole number, not '$seconds'" >&2; exit 2 ;; esac
jobs=1
work=
merge=no
targets=
while [ $# -gt 0 ]; do
    case $1 in
        --jobs) jobs=${2:?$usage}; shift 2 ;;
        --work) work=${2:?$usage}; shift 2 ;;
        --merge) merge=yes; shift ;;
        -*) echo "$usage" >&2; exit 2 ;;
        *) targets="$targets $1"; shift ;;
    esac
done
[ -n "$targets" ] || targets="scene_text engine_rules geometry_metric_scene geometry_place_cache cli_query_text"
here=$(cd "$(dirname "$0")" && pwd)
[ -n "$work" ] || work=$(mktemp -d)
mkdir -p "$work"
work=$(cd "$work" && pwd)

# The longest input each target takes: a rule file or scene of a few KB, a place cache file of a
# few vocabularies, a one-line query.
max_len() {
    case $1 in
        geometry_place_cache) echo 16384 ;;
        cli_query_text) echo 256 ;;
        *) echo 4096 ;;
    esac
}

for t in $targets; do
    [ -x "$build/tests/fuzz/${t}_fuzz" ] || { echo "$0: no fuzz target $build/tests/fuzz/${t}_fuzz (build it first)" >&2; exit 2; }
done

run_one() {
    t=$1
    mkdir -p "$work/$t" "$work/$t.artifacts"
    cp "$here/corpus/$t"/* "$work/$t/" 2>/dev/null || true
    ls "$work/$t" | wc -l > "$work/$t.seeds"
    # libFuzzer exits non-zero on a finding; the row below reports it, so the status is not needed.
    ( cd "$work" && "$build/tests/fuzz/${t}_fuzz" "$work/$t" -max_total_time="$seconds" \
        -max_len="$(max_len "$t")" -print_final_stats=1 -artifact_prefix="$work/$t.artifacts/" \
        > "$work/$t.log" 2>&1 ) || true
}

# Runs the targets JOBS at a time.
running=0
for t in $targets; do
    run_one "$t" &
    running=$((running + 1))
    if [ "$running" -ge "$jobs" ]; then wait; running=0; fi
done
wait

echo "| target | seconds | executions | exec/s | cov | ft | corpus (seeds → end) | findings |"
echo "|---|---:|---:|---:|---:|---:|---|---|"
status=0
for t in $targets; do
    log=$work/$t.log
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
    last=$(grep -E '^#[0-9]+' "$log" | tail -n 1)
    cov=$(echo "$last" | sed -n 's/.* cov: \([0-9]*\).*/\1/p')
    ft=$(echo "$last" | sed -n 's/.* ft: \([0-9]*\).*/\1/p')
    found=$(ls "$work/$t.artifacts" | tr '\n' ' ')
    [ -z "$found" ] || status=1
    echo "| $t | $seconds | ${execs:-?} | ${rate:-?} | ${cov:-?} | ${ft:-?} | $(cat "$work/$t.seeds") → $(ls "$work/$t" | wc -l) | ${found:-none} |"
    if [ "$merge" = yes ]; then
        before=$(ls "$here/corpus/$t" | wc -l)
        "$build/tests/fuzz/${t}_fuzz" -merge=1 -max_len="$(max_len "$t")" "$here/corpus/$t" "$work/$t" \
            > "$work/$t.merge.log" 2>&1 || { echo "$0: merging $t failed: $work/$t.merge.log" >&2; status=1; }
        echo "  merged into tests/fuzz/corpus/$t: $before → $(ls "$here/corpus/$t" | wc -l) files" >&2
    fi
done
echo "work folder: $work" >&2
exit $status
