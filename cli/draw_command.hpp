// cli/draw_command.hpp
// Provides:   draw_command(), `qm-atms draw METRIC-SCENE [--config 'PART=VALUE, ...' | --place A--B:ID |
//             --history 'STATE STATE ...' [--columns N]] --svg FILE [--size WxH] [--cache DIR | --no-cache]`
//             (docs/EXPLORER.md): the parts as drawn at a configuration (CONFIG as for --emit-def:
//             degrees for rotations, offsets for translations; every part, with the contacts of
//             every kinematic pair there), or the two parts of a pair at the sample configuration
//             of one of its places (geometry/place_sample.hpp; ids as in `--places --json`), in
//             the look of the configuration-space pictures (geometry/part_svg.hpp); or a history of
//             envisioned states, a drawing of the chain per state with its motions as arrows
//             (cli/state_drawing.hpp; the envisionment computed as `qm-atms envision` does).
// Errors:     bad input (scene, CONFIG, an unknown pair or place, bad options, a file that cannot
//             be written, a history that is not one: a state unknown, of another chain, or not
//             following the one before) goes to `err` as `file:line:col: error: ...` or a usage
//             line; returns 2.
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
