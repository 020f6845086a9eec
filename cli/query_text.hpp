// cli/query_text.hpp
// Provides:   query_text(), which accepts a --why/--without/`why` query in either spelling of the output:
//             the thesis notation (`Rotational-Motion (follower (-))`, quotes around a direction
//             allowed) or the JSON of --json, as one motion or freedom entry:
//               {"follower": {"rotation": "(-)"}}                 Rotational-Motion (follower (-))
//               {"block": {"translation": "(0 -)"}}               Translational-Motion (block (0 -))
//               {"freedom": {"block": {"translation": "(0 +)"}}}  Translational-Freedom (block (0 +))
//             and returns the thesis notation, which scene::parse_query_fact reads and checks.
// Errors:     a malformed JSON spelling is reported as `ORIGIN:1:COL: error: expected ... but found ...`.
#pragma once
#include "qm/diagnostics.hpp"
#include <optional>
#include <string>
#include <string_view>

namespace qm::cli {
[[nodiscard]] std::optional<std::string> query_text(std::string_view text, const std::string& origin,
                                                    Diagnostics& diagnostics);
}
