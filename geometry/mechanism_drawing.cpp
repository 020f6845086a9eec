// geometry/mechanism_drawing.cpp
#include "geometry/mechanism_drawing.hpp"

#include "geometry/kinematic_pairs.hpp"

#include <algorithm>

namespace qm::geometry {

namespace {

std::string feature_name(const Part& part, const ContactFeature& f) {
    return part.name + (f.kind == FeatureKind::corner ? "-c" : "-s") + std::to_string(global_segment(part, f.profile, f.segment) + 1);
}

}  // namespace

std::vector<DrawnPart> drawn_parts(const Mechanism& m, const Configuration& q, const std::vector<PartId>& drawn) {
    std::vector<DrawnPart> out;
    for (PartId p : drawn) out.push_back({&m.parts[p], q.at(p)});
    return out;
}

std::vector<ContactMark> contact_marks(const Mechanism& m, const PairSpec& pair, const ContactResult& r, std::size_t a, std::size_t b) {
    std::vector<ContactMark> out;
    for (const auto& c : r.contacts) {
        ContactMark mark;
        mark.point = 0.5 * (c.first.point + c.second.point);
        mark.parts = {a, b};
        const std::array<const ContactFeature*, 2> features{&c.first, &c.second};
        const std::array<const Part*, 2> parts{&m.parts[pair.a], &m.parts[pair.b]};
        for (std::size_t k = 0; k < 2; ++k) {
            const ContactFeature& f = *features[k];
            if (f.kind == FeatureKind::surface) mark.normals[k] = f.normal;
            mark.note += (k ? " against " : "") + feature_name(*parts[k], f) +
                         (f.kind == FeatureKind::surface ? " (surface, normal " + to_string(qualitative(f.normal, m.settings.normal_zero_tolerance)) + ")"
                                                         : " (corner)");
        }
        out.push_back(std::move(mark));
    }
    return out;
}

MechanismContacts mechanism_contacts(const Mechanism& m, const Configuration& q, const std::vector<PartId>& drawn) {
    MechanismContacts out;
    const ContactRequest request{m.settings.contact_tolerance, m.settings.normal_zero_tolerance};
    auto index = [&](PartId p) { return static_cast<std::size_t>(std::find(drawn.begin(), drawn.end(), p) - drawn.begin()); };
    for (const auto& pair : kinematic_pairs(m).modelled) {
        const std::size_t a = index(pair.a), b = index(pair.b);
        if (a == drawn.size() || b == drawn.size()) continue;
        const auto oracle = pair_oracle(m, pair);
        const auto r = detect_contacts(*oracle, {q.at(pair.a), q.at(pair.b)}, request);
        if (r.status == ContactStatus::overlapping) {
            out.overlapping.push_back(pair);
            continue;
        }
        auto marks = contact_marks(m, pair, r, a, b);
        out.marks.insert(out.marks.end(), marks.begin(), marks.end());
    }
    return out;
}

}  // namespace qm::geometry
