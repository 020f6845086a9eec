// cli/state_drawing.hpp
// Provides:   what `draw --history` and `explore` share to draw a kinematic chain at an envisioned
//             state (thesis 9.2, the histories of Figures 9.25, 9.27, 9.28, 9.32):
//             - envision_for_drawing(): the envisionment with the default laws (rules/clock) and
//               the place cache, as `qm-atms envision` computes it (the same state ids);
//             - chain_drawn_parts(): the parts drawn for a chain: its objects, then any part of its
//               pairs that is no object (a fixed part);
//             - state_configuration(): a configuration at a state: each drawn part at the sample
//               configuration (geometry/place_sample.hpp) of its place in the first of the chain's
//               pairs that holds it. Each pair's places are sampled on their own, so two parts on
//               one shaft may be drawn at different angles, and a part of two pairs is where its
//               first pair puts it;
//             - parse_history(): `--history 'STATE STATE ...'` (ids: `12`, `#12`, `2:12`) or
//               `'STATE; STATE; ...'` (names as the outputs print them), every state of one
//               chain, each consecutive two joined by a transition;
//             - write_history_svg(): a strip of drawings of the chain, one per state of a history,
//               each with its contacts and its parts' motions as arrows, titled with the state's
//               name in the thesis' notation and the transition that led to it.
// Ownership:  values; the mechanism and the envisionment outlive the calls.
// Errors:     located diagnostics (`--history:1:COL: error: ...`) for a state that cannot be found,
//             states of two chains, a step with no transition; the envisioner's own errors.
#pragma once
#include "envision/envisionment.hpp"
#include "geometry/mechanism.hpp"
#include "geometry/part_svg.hpp"
#include "qm/diagnostics.hpp"

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace qm::cli {

[[nodiscard]] std::optional<qm::envision::Envisionment> envision_for_drawing(const qm::geometry::Mechanism& m, bool use_cache,
                                                                            const std::optional<std::filesystem::path>& cache_dir,
                                                                            Diagnostics& diags);

[[nodiscard]] std::vector<qm::geometry::PartId> chain_drawn_parts(const qm::envision::Envisionment& e, const qm::envision::ChainEnvisionment& c);

[[nodiscard]] qm::geometry::Configuration state_configuration(const qm::geometry::Mechanism& m, const qm::envision::Envisionment& e,
                                                              const qm::envision::ChainEnvisionment& c, qm::envision::StateId s);

struct History {
    std::size_t chain = 0;                         // index into Envisionment::chains
    std::vector<qm::envision::StateId> states;
};
[[nodiscard]] std::optional<History> parse_history(const qm::envision::Envisionment& e, const std::string& text, Diagnostics& diags);

// panel_width x panel_height pixels per state, `columns` drawings a row.
void write_history_svg(std::ostream& os, const qm::geometry::Mechanism& m, const qm::envision::Envisionment& e, const History& h,
                       int panel_width, int panel_height, std::size_t columns);

}  // namespace qm::cli
