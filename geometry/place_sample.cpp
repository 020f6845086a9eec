// geometry/place_sample.cpp
#include "geometry/place_sample.hpp"

#include "qm/assert.hpp"

namespace qm::geometry {

Eigen::Vector2d sample_configuration(const CSpaceRequest& space, const Place& p) {
    QM_REQUIRE(!p.points.empty(), "a place without points has no sample configuration");
    const bool division = p.kind == PlaceKind::fsd || p.kind == PlaceKind::external_division || p.kind == PlaceKind::stop;
    if (division && p.points.size() == 2) return wrap(space, p.points[0] + 0.5 * difference(space, p.points[0], p.points[1]));
    return p.points[p.points.size() / 2];
}

}  // namespace qm::geometry
