#!/bin/sh
# bench/atms/choice_sets.sh: how `qm-atms run` scales with the size of one choice set.
# Prints numbers, passes or fails nothing; docs/PERFORMANCE.md records them.
#
# The program for S states (also written alone by --program S): S transition facts (next i i+1,
# the last back to 1), one rule declaring the choice set "exactly one state" over (range 1 S), and
# one transition rule concluding (reachable t) from (at s) and (next s t):
#
#   fact (clock)
#   fact (next 1 2) ... fact (next S 1)
#   rule state  when (clock)  then [exactly one ?s in (range 1 S): assume (at ?s)]
#   rule step   when (at ?s) (next ?s ?t)  then (reachable ?t)
#
# Its run: 3S + 1 facts, S interpretations, S(S-1)/2 pairwise nogoods (listed up to S = 64, one
# summary line above). Each size is run RUNS times as a whole process (/usr/bin/time: wall seconds,
# peak resident KiB); the median wall time and the largest peak are printed, with the output's
# line count as a check. Sizes are interleaved run by run (1k, 10k, 100k, 1k, ...), so a change in
# the machine's load falls on all of them alike.
#
# Usage: bench/atms/choice_sets.sh [QM_ATMS] [--runs N] [--sizes "1000 10000 100000"] [--callgrind]
#        bench/atms/choice_sets.sh --program S        (the program alone, on stdout)
#   QM_ATMS      the executable (default build/cli/qm-atms)
#   --callgrind  also count instructions once per size (valgrind --tool=callgrind; slow)
set -eu

program() {
    s=$1
    echo "# one choice of state over $s states and a transition rule (bench/atms/choice_sets.sh)"
    echo "fact (clock)"
    awk -v s="$s" 'BEGIN { for (i = 1; i <= s; i++) printf "fact (next %d %d)\n", i, i % s + 1 }'
    echo "rule state"
    echo "  when (clock)"
    echo "  then [exactly one ?s in (range 1 $s): assume (at ?s)]"
    echo "rule step"
    echo "  when (at ?s) (next ?s ?t)"
    echo "  then (reachable ?t)"
}

if [ "${1:-}" = "--program" ]; then
    program "$2"
    exit 0
fi

exe=build/cli/qm-atms
runs=5
sizes="1000 10000 100000"
callgrind=no
while [ $# -gt 0 ]; do
    case $1 in
        --runs) runs=$2; shift 2 ;;
        --sizes) sizes=$2; shift 2 ;;
        --callgrind) callgrind=yes; shift ;;
        -*) echo "usage: $0 [QM_ATMS] [--runs N] [--sizes \"1000 10000 100000\"] [--callgrind] | --program S" >&2; exit 2 ;;
        *) exe=$1; shift ;;
    esac
done

dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for s in $sizes; do program "$s" > "$dir/choice$s.rules"; done

i=0
while [ $i -lt "$runs" ]; do
    for s in $sizes; do
        /usr/bin/time -f "%e %M" -o "$dir/time" "$exe" run "$dir/choice$s.rules" > "$dir/out$s" 
        echo "$(cat "$dir/time")" >> "$dir/times$s"
        wc -l < "$dir/out$s" > "$dir/lines$s"
    done
    i=$((i + 1))
done

printf "%8s %6s %12s %12s %12s %14s\n" "states" "runs" "median s" "min s" "peak KiB" "output lines"
for s in $sizes; do
    median=$(cut -d' ' -f1 "$dir/times$s" | sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }')
    least=$(cut -d' ' -f1 "$dir/times$s" | sort -n | head -1)
    peak=$(cut -d' ' -f2 "$dir/times$s" | sort -n | tail -1)
    printf "%8s %6s %12s %12s %12s %14s\n" "$s" "$runs" "$median" "$least" "$peak" "$(cat "$dir/lines$s")"
done

if [ "$callgrind" = yes ]; then
    printf "\n%8s %16s\n" "states" "instructions"
    for s in $sizes; do
        n=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$exe" run "$dir/choice$s.rules" 2>&1 > /dev/null |
            awk '/Collected/ { print $4 }')
        printf "%8s %16s\n" "$s" "$n"
    done
fi
