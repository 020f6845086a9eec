// cli/metric_command.hpp
// Provides:   the metric-scene commands of qm-atms (docs/METRIC_SCENE_FORMAT.md):
//             - `qm-atms --emit-def METRIC-SCENE [CONFIG]`: the Alex scene (docs/SCENE_FORMAT.md) of
//               the parts at configuration CONFIG (`part=value, ...`: degrees for rotations,
//               lengths for translations, unnamed parts as drawn), with one situation holding the
//               contacts detected there and the external forces acting there;
//             - `qm-atms --places METRIC-SCENE [--json] [--svg DIR] [--cache DIR | --no-cache]`:
//               the place vocabulary of each kinematic pair (Def 20), from the on-disk cache when
//               the same pair and settings were computed before (8.1.3);
//             The Alex scene itself is built by bridge/scene_at_config.hpp (also for `qm-atms
//             METRIC-SCENE --config CONFIG`, cli/scene_command.cpp); this file only prints it.
// Errors:     bad input (scene, CONFIG, parts overlapping at CONFIG, bad options) goes to `diags`
//             / `err` as `file:line:col: error: ...` with the source line and a caret; the
//             commands then return 2. Warnings (a pair with no free space) are printed and do
//             not fail. Corners in contact are written as Alex corners (Def 18).
//             qm::InternalError propagates to main (exit 1).
#pragma once
#include "qm/diagnostics.hpp"
#include <optional>
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {


// args: the arguments after `--emit-def` / `--places`.
[[nodiscard]] int emit_def_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);
[[nodiscard]] int places_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace qm::cli
