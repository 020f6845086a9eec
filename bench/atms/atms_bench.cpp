// bench/atms/atms_bench.cpp
// Prints numbers, passes or fails nothing (STYLE.md section 8); docs/PERFORMANCE.md records them.
//   1. label propagation on seeded random Horn theories of growing size, two families:
//      local  fixed depth (8 layers of derived nodes over a layer of assumptions), growing width;
//             each node's justifications draw on nearby nodes of the layer below, so labels stay
//             bounded and the cost should grow with the theory;
//      deep   a layered window theory whose derivation depth grows with its size (antecedents from
//             the 30 nodes before the consequent), so labels grow combinatorially: the sizes listed
//             are the ones that finish (from 6x the smallest on, a run takes minutes: labels any
//             ATMS keeping them complete must compute);
//      clauses are given in random order, so labels are revised, not built bottom-up;
//   2. N-queens as ATMS interpretations, N = 4 ... 14 (queens.hpp, the at-most-one encoding): the
//      whole run (build the ATMS, enumerate and intern every solution), against a plain bitmask
//      backtracking N-queens, the floor; atms_gbench times each encoding and step apart;
//   3. interpretations on a base environment (base_queries.hpp): 200 queries of an envisioner's
//      kind (places of kinematic pairs x motions of objects, on top of a state's facts), each
//      streamed up to 5,000 interpretations;
//   4. peak memory: each theory and N-queens configuration runs once more while the resident set's
//      peak is watched (peak_growth_kib: how far the run raises RSS above its starting point).
// Times are wall-clock medians (and minima) of several repetitions on one thread.
// stdout is line buffered, so a run piped into a file or `tee` shows each row when it is done.
// Usage: atms_bench [--quick] [--queens | --theories | --bases]   (--quick: fewer repetitions,
//        smaller sizes, N up to 10; --queens, --theories, --bases: only that part)
#include "atms/atms.hpp"
#include "base_queries.hpp"
#include "queens.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <random>
#include <malloc.h>
#include <memory>
#include <string>
#include <vector>

using namespace qm::atms;
using qm::atms::bench::BaseQueries;
using qm::atms::bench::Encoding;
using qm::atms::bench::Queens;
using qm::atms::bench::queens_plain;
using Clock = std::chrono::steady_clock;

