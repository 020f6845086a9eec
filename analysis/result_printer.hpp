// analysis/result_printer.hpp
// Provides:   the outputs of an analysis: for people, in the thesis' notation (Figures 7.3-7.18:
//             `Translational-Freedom (block (0 +))`, `Rotational-Motion (driver (+))`); for programs,
//             JSON with the schema of docs/OUTPUT.md. Also "why" answers, as an indented derivation
//             tree or as JSON.
// Ownership:  writes to the stream given; keeps nothing.
#pragma once
#include "analysis/analysis.hpp"
#include <ostream>
#include <span>

namespace qm::analysis {
void print_situation(std::ostream& os, const Scene& scene, const SituationResult& r);
void print_freedom(std::ostream& os, const Scene& scene, const SituationResult& r);  // its free directions
void print_motions(std::ostream& os, const Scene& scene, const SituationResult& r);  // combinations, stability
void print_analysis(std::ostream& os, const Scene& scene, std::span<const SituationResult> results);
void print_why(std::ostream& os, const WhyAnswer& w);

// {"scene": NAME, "dimensions": N, "situations": [SITUATION...]} (docs/OUTPUT.md).
void write_analysis_json(std::ostream& os, const Scene& scene, std::span<const SituationResult> results);
// One situation object: {"index", "freedom", "motions", "stable"}.
void write_situation_json(std::ostream& os, const Scene& scene, const SituationResult& r);
void write_why_json(std::ostream& os, const WhyAnswer& w);
}  // namespace qm::analysis
