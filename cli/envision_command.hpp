// cli/envision_command.hpp
// Provides:   `qm-atms envision MECH.def [options]`, the Clock envisioner at the command line
//             (docs/ENVISION.md): every mechanical state and transition of each kinematic chain of a
//             metric mechanism (docs/METRIC_SCENE_FORMAT.md), as text, as the transition table of the
//             thesis' Appendices A-D (--table), or as JSON (--json, schema qm-envisionment/1).
//             Options: --max-states N (default 1000000), --max-memory SIZE (cli/resource_limits.hpp),
//             --without 'Force PART [CAUSE]' (repeatable), --cache DIR | --no-cache (place
//             vocabularies), --rules DIR (the laws; default the rules/clock folder beside the other
//             laws), --stats (timings on stderr).
// Errors:     bad input (the scene, the options, the laws' files) is reported on `err` as
//             `file:line:col: error: ...` and the command returns 2, having written nothing on
//             `out` and no file. So is a limit reached (--max-states, --max-memory), as
//             `qm-atms: error: state limit 1500 reached while finding the states of chain 2 of
//             clock.def (after 0.4 s: 1500 states and 2352 transitions found); raise it with
//             --max-states`. A progress line
//             (cli/progress_bar.hpp) goes to stderr when it is a terminal and the run takes more
//             than a second. qm::InternalError propagates to main (exit 1).
#pragma once
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {
// args: the arguments after `envision`.
[[nodiscard]] int envision_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);
}  // namespace qm::cli