namespace {
struct Timing {
    double median_ms = 0, min_ms = 0;
};

template <class F>
Timing time_runs(int reps, F&& run) {
    std::vector<double> t;
    for (int i = 0; i < reps; ++i) {
        const auto t0 = Clock::now();
        run();
        t.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    std::sort(t.begin(), t.end());
    return {t[t.size() / 2], t.front()};
}

// A field of /proc/self/status in KiB (VmRSS, VmHWM), or -1.
long status_kib(const char* field) {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (f == nullptr) return -1;
    char line[256];
    long kib = -1;
    const std::size_t len = std::strlen(field);
    while (std::fgets(line, sizeof line, f) != nullptr)
        if (std::strncmp(line, field, len) == 0 && line[len] == ':') kib = std::atol(line + len + 1);
    std::fclose(f);
    return kib;
}

// How far one run of f raises the resident set above where it started, in KiB: free heap is
// returned to the kernel first (malloc_trim), then the peak-RSS mark is reset to the current RSS
// (writing 5 to /proc/self/clear_refs, Linux >= 4.0) and read back after the run. -1 if the
// kernel does not allow the reset.
template <class F>
long peak_growth_kib(F&& f) {
    malloc_trim(0);
    std::FILE* c = std::fopen("/proc/self/clear_refs", "w");
    if (c == nullptr) return -1;
    const bool reset = std::fputs("5", c) >= 0;
    if (std::fclose(c) != 0 || !reset) return -1;
    const long before = status_kib("VmRSS");
    f();
    const long peak = status_kib("VmHWM");
    return before < 0 || peak < 0 ? -1 : peak - before;
}

// ---- 1. random Horn theories ---------------------------------------------------------------------
struct Clause {
    std::vector<NodeId> antecedents;
    std::optional<NodeId> consequent;  // none: a nogood
};

struct TheoryStats {
    std::size_t assumptions = 0, nodes = 0, clauses = 0, envs = 0, label_envs = 0, max_label = 0, nogoods = 0;
};

TheoryStats finish(Atms& atms, const std::vector<Clause>& clauses) {
    for (const Clause& c : clauses) {
        if (c.consequent) atms.justify(InformantId{0}, c.antecedents, *c.consequent);
        else atms.add_nogood(InformantId{0}, c.antecedents);
    }
    TheoryStats s;
    s.assumptions = atms.assumption_count();
    s.nodes = atms.node_count();
    s.clauses = clauses.size();
    s.envs = atms.environment_count();
    s.nogoods = atms.minimal_nogoods().size();
    for (std::uint32_t n = 0; n < atms.node_count(); ++n) {
        s.label_envs += atms.label(NodeId{n}).size();
        s.max_label = std::max(s.max_label, atms.label(NodeId{n}).size());
    }
    return s;
}

// Layer 0: `width` assumptions; layers 1..8: `width` derived nodes each. Node i of layer k gets
// 1-3 justifications, each from 1-2 nodes of layer k-1 within 2 places of i (cyclically) and,
// one time in four, an assumption near i too; width/4 nogoods between nearby nodes of layers 0-2.
TheoryStats local_theory(std::uint32_t seed, int width) {
    constexpr int depth = 8, reach = 2;
    std::mt19937 rng(seed);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    Atms atms;
    std::vector<std::vector<NodeId>> layer(depth + 1);
    for (int i = 0; i < width; ++i) layer[0].push_back(atms.add_assumption(DatumId{0}));
    for (int k = 1; k <= depth; ++k)
        for (int i = 0; i < width; ++i) layer[static_cast<std::size_t>(k)].push_back(atms.add_node(DatumId{0}));
    auto near = [&](int k, int i) {
        const int j = ((i + pick(-reach, reach)) % width + width) % width;
        return layer[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)];
    };
    std::vector<Clause> clauses;
    for (int k = 1; k <= depth; ++k)
        for (int i = 0; i < width; ++i)
            for (int j = pick(1, 3); j > 0; --j) {
                Clause c{{}, layer[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)]};
                for (int f = pick(1, 2); f > 0; --f) c.antecedents.push_back(near(k - 1, i));
                if (pick(0, 3) == 0) c.antecedents.push_back(near(0, i));
                clauses.push_back(std::move(c));
            }
    for (int g = 0; g < width / 4; ++g) {
        const int i = pick(0, width - 1);
        clauses.push_back(Clause{{near(pick(0, 2), i), near(pick(0, 2), i)}, std::nullopt});
    }
    std::shuffle(clauses.begin(), clauses.end(), rng);
    return finish(atms, clauses);
}

// `assumptions` assumptions, `nodes` derived nodes, `count` clauses: each concludes a random
// derived node from 1-3 antecedents, each an assumption with probability 1/3, else one of the 30
// derived nodes before the consequent; 4% of the clauses are nogoods instead.
TheoryStats deep_theory(std::uint32_t seed, int assumptions, int nodes, int count) {
    std::mt19937 rng(seed);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    Atms atms;
    std::vector<NodeId> all;
    for (int i = 0; i < assumptions; ++i) all.push_back(atms.add_assumption(DatumId{0}));
    for (int i = 0; i < nodes; ++i) all.push_back(atms.add_node(DatumId{0}));
    std::vector<Clause> clauses;
    for (int c = 0; c < count; ++c) {
        const int cons = pick(assumptions + 1, assumptions + nodes - 1);
        Clause clause{{}, all[static_cast<std::size_t>(cons)]};
        for (int k = pick(1, 3); k > 0; --k) {
            const int i = pick(0, 2) == 0 ? pick(0, assumptions - 1) : pick(std::max(assumptions, cons - 30), cons - 1);
            clause.antecedents.push_back(all[static_cast<std::size_t>(i)]);
        }
        if (pick(0, 99) < 4) clause.consequent.reset();
        clauses.push_back(std::move(clause));
    }
    return finish(atms, clauses);
}

void print_theory_header() {
    std::printf("%8s %7s %7s %8s %9s %9s %7s %10s %10s %10s %9s\n", "assumpt.", "nodes", "clauses", "envs",
                "label env", "max label", "nogoods", "median ms", "min ms", "us/clause", "peak KiB");
}

