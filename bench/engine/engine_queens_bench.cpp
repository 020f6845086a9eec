// bench/engine/engine_queens_bench.cpp
// N-queens (N = 4..10) solved two ways, timing the whole run (build, propagate, enumerate every
// interpretation), median of repeated runs:
//   bare   the ATMS API directly: one assumption per square, one choice set per row, a nogood per
//          attacking pair of squares in different rows (same row is the choice set's own nogood);
//   engine the rule program (rules place / same-column / same-diagonal, as in
//          scenarios/rules/queensN.rules), compiled and run by the Engine.
// The ratio engine/bare is the engine's overhead; the target is <= 3x at N = 8.
#include "compiled_program_builder.hpp"
#include "engine/engine.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace qm::engine;
using Clock = std::chrono::steady_clock;

namespace {

std::size_t bare_queens(int n) {
    qm::atms::Atms atms;
    std::vector<std::vector<qm::atms::NodeId>> square(n, std::vector<qm::atms::NodeId>(n));
    std::vector<std::vector<qm::atms::AssumptionId>> rows(n);
    std::uint32_t datum = 0;
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            square[r][c] = atms.add_assumption(qm::atms::DatumId{datum++});
            rows[r].push_back(*atms.assumption_of(square[r][c]));
        }
    qm::atms::InformantId why{0};
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
            for (int c2 = c + 1; c2 < n; ++c2) atms.add_nogood(why, {square[r][c], square[r][c2]});
    for (int r1 = 0; r1 < n; ++r1)
        for (int r2 = r1 + 1; r2 < n; ++r2)
            for (int c1 = 0; c1 < n; ++c1)
                for (int c2 = 0; c2 < n; ++c2)
                    if (c1 == c2 || std::abs(r1 - r2) == std::abs(c1 - c2))
                        atms.add_nogood(why, {square[r1][c1], square[r2][c2]});
    return atms.interpretations(rows).size();
}

std::size_t engine_queens(int n) {
    ValueTable v;
    CompiledProgram p = test::queens(v, n);
    Engine e(std::move(p), std::move(v));
    qm::Diagnostics d;
    e.run(d);
    return e.interpretations().size();
}

template <class F>
double median_ms(F&& f, int reps, std::size_t& answer) {
    std::vector<double> ms;
    for (int i = 0; i < reps; ++i) {
        auto t0 = Clock::now();
        answer = f();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    int reps = argc > 1 ? std::atoi(argv[1]) : 9;
    std::printf("%3s %10s %12s %12s %8s\n", "N", "solutions", "bare_ms", "engine_ms", "ratio");
    for (int n = 4; n <= 10; ++n) {
        std::size_t a = 0, b = 0;
        double bare = median_ms([&] { return bare_queens(n); }, reps, a);
        double engine = median_ms([&] { return engine_queens(n); }, reps, b);
        std::printf("%3d %10zu %12.3f %12.3f %8.2f%s\n", n, a, bare, engine, engine / bare,
                    a == b ? "" : "  MISMATCH");
    }
    return 0;
}
