// engine/run_report.hpp
// Provides:   RunReport, what `qm-atms run` shows after a run: every fact with its label, the
//             minimal nogoods and the interpretations of the declared choice sets, all written in
//             the rule language's notation and in a deterministic order (facts by predicate, then
//             arguments in ValueTable order; an environment's assumptions in fact order; environments
//             by size, then lexicographically). make_report() builds it; json_writer.hpp and
//             report_printer.hpp render it.
// Ownership:  a plain value, independent of the Engine once built.
// Knows nothing of mechanics.
#pragma once
#include "engine/engine.hpp"
#include <string>
#include <vector>

namespace qm::engine {
using EnvText = std::vector<std::string>;  // an environment: its assumptions as facts

struct RunReport {
    struct FactLine {
        std::string fact;
        std::vector<EnvText> label;  // empty: the fact holds in no consistent environment
    };
    std::vector<FactLine> facts;
    std::vector<EnvText> nogoods;
    std::vector<EnvText> interpretations;
};

// Pre: the engine has been run.
[[nodiscard]] RunReport make_report(Engine& engine);

// The facts of the engine in report order.
[[nodiscard]] std::vector<FactId> facts_in_order(const Engine& engine);
// An environment in report form.
[[nodiscard]] EnvText env_text(const Engine& engine, atms::EnvId env);
}  // namespace qm::engine
