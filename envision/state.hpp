// envision/state.hpp
// Provides:   State (a mechanical state of one kinematic chain: its place vector and one motion
//             per object, thesis Def 35, Figure 5.1), Transition (Def 36: an edge of the
//             envisionment, instantaneous or over an interval, with its causes), and their names in
//             the thesis' style.
// Ownership:  value types; a state's places and motions are indexed like its chain's pairs and
//             objects (chain.hpp).
// Invariants: motions and net forces are -1, 0, +1 (net force also `ambiguous`).
#pragma once
#include "geometry/place_vocabulary.hpp"
#include "qm/id.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace qm::envision {

using StateId = qm::Id<struct StateTag>;

inline constexpr std::int8_t ambiguous_sign = 2;  // the qualitative `?` (section 2.3)

struct State {
    std::vector<geometry::PlaceId> places;  // one per pair of the chain
    std::vector<std::int8_t> motions;       // one per object of the chain
    std::vector<std::int8_t> net_force;     // one per object; filled when its transitions are found
    bool may_rest = false;                  // the laws let it also stay as it is (rules/clock/rest.rules); filled then too
    friend bool operator==(const State& a, const State& b) { return a.places == b.places && a.motions == b.motions; }
};

enum class Duration : std::uint8_t { instant, interval };

// Causes of a transition, as bits.
enum Cause : std::uint8_t { kinematic = 1, dynamic = 2, collision = 4 };

struct Transition {
    StateId from{0}, to{0};
    Duration duration = Duration::interval;
    std::uint8_t causes = 0;
};

// "+", "0", "-" or "?".
[[nodiscard]] const char* sign_word(std::int8_t s) noexcept;
[[nodiscard]] const char* to_string(Duration d) noexcept;
// "kinematic", "dynamic", "collision" in that order, for the bits set.
[[nodiscard]] std::vector<std::string> cause_words(std::uint8_t causes);

}  // namespace qm::envision
