// cli/scene_command.hpp
// Provides:   scene_command(), `qm-atms SCENE.def [options]`: reads an Alex scene (docs/SCENE_FORMAT.md),
//             analyses it with the laws of rules/ and prints, per situation, the free directions,
//             every consistent combination of motions and the stability verdict (thesis notation, or
//             JSON with --json, docs/OUTPUT.md); --why explains a motion or freedom; --without takes
//             contacts or forces away; --given adds current motions; -i answers queries interactively.
//             A metric scene (cli/geometry_dispatch.hpp, is_metric_scene()) is analysed at --config
//             through `read_metric` (bridge::read_scene_at_config, in qm-atms-geometry only).
// Errors:     returns 2 for bad input (diagnostics on err as file:line:col: error: ...), 0 otherwise;
//             qm::InternalError propagates to main (exit 1).
#pragma once
#include "qm/diagnostics.hpp"
#include "scene/scene.hpp"
#include <istream>
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {
// Reads a metric scene at a configuration ('part=value, ...') into an Alex scene, errors in the
// Diagnostics: bridge::read_scene_at_config (bridge/scene_at_config.hpp). The light qm-atms, which
// links no geometry, has none and passes a metric scene on to qm-atms-geometry before this runs.
using MetricSceneReader = std::optional<scene::Scene> (*)(const std::string& path, const std::string& config, Diagnostics& d);

// read_metric: null in the light executable (a metric scene is then an error).
[[nodiscard]] int scene_command(std::span<const std::string> args, std::istream& in, std::ostream& out,
                                std::ostream& err, MetricSceneReader read_metric = nullptr);
[[nodiscard]] std::string scene_usage();
}  // namespace qm::cli
