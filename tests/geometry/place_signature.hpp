// tests/geometry/place_signature.hpp: a relabelling-invariant summary of a place vocabulary, to
// compare two vocabularies (other grids, another drawing of the same pair): each place's kind,
// join kind, normals and concavity, and each adjacency by the kinds it connects, its motion
// and flags. With `negate`, every normal and motion is negated: the signature of the point
// reflection of the configuration space (q0, q1) -> (-q0, -q1), the mirror image of a pair.
#pragma once
#include "geometry/place_vocabulary.hpp"

#include <algorithm>
#include <set>
#include <sstream>
#include <string>

namespace qm::geometry::test {

inline std::multiset<std::string> signature(const PlaceVocabulary& v, bool negate = false) {
    auto n = [&](QualDirection d) { return negate ? negated(d) : d; };
    std::multiset<std::string> out;
    for (const auto& p : v.places) {
        std::ostringstream s;
        s << to_string(p.kind);
        if (p.kind == PlaceKind::join) s << ' ' << to_string(p.join_kind);
        std::multiset<std::string> normals;
        for (auto d : p.normals) normals.insert(to_string(n(d)));
        for (const auto& d : normals) s << ' ' << d;
        if (p.concave) s << (*p.concave ? " concave" : " convex");
        if (p.gap) s << " gap";
        out.insert(s.str());
    }
    for (const auto& a : v.adjacency) {
        std::ostringstream s;
        s << "adj " << to_string(v.at(a.from).kind) << ' ' << to_string(v.at(a.to).kind) << ' ' << to_string(n(a.motion))
          << (a.instantaneous ? " inst" : "") << (a.constrained ? " constrained" : "");
        out.insert(s.str());
    }
    return out;
}

}  // namespace qm::geometry::test
