// cli/scene_command.hpp
// Provides:   scene_command(), `qm-atms SCENE.def [options]`: reads an Alex scene (docs/SCENE_FORMAT.md),
//             analyses it with the laws of rules/ and prints, per situation, the free directions,
//             every consistent combination of motions and the stability verdict (thesis notation, or
//             JSON with --json, docs/OUTPUT.md); --why explains a motion or freedom; --without takes
//             contacts or forces away; --given adds current motions; -i answers queries interactively.
//             A metric scene (one that opens with `(Defmechanism`, is_metric_scene()) is analysed at
//             --config through bridge::read_scene_at_config.
// Errors:     returns 2 for bad input (diagnostics on err as file:line:col: error: ...), 0 otherwise;
//             qm::InternalError propagates to main (exit 1).
#pragma once
#include "qm/diagnostics.hpp"
#include "scene/scene.hpp"
#include <istream>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace qm::cli {
[[nodiscard]] int scene_command(std::span<const std::string> args, std::istream& in, std::ostream& out,
                                std::ostream& err);
// A metric scene (docs/METRIC_SCENE_FORMAT.md) opens with `(Defmechanism`, after a byte-order mark,
// blanks and `;` comments (the name in any case); an Alex scene (docs/SCENE_FORMAT.md) does not.
[[nodiscard]] bool is_metric_scene(std::string_view text);
[[nodiscard]] std::string scene_usage();
}  // namespace qm::cli
