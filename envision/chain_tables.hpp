// envision/chain_tables.hpp
// Provides:   ChainTables, what the laws conclude for a chain independently of any state, read
//             once from the chain's state-space engine: how a pair's motion goes on when it arrives
//             at a place (rules/clock/arrival.rules, collision.rules: `arrival`) and how the laws'
//             preference between hypothesised states ranks each object's motion given the motions
//             a step allows it (rules/clock/nearness.rules: the `prefer` on `motion`, read through
//             engine/preferences.hpp's rank table), and which motion an object may have after a
//             step given its situation in it (rules/clock/settling.rules: the motions the step
//             allows it, its motion now, the motions the step's collisions fix, read through
//             engine/consistency.hpp; also whether any state with the step's places gives it a
//             motion the step allows it), with the rule that refutes each motion it may not have;
//             and which arrivals are collisions (collision.rules: `collision`) and which ways of
//             reaching a next place change it (transition_order.rules: `place-change`), for the
//             causes of a transition and whether one that comes back to its state is one.
// Ownership:  a value type.
// Invariants: arrival(pair, place, how, v) lists the motions after, without repeats, in a fixed
//             order; an empty list means the laws give no way on (the hypothesis is dropped).
#pragma once
#include "geometry/place_vocabulary.hpp"
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace qm::envision {

// How a pair reaches its next place (rules/clock/place_transitions.rules, transition_order.rules).
enum class How : std::uint8_t { stay, move, wrap };
[[nodiscard]] std::optional<How> how_of(std::string_view word) noexcept;
[[nodiscard]] const char* to_string(How h) noexcept;

class ChainTables {
public:
    // Pre: motion components are -1, 0, +1.
    void add_arrival(std::size_t pair, geometry::PlaceId place, How how, geometry::QualDirection v, geometry::QualDirection after);
    [[nodiscard]] const std::vector<geometry::QualDirection>& arrival(std::size_t pair, geometry::PlaceId place, How how,
                                                                      geometry::QualDirection v) const;
    // Whether arriving at the place with motion v and going on with `after` is a collision.
    void add_collision(std::size_t pair, geometry::PlaceId place, geometry::QualDirection v, geometry::QualDirection after);
    [[nodiscard]] bool collision(std::size_t pair, geometry::PlaceId place, geometry::QualDirection v, geometry::QualDirection after) const {
        return collisions_.count({pair, place.value, v, after}) != 0;
    }
    // Whether reaching the next place this way changes the place (a kinematic cause; a transition
    // even back to the state it left).
    void add_place_change(How how) { place_changes_.insert(how); }
    [[nodiscard]] bool place_change(How how) const { return place_changes_.count(how) != 0; }
    // The rank of motion m of the chain's object o when a step allows it the motions in `allowed`
    // (allowed_mask): smaller is preferred; all 0 where the laws prefer nothing. Pre: m is -1, 0, +1.
    void set_preference_rank(std::size_t object, std::uint8_t allowed, std::int8_t m, std::int64_t rank);
    [[nodiscard]] std::int64_t preference_rank(std::size_t object, std::uint8_t allowed, std::int8_t m) const {
        return object < preference_.size() ? preference_[object][allowed & 7U][idx(m)] : 0;
    }
    [[nodiscard]] static std::uint8_t allowed_mask(const std::vector<std::int8_t>& motions) {
        std::uint8_t mask = 0;
        for (const auto m : motions) mask = static_cast<std::uint8_t>(mask | 1U << idx(m));
        return mask;
    }
    // Where the preference is declared ("FILE:LINE"; empty if none), for explanations.
    std::string preference_where;

    // The rule that refutes a motion after a step (settling), for explanations.
    struct Refuter {
        std::string rule;   // its name (empty if no rule concluded the nogood)
        std::string where;  // "FILE:LINE"
        friend bool operator==(const Refuter&, const Refuter&) = default;
    };
    // Whether object o may move `next` after a step that allows it the motions in `allowed`
    // (allowed_mask), starting from motion `now`, with the collisions of the step fixing its motion
    // to each of the motions in `fixes` (a mask like allowed_mask; 0: no collision), where
    // `reachable` says whether some state with the step's places gives o a motion the step allows
    // it: 0 if the laws allow it, else 1 + the index of the refuting rule in refuter(). Where
    // nothing was set (the laws settle nothing), 0. Pre: motions are -1, 0, +1.
    void set_settling(std::size_t object, std::uint8_t allowed, std::int8_t now, std::uint8_t fixes, bool reachable, std::int8_t next,
                      const std::optional<Refuter>& refuted);
    [[nodiscard]] std::uint8_t settling(std::size_t object, std::uint8_t allowed, std::int8_t now, std::uint8_t fixes, bool reachable,
                                        std::int8_t next) const {
        return object < settling_.size() ? settling_[object][allowed & 7U][idx(now)][fixes & 7U][reachable ? 1 : 0][idx(next)] : 0;
    }
    // The mask of one motion (for allowed_mask, fixes). Pre: m is -1, 0, +1.
    [[nodiscard]] static std::uint8_t bit(std::int8_t m) { return static_cast<std::uint8_t>(1U << idx(m)); }
    // Pre: code is a non-zero value settling() returned.
    [[nodiscard]] const Refuter& refuter(std::uint8_t code) const { return refuters_.at(code - 1U); }

private:
    static std::size_t idx(std::int8_t s) { return static_cast<std::size_t>(s + 1); }
    std::map<std::tuple<std::size_t, std::uint32_t, How, geometry::QualDirection>, std::vector<geometry::QualDirection>> arrival_;
    std::set<std::tuple<std::size_t, std::uint32_t, geometry::QualDirection, geometry::QualDirection>> collisions_;
    std::set<How> place_changes_;
    std::vector<std::array<std::array<std::int64_t, 3>, 8>> preference_;  // [object][allowed mask][motion]
    // [object][allowed mask][now][fixes mask][reachable][next]: 0 or 1 + an index into refuters_.
    using Next = std::array<std::uint8_t, 3>;
    std::vector<std::array<std::array<std::array<std::array<Next, 2>, 8>, 3>, 8>> settling_;
    std::vector<Refuter> refuters_;
};

}  // namespace qm::envision
