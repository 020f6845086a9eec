// cli/draw_command.hpp
// Provides:   draw_command(), `qm-atms draw METRIC-SCENE [--config 'PART=VALUE, ...' | --place A--B:ID]
//             --svg FILE [--size WxH] [--cache DIR | --no-cache]` (docs/METRIC_SCENE_FORMAT.md,
//             "Drawings"): the parts as drawn at a configuration (CONFIG as for --emit-def:
//             degrees for rotations, offsets for translations; every part, with the contacts of
//             every kinematic pair there), or the two parts of a pair at the sample configuration
//             of one of its places (geometry/place_sample.hpp; ids as in `--places --json`), in
//             the look of the configuration-space pictures (geometry/part_svg.hpp).
// Errors:     bad input (scene, CONFIG, an unknown pair or place, bad options, a file that cannot
//             be written) goes to `err` as `file:line:col: error: ...` or a usage line; returns 2.
//             Parts that overlap at the configuration are drawn, with a warning naming them.
//             qm::InternalError propagates to main (exit 1).
#pragma once
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {

// args: the arguments after `draw`.
[[nodiscard]] int draw_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace qm::cli
