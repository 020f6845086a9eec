#!/usr/bin/env bash
# bench/engine/linear_fit.sh: how the whole `qm-atms SCENE.def` run grows with the size of a scene.
# For the generated stack of N blocks and train of N gears (bench/alex/generated_scenes.hpp) it
# counts the instructions of the whole process with callgrind (repeatable, unlike wall time on a
# shared machine), fits I(N) = a + b N + c N^2 by least squares, and prints the coefficients and the
# share of the N^2 term in I at the largest N (the budget: below 5% at N = 400), for the whole
# run and for the instructions spent in each module (engine, ATMS, Alex driver). It also
# prints each run's wall time and peak memory, measured without valgrind (one run each: for
# figures to quote, take medians of several runs, e.g. with bench/startup/startup.py --args).
# Prints numbers; passes or fails nothing (STYLE.md section 8).
#
# Usage: bench/engine/linear_fit.sh [BUILD_DIR] [N...]
#   BUILD_DIR  a Release build with the targets qm-atms and scene_gen (default: build)
#   N...       the sizes (default: 25 50 100 200 400)
# Environment: QM_ATMS=path overrides the qm-atms measured (e.g. an older build to compare with);
#              KINDS="stack train" chooses the scenes.
# Needs valgrind (with callgrind_annotate), awk and GNU time (/usr/bin/time). Takes about 10
# minutes per build at the default sizes. Results: docs/PERFORMANCE.md, "Rule engine: linear in
# the scene".
set -euo pipefail
build=${1:-build}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(25 50 100 200 400)
exe=${QM_ATMS:-$build/cli/qm-atms}
gen=$build/bench/alex/scene_gen
for tool in valgrind callgrind_annotate awk /usr/bin/time; do
    command -v "$tool" > /dev/null || { echo "linear_fit.sh: needs $tool" >&2; exit 2; }
done
[ -x "$exe" ] && [ -x "$gen" ] || { echo "linear_fit.sh: build qm-atms and scene_gen in $build first" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Self instructions by module from callgrind_annotate: a function belongs to the first qm module
# its name mentions (std::function handlers and hash tables of a module's types included; "alex"
# is the scene reader and the driver: qm::scene and qm::analysis); __popcountdi2 is the ATMS' (environment sizes),
# malloc/free/new/delete are "alloc", the rest (libc, whose memcpy/memset the ATMS' bitset pool
# calls, the loader, libstdc++) "other".
by_module() {
    callgrind_annotate --threshold=100 "$1" 2> /dev/null | awk '
        /file:function/ { on = 1; next }
        on && match($0, /^ *[0-9,]+ \(/) {
            v = substr($0, RSTART, RLENGTH - 1); gsub(/[ ,]/, "", v)
            m = "other"
            if (match($0, /qm::[a-z]+::/)) m = substr($0, RSTART + 4, RLENGTH - 6)
            else if ($0 ~ /__popcountdi2/) m = "atms"
            else if ($0 ~ /malloc|[^a-z_]free|operator new|operator delete|unlink_chunk|malloc_consolidate/) m = "alloc"
            sum[m] += v
        }
        END { printf "%.0f %.0f %.0f %.0f %.0f\n", sum["engine"], sum["atms"], sum["alex"] + sum["analysis"] + sum["scene"], sum["alloc"], \
                     sum["other"] + sum["cli"] + sum["geometry"] + sum["support"] }'
}

# Least squares for a + b N + c N^2 (columns: N, then one value per column named in $2): the 3x3
# normal equations solved by Cramer's rule, for each column.
fit() {
    awk -v names="$2" '
        { n = $1; s0++; s1 += n; s2 += n^2; s3 += n^3; s4 += n^4; if (n > nmax) nmax = n
          for (k = 2; k <= NF; k++) { t0[k] += $k; t1[k] += $k * n; t2[k] += $k * n^2 }; cols = NF }
        function det(a, b, c, d, e, f, g, h, i) { return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g) }
        END {
            if (s0 < 3) { print "  (at least three sizes are needed for a fit)"; exit }
            split(names, name, " ")
            D = det(s0, s1, s2, s1, s2, s3, s2, s3, s4)
            for (k = 2; k <= cols; k++) {
                a = det(t0[k], s1, s2, t1[k], s2, s3, t2[k], s3, s4) / D
                b = det(s0, t0[k], s2, s1, t1[k], s3, s2, t2[k], s4) / D
                c = det(s0, s1, t0[k], s1, s2, t1[k], s2, s3, t2[k]) / D
                total = a + b * nmax + c * nmax^2
                printf "  %-8s I(N) = %8.1f M + %7.3f M N + %8.3f k N^2; N^2 term at N = %d: %5.1f%% of %.0f M\n",
                       name[k - 1], a / 1e6, b / 1e6, c / 1e3, nmax, 100 * c * nmax^2 / total, total / 1e6
            }
        }' "$1"
}

echo "# $exe, $(date -u '+%Y-%m-%d %H:%M UTC'), load $(cut -d' ' -f1-3 /proc/loadavg)"
for kind in ${KINDS:-stack train}; do
    printf '\n%-6s %5s %14s %10s %10s %10s %10s %10s %8s %9s\n' "$kind" N "instructions" engine atms alex alloc other \
        "wall s" "peak MiB"
    : > "$work/points"
    for n in "${sizes[@]}"; do
        "$gen" "$kind" "$n" > "$work/scene.def"
        valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "$exe" "$work/scene.def" > /dev/null 2> "$work/vg.err"
        ir=$(awk '/^summary:/ { print $2 }' "$work/cg.out")
        read -r engine atms alex alloc other < <(by_module "$work/cg.out")
        /usr/bin/time -f '%e %M' -o "$work/time" "$exe" "$work/scene.def" > /dev/null
        read -r wall kib < "$work/time"
        printf '%-6s %5d %14d %10d %10d %10d %10d %10d %8s %9.1f\n' "" "$n" "$ir" "$engine" "$atms" "$alex" "$alloc" "$other" \
            "$wall" "$(awk -v k="$kib" 'BEGIN { print k / 1024 }')"
        echo "$n $ir $engine $atms $alex $alloc $other" >> "$work/points"
    done
    fit "$work/points" "total engine atms alex alloc other"
done
