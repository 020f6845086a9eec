// engine/json_writer.hpp
// Provides:   to_json(RunReport), exactly
//             {"facts": [{"fact": F, "label": [[A, ...], ...]}, ...], "nogoods": [[A, ...], ...],
//              "interpretations": [[A, ...], ...]}
//             with facts and assumptions as strings in the rule language's notation, in report order;
//             and to_json(Why), the explanation of `qm-atms run --why FACT --json` (docs/RULES.md):
//             {"fact": F, "status": "holds" | "ruled-out" | "unsupported",
//              "derivations": [DERIVATION, ...], "nogoods": [DERIVATION, ...]}, DERIVATION being
//             {"environment": [A, ...], "steps": [{"fact": F, "informant": TEXT, "binding": [TEXT, ...],
//              "antecedents": [F, ...], "not": [F, ...]}, ...]} with the steps leaves first, as the text
//             form prints them ("not": the `not` conditions the firing relied on, its "and not" lines).
// Strings are written by the project's one JSON string writer (qm/json.hpp).
// Knows nothing of the ATMS.
#pragma once
#include "engine/run_report.hpp"
#include "engine/why.hpp"
#include <string>

namespace qm::engine {
[[nodiscard]] std::string to_json(const RunReport& report);
[[nodiscard]] std::string to_json(const Why& why);
}  // namespace qm::engine
