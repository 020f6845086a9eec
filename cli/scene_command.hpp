// cli/scene_command.hpp
// Provides:   scene_command(), `qm-atms SCENE.def [options]`: reads an Alex scene (docs/SCENE_FORMAT.md),
//             analyses it with the laws of rules/ and prints, per situation, the free directions,
//             every consistent combination of motions and the stability verdict (thesis notation, or
//             JSON with --json, docs/OUTPUT.md); --why explains a motion or freedom; --without takes
//             contacts or forces away; --given adds current motions; -i answers queries interactively.
// Errors:     returns 2 for bad input (diagnostics on err as file:line:col: error: ...), 0 otherwise;
//             qm::InternalError propagates to main (exit 1).
#pragma once
#include <istream>
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {
[[nodiscard]] int scene_command(std::span<const std::string> args, std::istream& in, std::ostream& out,
                                std::ostream& err);
[[nodiscard]] std::string scene_usage();
}  // namespace qm::cli
