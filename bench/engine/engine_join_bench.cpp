// bench/engine/engine_join_bench.cpp
// The two-state join of an envisionment written as rules (STYLE.md section 8: prints numbers,
// passes or fails nothing): S states in one `exactly one` choice, each with its place, places in
// a chain of adjacencies, and the rule
//   when (state ?a) (state ?b) (place-of ?a ?p) (place-of ?b ?q) (adjacent ?p ?q) then (next ?a ?b)
// Written order scans every state for ?b under each seed (the adjacency's seeds scan both: S cubed
// in all); matched bound first (engine/match_plan.hpp) each seed costs what it matches. Timed:
// Engine construction and the run to quiescence, the program read and compiled outside; medians of
// REPS runs, with the time per state, so that growth faster than S log S shows as a rising column.
// Usage: engine_join_bench [REPS]   (default 5)
#include "engine/engine.hpp"
#include "engine/rule_checker.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace qm::engine;
using Clock = std::chrono::steady_clock;

namespace {

std::string join_text(int states) {
    std::string t = "fact (start)\n";
    for (int i = 1; i <= states; ++i) {
        const std::string s = std::to_string(i);
        t += "fact (state s" + s + ")\nfact (place-of s" + s + " p" + s + ")\n";
        if (i < states) t += "fact (adjacent p" + s + " p" + std::to_string(i + 1) + ")\n";
    }
    t += "rule pick\n  when (start)\n  then [exactly one ?s in (range 1 " + std::to_string(states) +
         "): assume (current ?s)]\n"
         "rule next\n  when (state ?a) (state ?b) (place-of ?a ?p) (place-of ?b ?q) (adjacent ?p ?q)\n"
         "  then (next ?a ?b)\n";
    return t;
}

LoadedProgram load(const std::string& text) {
    ProgramSpec spec;
    qm::Diagnostics d;
    read_rule_text(text, "join.rules", spec, d);
    if (d.has_errors() || !check_program(spec, d)) std::abort();
    auto p = compile_program(spec, d);
    if (!p) std::abort();
    return std::move(*p);
}

}  // namespace

int main(int argc, char** argv) {
    const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    std::printf("%8s %8s %10s %12s\n", "S", "facts", "median_ms", "us_per_state");
    for (int states : {1000, 3000, 10000, 30000, 100000}) {
        const std::string text = join_text(states);
        std::vector<double> ms;
        std::size_t found = 0;
        for (int r = 0; r < reps; ++r) {
            LoadedProgram p = load(text);
            const auto t0 = Clock::now();
            Engine e(std::move(p.program), std::move(p.values));
            qm::Diagnostics d;
            e.run(d);
            ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
            found = e.facts().size();
        }
        std::sort(ms.begin(), ms.end());
        const double m = ms[ms.size() / 2];
        std::printf("%8d %8zu %10.1f %12.2f\n", states, found, m, 1000.0 * m / states);
    }
    return 0;
}
