// analysis/detail/why_responsible.hpp (internal to analysis/)
// Provides:   the responsible sets of a --why answer: the sets of the situation's contacts, forces
//             and given motions with which alone the situation rules the motion out. minimal_sets(),
//             those of the exclusions, reduced; set_responsible(), the exact minimal ones by
//             re-analysis of the situation's item subsets where it is small enough
//             (WhyLimits::exact_items), else a sufficient set with a note; predicted(), whether a
//             motion is in a predicted combination; coarse_note(), the note of an analysis one
//             assumption per situation.
// Ownership:  values; the State is borrowed (set_responsible runs what-if contexts in its engine).
#pragma once
#include "analysis/detail/analysis_state.hpp"
#include <set>
#include <string>
#include <vector>

namespace qm::analysis::detail {

// Says in w that its responsible sets may not be minimal, when the scene is analysed one
// assumption per situation.
void coarse_note(const Analysis::State& st, WhyAnswer& w);

// The distinct responsible sets of the exclusions, none a superset of another, smallest first.
[[nodiscard]] std::vector<std::vector<std::string>> minimal_sets(const std::vector<Exclusion>& exclusions);

// Whether `d` is the object's motion in some predicted combination of r; the first such combination
// as text in `example`.
[[nodiscard]] bool predicted(const Analysis::State& st, const SituationResult& r, ObjectId o, bool translational,
                             const Direction& d, std::string* example = nullptr);

// w's responsible sets for motion d of o in situation s (environment base): the exact minimal ones
// by re-analysis where the situation has at most st.options.why.exact_items items, else `together`
// (the items `reasons` rest on), which suffices but is not reduced (with a note saying so).
void set_responsible(Analysis::State& st, WhyAnswer& w, const std::set<std::string>& together, std::size_t s,
                     atms::EnvId base, ObjectId o, bool translational, const Direction& d, const std::string& reasons);

}  // namespace qm::analysis::detail
