// bench/atms/atms_gbench.cpp: the N-queens benchmark of atms_bench under Google Benchmark, for
// its statistics (repetitions, aggregates, JSON output: --benchmark_repetitions=9
// --benchmark_format=json). Three variants per N: the whole ATMS run (build, nogoods, enumerate and
// intern every interpretation), the streaming enumeration alone on a built ATMS, and the plain
// backtracking floor. The solution count is a counter, so a wrong answer shows in the report.
#include "queens.hpp"

#include <benchmark/benchmark.h>

namespace {
using qm::atms::Environment;
using qm::atms::bench::Queens;
using qm::atms::bench::queens_plain;

void whole_run(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    std::size_t solutions = 0;
    for (auto _ : state) {
        Queens q(n);
        solutions = q.atms.interpretations(q.rows).size();
        benchmark::DoNotOptimize(solutions);
    }
    state.counters["solutions"] = static_cast<double>(solutions);
}

void enumeration_only(benchmark::State& state) {
    Queens q(static_cast<int>(state.range(0)));
    std::size_t solutions = 0;
    for (auto _ : state) {
        solutions = q.atms.for_each_interpretation(q.rows, q.atms.empty_environment(), [](const Environment&) { return true; });
        benchmark::DoNotOptimize(solutions);
    }
    state.counters["solutions"] = static_cast<double>(solutions);
}

void plain_backtracking(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    std::size_t solutions = 0;
    for (auto _ : state) {
        solutions = queens_plain(n, 0, 0, 0, 0);
        benchmark::DoNotOptimize(solutions);
    }
    state.counters["solutions"] = static_cast<double>(solutions);
}

}  // namespace

BENCHMARK(whole_run)->DenseRange(4, 12)->Unit(benchmark::kMillisecond);
BENCHMARK(enumeration_only)->DenseRange(4, 12)->Unit(benchmark::kMillisecond);
BENCHMARK(plain_backtracking)->DenseRange(4, 12)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
