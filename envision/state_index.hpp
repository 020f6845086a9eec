// envision/state_index.hpp
// Provides:   StateIndex, the state store of one chain: states by id (their order in the state
//             space), found by their place vector (the states a hypothesis may settle on, 8.3.4)
//             and by place vector and motions (8.3.5: "we search the previously generated set of
//             all possible mechanical states to determine if this one matches any of them").
// Ownership:  holds the states; ids index them.
#pragma once
#include "envision/state.hpp"
#include <map>
#include <optional>
#include <span>
#include <vector>

namespace qm::envision {

class StateIndex {
public:
    explicit StateIndex(std::vector<State> states);
    [[nodiscard]] std::size_t size() const noexcept { return states_.size(); }
    [[nodiscard]] const State& operator[](StateId id) const { return states_[id.value]; }
    [[nodiscard]] State& operator[](StateId id) { return states_[id.value]; }
    [[nodiscard]] const std::vector<State>& states() const noexcept { return states_; }
    [[nodiscard]] std::vector<State>& states() noexcept { return states_; }
    // The states with exactly these places, by increasing id.
    [[nodiscard]] std::span<const StateId> with_places(std::span<const geometry::PlaceId> places) const;
    [[nodiscard]] std::optional<StateId> find(const State& s) const;

private:
    static std::vector<std::uint32_t> key(std::span<const geometry::PlaceId> places);
    std::vector<State> states_;
    std::map<std::vector<std::uint32_t>, std::vector<StateId>> by_places_;
};

}  // namespace qm::envision
