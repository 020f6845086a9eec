// geometry/place_text.cpp
#include "geometry/place_text.hpp"

namespace qm::geometry {

void write_place_text(std::ostream& os, const PlaceVocabulary& v) {
    os << "places " << v.places.size() << " (cseg " << v.count(PlaceKind::cseg) << ", join " << v.count(PlaceKind::join)
       << ", fsd " << v.count(PlaceKind::fsd) << ", external-division " << v.count(PlaceKind::external_division)
       << ", face " << v.count(PlaceKind::face);
    if (const auto stops = v.count(PlaceKind::stop)) os << ", stop " << stops;
    os << ")\n";
    for (const Place& p : v.places) {
        os << "place " << p.id.value << ' ' << to_string(p.kind);
        if (p.kind == PlaceKind::join) os << ' ' << to_string(p.join_kind);
        if (p.gap) os << " gap";  // 8.1.6: the play collapsed with its CSEGs; normals: theirs
        if (!p.normals.empty()) {
            os << " normal";
            for (auto n : p.normals) os << ' ' << to_string(n);
        }
        if (p.concave) os << (*p.concave ? " concave" : " convex");
        if (p.axis >= 0) os << " along q" << p.axis;
        if (!p.label.empty()) os << " \"" << p.label << '"';
        if (!p.points.empty()) os << " at (" << p.points.front().x() << ' ' << p.points.front().y() << ')';
        os << '\n';
    }
    for (const Adjacency& a : v.adjacency)
        os << "(adjacent " << a.from.value << ' ' << a.to.value << ' ' << to_string(a.motion) << ')'
           << (a.constrained ? " constrained" : a.instantaneous ? " instantaneous" : " interval") << '\n';
}

}  // namespace qm::geometry
