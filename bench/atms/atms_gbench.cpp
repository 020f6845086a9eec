// bench/atms/atms_gbench.cpp: the N-queens benchmark of atms_bench under Google Benchmark, for
// its statistics (repetitions, aggregates, JSON output: --benchmark_repetitions=9
// --benchmark_format=json). Variants per N, each encoding (queens.hpp: pairwise nogoods or
// at-most-one constraints): the whole run (build, enumerate and intern every interpretation) and the
// streaming enumeration alone on a built ATMS; and the plain backtracking floor. The solution count
// is a counter, so a wrong answer shows in the report.
#include "queens.hpp"

#include <benchmark/benchmark.h>

namespace {
using qm::atms::Environment;
using qm::atms::bench::Encoding;
using qm::atms::bench::Queens;
using qm::atms::bench::queens_plain;

template <Encoding E>
void whole_run(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    std::size_t solutions = 0;
    for (auto _ : state) {
        Queens q(n, E);
        solutions = q.atms.interpretations(q.rows).size();
        benchmark::DoNotOptimize(solutions);
    }
    state.counters["solutions"] = static_cast<double>(solutions);
}

template <Encoding E>
void enumeration_only(benchmark::State& state) {
    Queens q(static_cast<int>(state.range(0)), E);
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

BENCHMARK(whole_run<Encoding::pairwise>)->Name("whole_run/pairwise")->DenseRange(4, 12)->Unit(benchmark::kMillisecond);
BENCHMARK(whole_run<Encoding::at_most_one>)->Name("whole_run/at_most_one")->DenseRange(4, 14)->Unit(benchmark::kMillisecond);
BENCHMARK(enumeration_only<Encoding::pairwise>)->Name("enumeration_only/pairwise")->DenseRange(4, 12)->Unit(benchmark::kMillisecond);
BENCHMARK(enumeration_only<Encoding::at_most_one>)->Name("enumeration_only/at_most_one")->DenseRange(4, 14)->Unit(benchmark::kMillisecond);
BENCHMARK(plain_backtracking)->DenseRange(4, 14)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
