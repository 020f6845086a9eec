// engine/run_report.hpp
// Provides:   RunReport, what `qm-atms run` shows after a run: every fact with its label, the
//             minimal nogoods (a choice set's pairwise ones summarised when it is large) and the
//             interpretations of the declared choice sets, all written in
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

// A choice set of more members than this has its pairwise nogoods summarised, not listed: S members
// make S(S-1)/2 of them (docs/RULES.md, "How `qm-atms run` shows results").
inline constexpr std::size_t listed_choice_set_limit = 64;

struct RunReport {
    struct FactLine {
        std::string fact;
        std::vector<EnvText> label;  // empty: the fact holds in no consistent environment
    };
    // A choice set whose pairwise nogoods are not among `nogoods` (more than
    // listed_choice_set_limit members).
    struct UnlistedChoiceSet {
        EnvText members;     // in fact order
        std::string where;   // the `exactly one` that declared it, file:line:col
        std::size_t nogoods; // its minimal pairwise nogoods: pairs of members each consistent alone
    };
    std::vector<FactLine> facts;
    std::vector<EnvText> nogoods;
    std::vector<UnlistedChoiceSet> unlisted;
    std::vector<EnvText> interpretations;
};

// Pre: the engine has been run.
[[nodiscard]] RunReport make_report(Engine& engine);

// The facts of the engine in report order.
[[nodiscard]] std::vector<FactId> facts_in_order(const Engine& engine);
// An environment in report form.
[[nodiscard]] EnvText env_text(const Engine& engine, atms::EnvId env);
[[nodiscard]] EnvText env_text(const Engine& engine, const atms::Environment& env);
}  // namespace qm::engine
