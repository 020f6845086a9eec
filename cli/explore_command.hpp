// cli/explore_command.hpp
// Provides:   explore_command(), `qm-atms explore METRIC-SCENE -o DIR [--no-envision | --path 'DESC; ...'...
//             [--avoid 'DESC']...] [--cache DIR | --no-cache]` (docs/EXPLORER.md): writes
//             DIR/index.html, DIR/explore.js, DIR/envision.js and DIR/explore.css, a page
//             that works opened from disk with no network: each kinematic pair's configuration
//             space with its places (geometry/cspace_svg.hpp); pointing at or selecting a place
//             shows its kind, normals, adjacency under each motion (8.1.3) and the two parts drawn
//             at its sample configuration (geometry/part_svg.hpp); and the envisionment (thesis
//             8-9, as `qm-atms envision` computes it): each chain's states as a graph grouped by
//             behavioural cycles and terminal states, a state's drawing with its motions and its
//             next and previous states, histories (and the paths of described behaviours, --path)
//             played state by state. The page's data is one JSON blob in index.html (schema
//             qm-explore/1) holding the envisioner's own qm-envisionment/1 JSON.
// Errors:     bad input (scene, options, a folder that cannot be written, a mechanism the
//             envisioner refuses, a bad --path) goes to `err`; returns 2.
//             qm::InternalError propagates to main (exit 1).
#pragma once
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {

// args: the arguments after `explore`.
[[nodiscard]] int explore_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace qm::cli
