#!/usr/bin/env bash
# bench/engine/linear_fit.sh: how the whole `qm-atms SCENE.def` run grows with the size of a scene.
# For the generated stack of N blocks and train of N gears (bench/alex/generated_scenes.hpp) it
# counts the instructions of the whole process with callgrind (repeatable, unlike wall time on a
# shared machine), fits I(N) = a + b N + c N^2 by least squares, and prints the coefficients and the
# share of the N^2 term in I at the largest N (issue 15 item 2: below 5% at N = 400). It also
# prints each run's wall time and peak memory, measured without valgrind (one run each: for
# figures to quote, take medians of several runs, e.g. with bench/alex/alex_bench).
# Prints numbers; passes or fails nothing (STYLE.md section 8).
#
# Usage: bench/engine/linear_fit.sh [BUILD_DIR] [N...]
#   BUILD_DIR  a Release build with the targets qm-atms and scene_gen (default: build)
#   N...       the sizes (default: 25 50 100 200 400)
# Environment: QM_ATMS=path overrides the qm-atms measured (e.g. an older build to compare with);
#              KINDS="stack train" chooses the scenes.
# Needs valgrind, awk and GNU time (/usr/bin/time). Takes about 10 minutes at the default sizes.
set -euo pipefail
build=${1:-build}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(25 50 100 200 400)
exe=${QM_ATMS:-$build/cli/qm-atms}
gen=$build/bench/alex/scene_gen
for tool in valgrind awk /usr/bin/time; do
    command -v "$tool" > /dev/null || { echo "linear_fit.sh: needs $tool" >&2; exit 2; }
done
[ -x "$exe" ] && [ -x "$gen" ] || { echo "linear_fit.sh: build qm-atms and scene_gen in $build first" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "# $exe, $(date -u '+%Y-%m-%d %H:%M UTC'), load $(cut -d' ' -f1-3 /proc/loadavg)"
for kind in ${KINDS:-stack train}; do
    printf '\n%-6s %6s %16s %10s %10s\n' "$kind" N instructions "wall s" "peak MiB"
    : > "$work/points"
    for n in "${sizes[@]}"; do
        "$gen" "$kind" "$n" > "$work/scene.def"
        valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "$exe" "$work/scene.def" > /dev/null 2> "$work/vg.err"
        ir=$(awk '/^summary:/ { print $2 }' "$work/cg.out")
        /usr/bin/time -f '%e %M' -o "$work/time" "$exe" "$work/scene.def" > /dev/null
        read -r wall kib < "$work/time"
        printf '%-6s %6d %16d %10s %10.1f\n' "" "$n" "$ir" "$wall" "$(awk -v k="$kib" 'BEGIN { print k / 1024 }')"
        echo "$n $ir" >> "$work/points"
    done
    # Least squares for a + b N + c N^2: the 3x3 normal equations solved by Cramer's rule.
    awk '
        { n = $1; y = $2; s0++; s1 += n; s2 += n^2; s3 += n^3; s4 += n^4; t0 += y; t1 += y * n; t2 += y * n^2
          if (n > nmax) nmax = n }
        function det(a, b, c, d, e, f, g, h, i) { return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g) }
        END {
            if (s0 < 3) { print "  (at least three sizes are needed for a fit)"; exit }
            D = det(s0, s1, s2, s1, s2, s3, s2, s3, s4)
            a = det(t0, s1, s2, t1, s2, s3, t2, s3, s4) / D
            b = det(s0, t0, s2, s1, t1, s3, s2, t2, s4) / D
            c = det(s0, s1, t0, s1, s2, t1, s2, s3, t2) / D
            total = a + b * nmax + c * nmax^2
            printf "  fit: I(N) = %.1f M + %.3f M N + %.2f k N^2; at N = %d the N^2 term is %.1f%% of %.0f M\n",
                   a / 1e6, b / 1e6, c / 1e3, nmax, 100 * c * nmax^2 / total, total / 1e6
        }' "$work/points"
done
