// geometry/place_vocabulary.cpp
#include "geometry/place_vocabulary.hpp"

#include <algorithm>

namespace qm::geometry {

const char* to_string(PlaceKind k) noexcept {
    switch (k) {
        case PlaceKind::cseg: return "cseg";
        case PlaceKind::join: return "join";
        case PlaceKind::fsd: return "fsd";
        case PlaceKind::external_division: return "external-division";
        case PlaceKind::face: return "face";
        case PlaceKind::stop: return "stop";
    }
    return "?";
}

const char* to_string(JoinKind k) noexcept {
    switch (k) {
        case JoinKind::normal_change: return "normal-change";
        case JoinKind::fsd_end: return "fsd-end";
        case JoinKind::crossing: return "crossing";
        case JoinKind::limit: return "limit";
    }
    return "?";
}

std::size_t PlaceVocabulary::count(PlaceKind k) const {
    return static_cast<std::size_t>(std::count_if(places.begin(), places.end(), [k](const Place& p) { return p.kind == k; }));
}

}  // namespace qm::geometry
