// geometry/place_json.cpp
#include "geometry/place_json.hpp"
#include "qm/json.hpp"


namespace qm::geometry {
namespace {

void point(std::ostream& os, const Eigen::Vector2d& p) { os << '[' << p.x() << ',' << p.y() << ']'; }
void direction(std::ostream& os, QualDirection d) { os << '[' << int{d.s[0]} << ',' << int{d.s[1]} << ']'; }


}  // namespace

void write_place_json(std::ostream& os, const CSpaceRequest& space, const PlaceVocabulary& v) {
    const auto precision = os.precision(17);
    os << "{\"schema\":\"qm-place-vocabulary/1\",\"axes\":[";
    for (int k = 0; k < 2; ++k) {
        const auto& a = space.axes[static_cast<std::size_t>(k)];
        os << (k ? "," : "") << "{\"lo\":" << a.lo << ",\"hi\":" << a.hi << ",\"periodic\":" << (a.periodic ? "true" : "false")
           << ",\"samples\":" << a.samples << '}';
    }
    os << "],\"boundary_tolerance\":" << space.boundary_tolerance << ",\"places\":[";
    for (std::size_t i = 0; i < v.places.size(); ++i) {
        const Place& p = v.places[i];
        os << (i ? ",\n" : "\n") << "{\"id\":" << p.id.value << ",\"kind\":\"" << to_string(p.kind) << '"';
        if (p.kind == PlaceKind::join) os << ",\"join_kind\":\"" << to_string(p.join_kind) << '"';
        os << ",\"normals\":[";
        for (std::size_t k = 0; k < p.normals.size(); ++k) {
            if (k) os << ',';
            direction(os, p.normals[k]);
        }
        os << ']';
        if (p.concave) os << ",\"concave\":" << (*p.concave ? "true" : "false");
        if (p.axis >= 0) os << ",\"axis\":" << p.axis;
        if (!p.label.empty()) {
            os << ",\"label\":";
            write_json_string(os, p.label);
        }
        if (p.kind == PlaceKind::face) os << ",\"samples\":" << p.extent;
        if (p.gap) os << ",\"gap\":true";
        os << ",\"points\":[";
        for (std::size_t k = 0; k < p.points.size(); ++k) {
            if (k) os << ',';
            point(os, p.points[k]);
        }
        os << "]}";
    }
    os << "],\n\"adjacency\":[";
    for (std::size_t i = 0; i < v.adjacency.size(); ++i) {
        const Adjacency& a = v.adjacency[i];
        os << (i ? ",\n" : "\n") << "{\"from\":" << a.from.value << ",\"to\":" << a.to.value << ",\"motion\":";
        direction(os, a.motion);
        os << ",\"instantaneous\":" << (a.instantaneous ? "true" : "false") << ",\"constrained\":" << (a.constrained ? "true" : "false") << '}';
    }
    os << "]}\n";
    os.precision(precision);
}

}  // namespace qm::geometry
