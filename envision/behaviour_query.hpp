// envision/behaviour_query.hpp
// Provides:   the envisionment's graph questions (thesis 5.4: "Can a behavioral sequence occur?";
//             9.1.5's search for de Carle's description; 11.2.2):
//             - reachable_from(): the states a state leads to (itself included);
//             - parse_behaviour(): a described behaviour, a sequence of partial state descriptions
//               separated by `;`, each a conjunction of terms: `PAIR-PLACE` (that place), `PAIR:KIND`
//               (a place of that kind: cseg, join, fsd, external-division, face, stop; `contact`: a
//               place with a normal, the parts touching; `free`: one without), `PART=+|0|-` (a
//               motion), `#ID` (that state), and the state's part in the graph: `terminal` (no
//               transition out), `rest` (behaviour may end there: terminal or a possible rest),
//               `cycle` (on a behavioural cycle), `transient` (on a transient cycle);
//             - find_behaviour(): the shortest path whose states match the descriptions in order
//               (a state may match several in a row), avoiding states that match any of `avoid`;
//               or, when there is none, how far it gets: the descriptions matched, and the last
//               state reached that matched the last of them.
// Errors:     located diagnostics in the option's text (`OPTION:1:COL: error: ...`): an unknown
//             pair, part, kind or place, a malformed term, terms of two chains, an empty description.
#pragma once
#include "envision/envisionment.hpp"
#include "qm/diagnostics.hpp"
#include <optional>
#include <string>
#include <vector>

namespace qm::envision {

struct DescriptionTerm {
    enum class Kind : std::uint8_t { place, place_kind, contact, free, motion, state, terminal, rest, cycle, transient } kind = Kind::place;
    std::size_t index = 0;        // the pair (place terms) or the object (motion) in the chain
    std::uint32_t value = 0;      // place id, or state id
    geometry::PlaceKind place_kind = geometry::PlaceKind::face;
    std::int8_t motion = 0;
};
struct StateDescription {
    std::string text;
    std::vector<DescriptionTerm> terms;
};
struct Behaviour {
    std::size_t chain = 0;
    std::vector<StateDescription> steps, avoid;
};

[[nodiscard]] std::vector<bool> reachable_from(const ChainEnvisionment& c, StateId from);
[[nodiscard]] bool matches(const Envisionment& e, const ChainEnvisionment& c, StateId s, const StateDescription& d);

// Pre: the chain of `behaviour` (when avoid has terms) is the one the steps name.
[[nodiscard]] std::optional<Behaviour> parse_behaviour(const Envisionment& e, const std::string& steps, const std::string& steps_option,
                                                       const std::vector<std::string>& avoid, Diagnostics& diagnostics);

struct BehaviourAnswer {
    std::vector<StateId> path;                 // found: the states in order
    std::vector<std::size_t> matched_at;       // found: the position in path where each description matched
    std::size_t matched = 0;                   // not found: how many descriptions some path matches
    std::optional<StateId> farthest;           // not found: a state where the last of those matched
};
[[nodiscard]] BehaviourAnswer find_behaviour(const Envisionment& e, const Behaviour& b);

}  // namespace qm::envision
