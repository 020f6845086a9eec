// tests/geometry/division_pieces.hpp
// Test helper (not a test): a vocabulary's free-space and external divisions cut into straight
// pieces, for the tests that walk across them with the pair's oracle.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/place_vocabulary.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace qm::geometry::test {

// One straight piece of a division: along `axis`, at `c` on the other axis, from `a` to `b` (a <= b,
// unwrapped the short way on a periodic axis); `id` is its division's place.
struct Piece {
    std::uint32_t id;
    int axis;
    double c, a, b;
};

inline std::vector<Piece> division_pieces(const CSpaceRequest& r, const PlaceVocabulary& v) {
    std::vector<Piece> out;
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::fsd && p.kind != PlaceKind::external_division) continue;
        const auto& ax = r.axes[static_cast<std::size_t>(p.axis)];
        for (std::size_t k = 0; k + 1 < p.points.size(); ++k) {
            const double x = p.points[k][p.axis];
            double y = p.points[k + 1][p.axis];
            if (ax.periodic) y = x + std::remainder(y - x, ax.span());
            out.push_back({p.id.value, p.axis, p.points[k][1 - p.axis], std::min(x, y), std::max(x, y)});
        }
    }
    return out;
}

}  // namespace qm::geometry::test
