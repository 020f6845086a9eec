// geometry/metric_scene_checker.hpp
// Provides:   check_mechanism (raw AST -> Mechanism) and check_configuration (raw CONFIG ->
//             Configuration): every semantic check of docs/METRIC_SCENE_FORMAT.md ("Checks"),
//             each reported at the item it concerns; parts' profiles are built (drawn or
//             generated), placed, oriented counter-clockwise and validated (profile_check.hpp).
// Ownership:  results are values; the AST and source are only read.
// Errors:     all into `diags`, sorted later by location; the result is empty if any was found.
#pragma once
#include "geometry/mechanism.hpp"
#include "geometry/metric_scene_ast.hpp"
#include "geometry/metric_source.hpp"
#include "qm/diagnostics.hpp"
#include <optional>
#include <vector>

namespace qm::geometry {

[[nodiscard]] std::optional<Mechanism> check_mechanism(const mast::MechanismFile& file, const MetricPositions& positions,
                                                       const MetricSource& src, Diagnostics& diags);
[[nodiscard]] std::optional<Configuration> check_configuration(const std::vector<mast::ConfigEntry>& entries, const Mechanism& m,
                                                               const MetricPositions& positions, const MetricSource& src,
                                                               Diagnostics& diags);

}  // namespace qm::geometry
