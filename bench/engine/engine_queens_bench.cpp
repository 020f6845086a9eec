// bench/engine/engine_queens_bench.cpp
// N-queens (N = 4..10) solved two ways, median of repeated runs (STYLE.md section 8: prints
// numbers, passes or fails nothing):
//   bare   the ATMS API directly: one assumption per square, one choice set per row, a nogood per
//          pair of squares in one row and per attacking pair in different rows; timed: building
//          the ATMS, label propagation, enumerating every interpretation;
//   engine the rule program of scenarios/rules/queensN.rules (for N = 9, 10 the same text with N
//          replaced), read by the X3 front end, checked and compiled outside the timed region;
//          timed: Engine construction, run to quiescence, enumerating every interpretation;
//   load   reading (X3 parser), checking and compiling the program text, timed on its own.
// The ratio engine/bare is the engine's overhead; the target is <= 3x at N = 8. (load+engine)/bare
// ("e2e") is the end-to-end ratio of a rule program read from text. The three are measured in
// turn within each repetition; medians and minimums are printed.
// Usage: engine_queens_bench [REPS]   (default 9)
#include "engine/engine.hpp"
#include "engine/rule_checker.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_printer.hpp"
#include "engine/rule_spec_reader.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
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

// The text of scenarios/rules/queensN.rules, rules and facts only.
std::string queens_text(int n) {
    std::string t;
    for (int r = 1; r <= n; ++r) t += "fact (row " + std::to_string(r) + ")\n";
    t += "rule place\n  when (row ?r)\n  then [exactly one ?c in (range 1 " + std::to_string(n) +
         "): assume (queen ?r ?c)]\n"
         "rule same-column\n  when (queen ?r1 ?c) (queen ?r2 ?c) (< ?r1 ?r2)\n  then false\n"
         "rule same-diagonal\n  when (queen ?r1 ?c1) (queen ?r2 ?c2) (< ?r1 ?r2)\n"
         "       (= (abs (- ?r1 ?r2)) (abs (- ?c1 ?c2)))\n  then false\n";
    return t;
}

ProgramSpec read_text(const std::string& text) {
    ProgramSpec spec;
    qm::Diagnostics d;
    read_rule_text(text, "queens.rules", spec, d);
    if (d.has_errors()) std::abort();
    return spec;
}

LoadedProgram load(const std::string& text) {
    ProgramSpec spec = read_text(text);
    qm::Diagnostics d;
    if (!check_program(spec, d)) std::abort();
    auto p = compile_program(spec, d);
    if (!p) std::abort();
    return std::move(*p);
}

std::size_t engine_queens(LoadedProgram p) {
    Engine e(std::move(p.program), std::move(p.values));
    qm::Diagnostics d;
    e.run(d);
    return e.interpretations().size();
}

double elapsed_ms(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double median(std::vector<double> xs) {
    std::sort(xs.begin(), xs.end());
    return xs[xs.size() / 2];
}
double minimum(const std::vector<double>& xs) { return *std::min_element(xs.begin(), xs.end()); }

}  // namespace

int main(int argc, char** argv) {
    int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
    // The generated text is the bundled program: both read to the same spec.
    for (int n = 4; n <= 8; ++n) {
        ProgramSpec file;
        qm::Diagnostics d;
        read_rule_file(std::string(QM_SOURCE_DIR) + "/scenarios/rules/queens" + std::to_string(n) + ".rules", file, d);
        if (d.has_errors() || print_program(file) != print_program(read_text(queens_text(n)))) {
            std::fprintf(stderr, "queens%d.rules differs from the benchmark's program\n", n);
            return 1;
        }
    }
    // Medians, then minimums: on a loaded machine a run preempted by the scheduler costs a whole
    // time slice more, so the minimum shows the cost of the work itself.
    std::printf("%3s %9s | %8s %9s %7s %6s %6s | %8s %9s %6s\n", "N", "solutions", "bare_ms", "engine_ms",
                "load_ms", "ratio", "e2e", "bare_min", "engine_min", "ratio");
    for (int n = 4; n <= 10; ++n) {
        const std::string text = queens_text(n);
        // The three measurements are interleaved repetition by repetition, so that the load of the
        // shared machine at any moment weighs on all three alike.
        std::vector<double> bare, engine, loading;
        std::size_t a = 0, b = 0;
        for (int i = 0; i < reps; ++i) {
            auto t0 = Clock::now();
            a = bare_queens(n);
            bare.push_back(elapsed_ms(t0));
            LoadedProgram program = load(text);
            t0 = Clock::now();
            b = engine_queens(std::move(program));
            engine.push_back(elapsed_ms(t0));
            t0 = Clock::now();
            if (load(text).program.rules.size() != 3) std::abort();
            loading.push_back(elapsed_ms(t0));
        }
        const double mb = median(bare), me = median(engine), ml = median(loading);
        std::printf("%3d %9zu | %8.3f %9.3f %7.3f %6.2f %6.2f | %8.3f %9.3f %6.2f%s\n", n, a, mb, me, ml, me / mb,
                    (me + ml) / mb, minimum(bare), minimum(engine), minimum(engine) / minimum(bare),
                    a == b ? "" : "  MISMATCH");
    }
    return 0;
}