template <class F>
void theory_row(int reps, F&& build) {
    TheoryStats s;
    const Timing t = time_runs(reps, [&] { s = build(); });
    const long peak = peak_growth_kib([&] { (void)build(); });
    std::printf("%8zu %7zu %7zu %8zu %9zu %9zu %7zu %10.2f %10.2f %10.2f %9ld\n", s.assumptions, s.nodes,
                s.clauses, s.envs, s.label_envs, s.max_label, s.nogoods, t.median_ms, t.min_ms,
                1e3 * t.median_ms / static_cast<double>(s.clauses), peak);
}

// ---- 2. N-queens on the ATMS -------------------------------------------------------------------
void theory_tables(bool quick) {
    const int reps = quick ? 3 : 7;
    std::printf("== label propagation, local theories: 8 layers, growing width (median of %d) ==\n", reps);
    print_theory_header();
    for (int width = 100; width <= (quick ? 1600 : 6400); width *= 2)
        theory_row(reps, [&] { return local_theory(7, width); });

    std::printf("\n== label propagation, deep theories: depth grows with size (median of %d) ==\n", reps);
    print_theory_header();
    for (int s = 1; s <= (quick ? 4 : 5); ++s)
        theory_row(reps, [&] { return deep_theory(42, 20 * s, 100 * s, 200 * s); });
}

const std::size_t queens_solutions[] = {0, 1, 0, 0, 2, 10, 4, 40, 92, 352, 724, 2680, 14200, 73712, 365596};

void queens_table(bool quick) {
    std::printf("\n== N-queens as interpretations, at-most-one encoding: ms, median of runs (plain: the floor) ==\n");
    std::printf("%3s %9s %9s %9s %8s %9s\n", "N", "solutions", "plain", "amo whole", "whole/pl", "peak KiB");
    for (int n = 4; n <= (quick ? 10 : 14); ++n) {
        const int r = quick ? 3 : (n <= 10 ? 9 : n <= 12 ? 5 : 3);
        std::size_t plain = 0, solutions = 0;
        const Timing t_plain = time_runs(r, [&] { plain = queens_plain(n, 0, 0, 0, 0); });
        auto whole = [&] {
            Queens q(n, Encoding::at_most_one);
            solutions = q.atms.interpretations(q.rows).size();
        };
        const Timing t = time_runs(r, whole);
        const long peak = peak_growth_kib(whole);
        const bool right = plain == queens_solutions[n] && solutions == queens_solutions[n];
        std::printf("%3d %9zu %9.3f %9.3f %8.1f %9ld%s\n", n, solutions, t_plain.median_ms, t.median_ms,
                    t.median_ms / t_plain.median_ms, peak, right ? "" : "  WRONG COUNT");
    }
}

// Interpretations on a base environment (base_queries.hpp): 200 queries on one theory, each
// streamed up to 5,000 interpretations; the time of all of them, and per query.
void base_table(bool quick) {
    const int reps = quick ? 3 : 5;
    std::printf("\n== interpretations on a base environment: 200 queries, each up to 5,000 (median of %d) ==\n", reps);
    std::printf("%6s %8s %12s %10s %12s %12s\n", "pairs", "objects", "build ms", "visited", "queries ms", "us/query");
    for (auto [pairs, objects] : {std::pair{4, 2}, std::pair{8, 4}, std::pair{16, 8}}) {
        if (quick && pairs > 8) break;
        std::size_t visited = 0;
        std::unique_ptr<BaseQueries> q;
        const Timing build = time_runs(reps, [&] { q = std::make_unique<BaseQueries>(11, pairs, objects, 200); });
        const Timing t = time_runs(reps, [&] { visited = q->run(5000); });
        std::printf("%6d %8d %12.2f %10zu %12.2f %12.1f\n", pairs, objects, build.median_ms, visited, t.median_ms,
                    1e3 * t.median_ms / 200.0);
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    bool quick = false, theories = true, queens = true, bases = true;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--quick") == 0) {
            quick = true;
        } else if (std::strcmp(argv[i], "--queens") == 0) {
            theories = bases = false;
        } else if (std::strcmp(argv[i], "--theories") == 0) {
            queens = bases = false;
        } else if (std::strcmp(argv[i], "--bases") == 0) {
            theories = queens = false;
        } else {
            std::fprintf(stderr, "usage: atms_bench [--quick] [--queens | --theories | --bases]\n");
            return 2;
        }
    }
    if (theories) theory_tables(quick);
    if (queens) queens_table(quick);
    if (bases) base_table(quick);
    return 0;
}
