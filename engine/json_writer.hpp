// engine/json_writer.hpp
// Provides:   to_json(RunReport), exactly
//             {"facts": [{"fact": F, "label": [[A, ...], ...]}, ...], "nogoods": [[A, ...], ...],
//              "interpretations": [[A, ...], ...]}
//             with facts and assumptions as strings in the rule language's notation, in report order.
// Knows nothing of the ATMS.
#pragma once
#include "engine/run_report.hpp"
#include <string>
#include <string_view>

namespace qm::engine {
[[nodiscard]] std::string to_json(const RunReport& report);
// A JSON string literal for text (quotes, backslashes and control characters escaped).
[[nodiscard]] std::string json_string(std::string_view text);
}  // namespace qm::engine
