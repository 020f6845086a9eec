// engine/preferences.hpp
// Provides:   the reading of a program's `prefer` declarations (docs/RULES.md "Preferences") over
//             an engine's facts: which facts rank a member of a choice set, and the ranks of a choice
//             set's members in an environment, as the generic preference query over interpretations
//             (atms/preferred_interpretations.hpp) takes them.
// Semantics:  a member (c a1 ... an) of a choice set is ranked k by a fact of the preference's rank
//             predicate r holding the member's arguments at the declared places and the integer k at
//             the rank's place; with several such facts holding, by the least k; with `up to N`, a k
//             above N counts as N. A choice set is ranked in an environment if some member has a rank
//             fact holding there; a member with none then ranks after every ranked member (it is
//             farther than the ranking reaches). A rank fact whose rank is not an integer ranks nothing.
//             A rank table reads one choice set's ranks in the environment of every subset of a few
//             reference assumptions at once, for a driver that asks the same preference many times
//             in environments built from them (the envisioner: the motions a step allows, 8.3.4).
// Ownership:  returns values; reads the engine (the rank table interns environments in its ATMS).
// Knows nothing of what is ranked, nor of mechanics.
#pragma once
#include "atms/atms.hpp"
#include "engine/engine.hpp"
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace qm::engine {

// The facts that rank assumption a (whatever environment they hold in), in creation order; none if
// a is not the fact of a preference's chosen predicate.
[[nodiscard]] std::vector<FactId> rank_facts(const Engine& e, atms::AssumptionId a);

// The ranks of set's members in env (ranks[i] is set[i]'s); nullopt if the set is not ranked there
// (no preference chooses among its members, or none of them has a rank fact holding in env).
// Pre: set's assumptions and env were issued by e's ATMS.
[[nodiscard]] std::optional<std::vector<std::int64_t>> choice_set_ranks(const Engine& e, std::span<const atms::AssumptionId> set,
                                                                        atms::EnvId env);

// The `prefer` declaration choosing among set's members (that of its first member's predicate), if
// any: its location is where a driver's explanation cites the preference.
[[nodiscard]] const CompiledPreference* choosing_preference(const Engine& e, std::span<const atms::AssumptionId> set);

// table[mask][i]: set[i]'s rank in the environment of the references whose bits are in mask (bit j:
// references[j]), as choice_set_ranks gives it there; where the set is not ranked, every member 0
// (the preference says nothing: all tie). Pre: references.size() < 16; ids issued by e's ATMS.
[[nodiscard]] std::vector<std::vector<std::int64_t>> choice_set_rank_table(Engine& e, std::span<const atms::AssumptionId> set,
                                                                           std::span<const atms::AssumptionId> references);

}  // namespace qm::engine
