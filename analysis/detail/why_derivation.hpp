// analysis/detail/why_derivation.hpp (internal to analysis/)
// Provides:   the reasons of a --why answer as derivation trees read off ATMS explanations
//             (atms/explanation.hpp): explain_nogood() and explain_holding() give an Exclusion, the
//             tree naming the law (rule, file:line, citation, bindings) at every step down to the
//             scene's items, premises and assumptions, with the items it rests on;
//             order_by_relevance() orders nogoods for the answer; located() prints a location.
// Ownership:  values; the State is borrowed for the call.
// Knows the scene's items and the laws' firings, not which motion is asked about.
#pragma once
#include "analysis/detail/analysis_state.hpp"
#include <string>
#include <vector>

namespace qm::analysis::detail {

// "file:line".
[[nodiscard]] std::string located(const SourceLocation& w);

// The derivation of the contradiction from `nogood`, and the scene items it rests on (those of the
// nogood; with one assumption per situation, those the derivation uses: sufficient, maybe not minimal).
[[nodiscard]] Exclusion explain_nogood(const Analysis::State& st, atms::EnvId nogood);

// The derivation of node n in label_env (one of its label's environments), and the items it rests on
// (as explain_nogood). Pre: n holds in label_env.
[[nodiscard]] Exclusion explain_holding(const Analysis::State& st, atms::NodeId n, atms::EnvId label_env);

// Most relevant first: nogoods with the queried motion a, then those naming scene items, smaller
// ones first; otherwise in the order given (a stable sort).
void order_by_relevance(const Analysis::State& st, std::vector<atms::EnvId>& nogoods, atms::AssumptionId a);

}  // namespace qm::analysis::detail
