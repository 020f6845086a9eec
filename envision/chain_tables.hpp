// envision/chain_tables.hpp
// Provides:   ChainTables, what the laws conclude for a chain independently of any state, read
//             once from the chain's state-space engine: how a pair's motion goes on when it arrives
//             at a place (rules/clock/arrival.rules, collision.rules: `arrival`) and the
//             nearness ranks of motions (rules/clock/nearness.rules: `nearness-rank`).
// Ownership:  a value type.
// Invariants: arrival(pair, place, how, v) lists the motions after, without repeats, in a fixed
//             order; an empty list means the laws give no way on (the hypothesis is dropped).
#pragma once
#include "geometry/place_vocabulary.hpp"
#include <array>
#include <cstdint>
#include <map>
#include <optional>
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
    // Pre: h and m are -1, 0, +1; rank in 0..3 (3: beyond the zero threshold).
    void set_rank(std::int8_t h, std::int8_t m, int rank) { rank_[idx(h)][idx(m)] = rank; }
    [[nodiscard]] int rank(std::int8_t h, std::int8_t m) const { return rank_[idx(h)][idx(m)]; }
    [[nodiscard]] bool ranks_complete() const;

private:
    static std::size_t idx(std::int8_t s) { return static_cast<std::size_t>(s + 1); }
    std::map<std::tuple<std::size_t, std::uint32_t, How, geometry::QualDirection>, std::vector<geometry::QualDirection>> arrival_;
    std::array<std::array<int, 3>, 3> rank_{{{-1, -1, -1}, {-1, -1, -1}, {-1, -1, -1}}};
};

}  // namespace qm::envision
