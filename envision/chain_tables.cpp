// envision/chain_tables.cpp
#include "envision/chain_tables.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::envision {

std::optional<How> how_of(std::string_view word) noexcept {
    if (word == "stay") return How::stay;
    if (word == "move") return How::move;
    if (word == "wrap") return How::wrap;
    return std::nullopt;
}

const char* to_string(How h) noexcept {
    switch (h) {
        case How::stay: return "stay";
        case How::move: return "move";
        case How::wrap: return "wrap";
    }
    return "?";
}

void ChainTables::add_arrival(std::size_t pair, geometry::PlaceId place, How how, geometry::QualDirection v,
                              geometry::QualDirection after) {
    auto& list = arrival_[{pair, place.value, how, v}];
    if (std::find(list.begin(), list.end(), after) == list.end()) {
        list.push_back(after);
        std::sort(list.begin(), list.end());
    }
}

void ChainTables::add_collision(std::size_t pair, geometry::PlaceId place, geometry::QualDirection v, geometry::QualDirection after) {
    collisions_.insert({pair, place.value, v, after});
}

const std::vector<geometry::QualDirection>& ChainTables::arrival(std::size_t pair, geometry::PlaceId place, How how,
                                                                 geometry::QualDirection v) const {
    static const std::vector<geometry::QualDirection> none;
    const auto it = arrival_.find({pair, place.value, how, v});
    return it == arrival_.end() ? none : it->second;
}

void ChainTables::set_preference_rank(std::size_t object, std::uint8_t allowed, std::int8_t m, std::int64_t rank) {
    if (preference_.size() <= object) preference_.resize(object + 1, {});
    preference_[object][allowed & 7U][idx(m)] = rank;
}

void ChainTables::set_settling(std::size_t object, std::uint8_t allowed, std::int8_t now, std::uint8_t fixes, bool reachable,
                               std::int8_t next, const std::optional<Refuter>& refuted) {
    if (settling_.size() <= object) settling_.resize(object + 1, {});
    std::uint8_t code = 0;
    if (refuted) {
        auto it = std::find(refuters_.begin(), refuters_.end(), *refuted);
        if (it == refuters_.end()) {
            QM_REQUIRE(refuters_.size() < 255, "at most 255 refuting rules in a settling table");
            refuters_.push_back(*refuted);
            it = refuters_.end() - 1;
        }
        code = static_cast<std::uint8_t>(it - refuters_.begin() + 1);
    }
    settling_[object][allowed & 7U][idx(now)][fixes & 7U][reachable ? 1 : 0][idx(next)] = code;
}

}  // namespace qm::envision
