// analysis/result_printer.hpp
// Provides:   the outputs of an analysis: for people, in the thesis' notation (Figures 7.3-7.18:
//             `Translational-Freedom (block (0 +))`, `Rotational-Motion (driver (+))`); for programs,
//             JSON with the schema of docs/OUTPUT.md. ("Why" answers: analysis/why_printer.hpp.)
// Ownership:  writes to the stream given; keeps nothing.
#pragma once
#include "analysis/analysis.hpp"
#include <ostream>
#include <span>

namespace qm::analysis {
// Which combinations a listing shows: those the forces select (the default), or every kinematically
// consistent one (--kinematic: blocking, pushing and given motions alone). Headings say which, and
// count both.
enum class MotionSet : std::uint8_t { selected, kinematic };

void print_situation(std::ostream& os, const Scene& scene, const SituationResult& r, MotionSet shown = MotionSet::selected);
void print_freedom(std::ostream& os, const Scene& scene, const SituationResult& r);  // its free directions
// The combinations of `shown`, both counts, and the stability verdict (of the selected ones).
void print_motions(std::ostream& os, const Scene& scene, const SituationResult& r, MotionSet shown = MotionSet::selected);
void print_analysis(std::ostream& os, const Scene& scene, std::span<const SituationResult> results,
                    MotionSet shown = MotionSet::selected);

// {"scene": NAME, "dimensions": N, "situations": [SITUATION...]} (docs/OUTPUT.md).
void write_analysis_json(std::ostream& os, const Scene& scene, std::span<const SituationResult> results,
                         MotionSet shown = MotionSet::selected);
// One situation object: {"index", "freedom", "motions", "motion_set", "combinations", "stable"}.
void write_situation_json(std::ostream& os, const Scene& scene, const SituationResult& r,
                          MotionSet shown = MotionSet::selected);
}  // namespace qm::analysis
