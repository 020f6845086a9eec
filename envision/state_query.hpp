// envision/state_query.hpp
// Provides:   find_state(), a state named on the command line:
//             by its id (`12`, `#12`; `2:12` or `2:#12` for chain 2 when there are several chains) or
//             by its name as the outputs print it (`scape-wheel/pallets-36 - -`: each pair's
//             PAIR-PLACE, then one motion per object of the chain, in the chain's order).
// Errors:     located diagnostics in the option's text (`OPTION:1:COL: error: ...`): an unknown id,
//             pair, place or part count, a malformed name, a state that is not consistent.
#pragma once
#include "envision/envisionment.hpp"
#include "qm/diagnostics.hpp"
#include <optional>
#include <string>

namespace qm::envision {

struct StateRef {
    std::size_t chain = 0;  // index into Envisionment::chains
    StateId state{0};
};

[[nodiscard]] std::optional<StateRef> find_state(const Envisionment& e, const std::string& text, const std::string& option,
                                                 Diagnostics& diagnostics);

// A state as named, whether or not it is consistent (for "why is this not a state?"): its chain and
// its places and motions. An id names a generated state.
struct NamedState {
    std::size_t chain = 0;
    State state;
    std::optional<StateId> id;  // when it is a state of the envisionment
};
// column: where text starts within the option's text (for locating errors in a part of it).
[[nodiscard]] std::optional<NamedState> parse_state(const Envisionment& e, const std::string& text, const std::string& option,
                                                    Diagnostics& diagnostics, const std::string& whole = {}, std::uint32_t column = 1);

}  // namespace qm::envision
