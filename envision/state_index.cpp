// envision/state_index.cpp
#include "envision/state_index.hpp"

namespace qm::envision {

StateIndex::StateIndex(std::vector<State> states) : states_(std::move(states)) {
    for (std::uint32_t i = 0; i < states_.size(); ++i) by_places_[key(states_[i].places)].push_back(StateId{i});
}

std::vector<std::uint32_t> StateIndex::key(std::span<const geometry::PlaceId> places) {
    std::vector<std::uint32_t> k;
    k.reserve(places.size());
    for (const auto p : places) k.push_back(p.value);
    return k;
}

std::span<const StateId> StateIndex::with_places(std::span<const geometry::PlaceId> places) const {
    const auto it = by_places_.find(key(places));
    if (it == by_places_.end()) return {};
    return it->second;
}

std::optional<StateId> StateIndex::find(const State& s) const {
    for (const StateId id : with_places(s.places))
        if (states_[id.value].motions == s.motions) return id;
    return std::nullopt;
}

}  // namespace qm::envision
