// bench/atms/atms_bench.cpp
// Prints numbers, passes or fails nothing (STYLE.md section 8):
//   1. label propagation on seeded random layered Horn theories of growing size;
//   2. N-queens N = 4..12 as ATMS interpretations: one choice set per row (assumption = column),
//      pairwise nogoods for attacking placements; the whole run (build the ATMS, assumptions,
//      nogoods, enumerate and intern all solutions) is timed, median of several repetitions;
//   3. the same count by the streaming interpretation visitor (no interning);
//   4. a plain bitmask backtracking N-queens as the floor.
// Peak RSS (getrusage ru_maxrss) is printed at the end of each section.
// Usage: atms_bench [--quick]   (--quick: fewer repetitions, N up to 10)
#include "atms/atms.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sys/resource.h>
#include <vector>

using namespace qm::atms;
using Clock = std::chrono::steady_clock;

namespace {
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

long peak_rss_kib() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;  // KiB on Linux
}

template <class F>
double median_seconds(int reps, F&& run) {
    std::vector<double> t;
    for (int i = 0; i < reps; ++i) {
        const auto t0 = Clock::now();
        run();
        t.push_back(seconds_since(t0));
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

// ---- 1. random layered Horn theories --------------------------------------------------------
struct TheoryStats {
    std::size_t envs = 0, label_envs = 0, nogoods = 0;
};

TheoryStats random_theory(std::uint32_t seed, int assumptions, int nodes, int clauses) {
    std::mt19937 rng(seed);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    Atms atms;
    std::vector<NodeId> all;
    for (int i = 0; i < assumptions; ++i) all.push_back(atms.add_assumption(DatumId{0}));
    for (int i = 0; i < nodes; ++i) all.push_back(atms.add_node(DatumId{0}));
    for (int c = 0; c < clauses; ++c) {
        // Consequent: a derived node; antecedents: 1-3 earlier nodes, each an assumption with
        // probability 1/3, else a derived node from the 30 before the consequent (a layered
        // theory, so labels stay bounded, with chains as rules make them).
        const int cons = pick(assumptions + 1, assumptions + nodes - 1);
        std::vector<NodeId> ants;
        for (int k = pick(1, 3); k > 0; --k) {
            const int i = pick(0, 2) == 0 ? pick(0, assumptions - 1) : pick(std::max(assumptions, cons - 30), cons - 1);
            ants.push_back(all[static_cast<std::size_t>(i)]);
        }
        if (pick(0, 99) < 4) atms.add_nogood(InformantId{0}, ants);
        else atms.justify(InformantId{0}, ants, all[static_cast<std::size_t>(cons)]);
    }
    TheoryStats s;
    s.envs = atms.environment_count();
    s.nogoods = atms.minimal_nogoods().size();
    for (NodeId n : all) s.label_envs += atms.label(n).size();
    return s;
}

// ---- 2/3. N-queens on the ATMS ---------------------------------------------------------------
struct Queens {
    Atms atms;
    std::vector<std::vector<AssumptionId>> rows;
    explicit Queens(int n) : rows(static_cast<std::size_t>(n)) {
        std::vector<NodeId> node(static_cast<std::size_t>(n * n));
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) {
                const NodeId q = atms.add_assumption(DatumId{static_cast<std::uint32_t>(r * n + c)});
                node[static_cast<std::size_t>(r * n + c)] = q;
                rows[static_cast<std::size_t>(r)].push_back(*atms.assumption_of(q));
            }
        for (int r1 = 0; r1 < n; ++r1)
            for (int c1 = 0; c1 < n; ++c1)
                for (int r2 = r1 + 1; r2 < n; ++r2)
                    for (int c2 = 0; c2 < n; ++c2)
                        if (c1 == c2 || std::abs(r1 - r2) == std::abs(c1 - c2))
                            atms.add_nogood(InformantId{0}, {node[static_cast<std::size_t>(r1 * n + c1)],
                                                             node[static_cast<std::size_t>(r2 * n + c2)]});
    }
};

std::size_t queens_atms(int n) {
    Queens q(n);
    return q.atms.interpretations(q.rows).size();
}

std::size_t queens_streaming(int n) {
    Queens q(n);
    return q.atms.for_each_interpretation(q.rows, q.atms.empty_environment(),
                                          [](const Environment&) { return true; });
}

// ---- 4. the floor: bitmask backtracking --------------------------------------------------------
std::size_t queens_plain(int n, int row, std::uint32_t cols, std::uint32_t d1, std::uint32_t d2) {
    if (row == n) return 1;
    std::size_t count = 0;
    std::uint32_t free = ~(cols | d1 | d2) & ((1U << n) - 1);
    while (free != 0) {
        const std::uint32_t bit = free & (~free + 1);
        free ^= bit;
        count += queens_plain(n, row + 1, cols | bit, (d1 | bit) << 1, (d2 | bit) >> 1);
    }
    return count;
}
}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const int max_n = quick ? 10 : 12;
    static const std::size_t expected[] = {0, 1, 0, 0, 2, 10, 4, 40, 92, 352, 724, 2680, 14200};

    std::printf("== label propagation: random layered Horn theories (median of 5) ==\n");
    std::printf("%10s %8s %8s %10s %10s %8s %10s\n", "assumpt.", "nodes", "clauses", "envs", "label envs",
                "nogoods", "ms");
    for (int scale = 1; scale <= (quick ? 8 : 32); scale *= 2) {
        const int a = 20 * scale, nodes = 100 * scale, clauses = 200 * scale;
        TheoryStats s;
        const double t = median_seconds(5, [&] { s = random_theory(42, a, nodes, clauses); });
        std::printf("%10d %8d %8d %10zu %10zu %8zu %10.2f\n", a, nodes, clauses, s.envs, s.label_envs, s.nogoods,
                    t * 1e3);
    }
    std::printf("peak RSS so far: %ld KiB\n\n", peak_rss_kib());

    std::printf("== N-queens as interpretations (build + nogoods + enumerate + intern) ==\n");
    std::printf("%3s %9s %14s %14s %14s\n", "N", "solutions", "atms ms", "streaming ms", "plain ms");
    for (int n = 4; n <= max_n; ++n) {
        const int reps = quick ? 3 : (n <= 10 ? 9 : 5);
        std::size_t got = 0, streamed = 0, plain = 0;
        const double t_atms = median_seconds(reps, [&] { got = queens_atms(n); });
        const double t_stream = median_seconds(reps, [&] { streamed = queens_streaming(n); });
        const double t_plain = median_seconds(reps, [&] { plain = queens_plain(n, 0, 0, 0, 0); });
        std::printf("%3d %9zu %14.3f %14.3f %14.3f%s\n", n, got, t_atms * 1e3, t_stream * 1e3, t_plain * 1e3,
                    got == expected[n] && streamed == expected[n] && plain == expected[n] ? "" : "  WRONG COUNT");
    }
    std::printf("peak RSS: %ld KiB\n", peak_rss_kib());
    return 0;
}
