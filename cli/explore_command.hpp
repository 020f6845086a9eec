// cli/explore_command.hpp
// Provides:   explore_command(), `qm-atms explore METRIC-SCENE -o DIR [--cache DIR | --no-cache]`
//             (docs/EXPLORER.md): writes DIR/index.html, DIR/explore.js and DIR/explore.css, a page
//             that works opened from disk with no network: each kinematic pair's configuration
//             space with its places (geometry/cspace_svg.hpp); pointing at or selecting a place
//             shows its kind, normals, adjacency under each motion (8.1.3) and the two parts drawn
//             at its sample configuration (geometry/part_svg.hpp). The page's data is one JSON
//             blob in index.html (schema qm-explore/1), with room for the envisionment
//             (qm-envisionment/1) once the envisioner writes one.
// Errors:     bad input (scene, options, a folder that cannot be written) goes to `err`; returns 2.
//             qm::InternalError propagates to main (exit 1).
#pragma once
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {

// args: the arguments after `explore`.
[[nodiscard]] int explore_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace qm::cli
