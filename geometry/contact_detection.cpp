// geometry/contact_detection.cpp: contacts at a configuration (Def 19), features from the exact
// profiles (surfaces, corners of Def 18), FCL for nearness and overlap.
#include "geometry/contact_detection.hpp"

#include "geometry/placed_part.hpp"
#include "geometry/segment_queries.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>

namespace qm::geometry {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

struct Hit {
    int profile = 0, segment = 0;
    double t = 0;
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

struct Candidate {
    Hit a, b;
};

using Placed = PlacedPart;

const Segment& seg(const Placed& p, int profile, int s) {
    return p.profiles[static_cast<std::size_t>(profile)].segments[static_cast<std::size_t>(s)];
}
int count(const Placed& p, int profile) { return static_cast<int>(p.profiles[static_cast<std::size_t>(profile)].segments.size()); }

// Signed turn at the vertex where segment s begins (left, i.e. convex for a counter-clockwise
// profile, is positive).
double turn_at(const Placed& p, int profile, int s) {
    const int n = count(p, profile);
    const Segment& in = seg(p, profile, (s + n - 1) % n);
    const Segment& out = seg(p, profile, s);
    const Eigen::Vector2d a = in.tangent_at(1), b = out.tangent_at(0);
    return std::atan2(cross(a, b), a.dot(b));
}

// The features of one side of a cluster of candidate hits near `centre`.
std::vector<ContactFeature> side_features(const Placed& p, const std::vector<Hit>& hits, const Eigen::Vector2d& centre, double tol,
                                          double zero_angle) {
    std::vector<std::pair<int, int>> vertices, surfaces;  // (profile, segment beginning at it) / (profile, segment)
    for (const auto& h : hits) {
        const Segment& s = seg(p, h.profile, h.segment);
        const double len = s.length();
        if (h.t * len <= tol) vertices.emplace_back(h.profile, h.segment);
        else if ((1 - h.t) * len <= tol) vertices.emplace_back(h.profile, (h.segment + 1) % count(p, h.profile));
        else surfaces.emplace_back(h.profile, h.segment);
    }
    auto surface = [&](int profile, int s, std::optional<Eigen::Vector2d> normal = std::nullopt) {
        ContactFeature f;
        f.kind = FeatureKind::surface;
        f.profile = profile;
        f.segment = s;
        const auto cp = closest_point(seg(p, profile, s), centre);
        f.point = cp.point;
        f.normal = normal ? *normal : seg(p, profile, s).outward_normal_at(cp.t);
        return f;
    };
    std::vector<ContactFeature> out;
    if (!vertices.empty()) {
        // Within the tolerance of a vertex, the vertex decides (a corner wins over its sides).
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        const auto v = *std::min_element(vertices.begin(), vertices.end(), [&](const auto& x, const auto& y) {
            return (seg(p, x.first, x.second).from - centre).norm() < (seg(p, y.first, y.second).from - centre).norm();
        });
        const int n = count(p, v.first), prev = (v.second + n - 1) % n;
        const double turn = turn_at(p, v.first, v.second);
        const Segment& in = seg(p, v.first, prev);
        const Segment& o = seg(p, v.first, v.second);
        if (turn > zero_angle) {
            ContactFeature f;
            f.kind = FeatureKind::corner;
            f.profile = v.first;
            f.segment = v.second;
            f.previous = prev;
            f.point = o.from;
            f.sides = {in.outward_normal_at(1), o.outward_normal_at(0)};
            out.push_back(f);
        } else if (turn < -zero_angle) {  // concave: contact with both surfaces (2.4.1)
            out.push_back(surface(v.first, prev));
            out.push_back(surface(v.first, v.second));
        } else {  // smooth join: one surface
            out.push_back(surface(v.first, v.second, Eigen::Vector2d((in.outward_normal_at(1) + o.outward_normal_at(0)).normalized())));
        }
        return out;
    }
    std::sort(surfaces.begin(), surfaces.end());
    surfaces.erase(std::unique(surfaces.begin(), surfaces.end()), surfaces.end());
    for (const auto& [profile, s] : surfaces) out.push_back(surface(profile, s));
    return out;
}

// Two straight edges lying on each other over a stretch longer than 2 tol: contacts at both
// ends of the stretch, surface against surface.
std::optional<std::array<Contact, 2>> lying_on(const Segment& a, const Segment& b, double tol) {
    if (a.is_arc() || b.is_arc()) return std::nullopt;
    const Eigen::Vector2d ua = (a.to - a.from).normalized();
    const double len = (a.to - a.from).norm();
    const double s0 = (b.from - a.from).dot(ua), s1 = (b.to - a.from).dot(ua);
    const double lo = std::max(0.0, std::min(s0, s1)), hi = std::min(len, std::max(s0, s1));
    if (hi - lo <= 2 * tol) return std::nullopt;
    const Eigen::Vector2d na = a.outward_normal_at(0.5), nb = b.outward_normal_at(0.5);
    if (na.dot(nb) >= 0) return std::nullopt;
    std::array<Contact, 2> out;
    for (int k = 0; k < 2; ++k) {
        const Eigen::Vector2d pa = a.from + (k == 0 ? lo : hi) * ua;
        const auto cb = closest_point(b, pa);
        if (cb.distance > tol) return std::nullopt;
        auto& c = out[static_cast<std::size_t>(k)];
        c.first.point = pa;
        c.first.normal = na;
        c.second.point = cb.point;
        c.second.normal = nb;
        c.distance = cb.distance;
    }
    return out;
}

}  // namespace

int global_segment(const Part& part, int profile, int segment) {
    int g = 0;
    for (int i = 0; i < profile; ++i) g += static_cast<int>(part.profiles[static_cast<std::size_t>(i)].segments.size());
    return g + segment;
}

QualDirection origin_direction(const Part& part, double q, const Eigen::Vector2d& point, double zero_length) {
    if (!part.rotates()) return {};
    const Eigen::Vector2d d = part.pose(q) * part.dof.pivot - point;  // the pivot does not move
    return QualDirection{{tolerant_sign(d.x(), zero_length), tolerant_sign(d.y(), zero_length)}};
}

QualDirection origin_direction_at_contact(const Part& part, double q, const Eigen::Vector2d& point, const Eigen::Vector2d& normal,
                                          double zero_length, double zero_tolerance) {
    QualDirection o = origin_direction(part, q, point, zero_length);
    if (!part.rotates()) return o;
    const Eigen::Vector2d d = part.pose(q) * part.dof.pivot - point;
    const QualDirection n = qualitative(normal, zero_tolerance);
    // cross(o, n) = o.x n.y - o.y n.x, qualitatively: ambiguous when both terms are non-zero with
    // opposite signs.
    const int t1 = o.s[0] * n.s[1], t2 = -o.s[1] * n.s[0];
    if (t1 == 0 || t2 == 0 || t1 == t2) return o;
    const double x_term = d.x() * normal.y(), y_term = d.y() * normal.x();
    if (std::abs(x_term - y_term) <= zero_tolerance * d.norm()) return o;  // too close to decide
    if (std::abs(x_term) > std::abs(y_term)) o.s[1] = 0;
    else o.s[0] = 0;
    return o;
}

bool can_contact(const ContactFeature& corner, const Eigen::Vector2d& n, double zero_tolerance) {
    QM_REQUIRE(corner.kind == FeatureKind::corner, "can_contact needs a corner");
    return (-corner.sides[0]).dot(n) >= -zero_tolerance && (-corner.sides[1]).dot(n) >= -zero_tolerance;
}

bool apart_beyond_contact(const Part& a, const Part& b, const Eigen::Vector2d& q, const ContactRequest& request, double chordal_tolerance) {
    // A mesh's vertices lie on the exact profiles and its chords within the chordal tolerance of
    // them, so FCL's distance is at most two chordal errors short of the exact one.
    const double tol = request.tolerance * std::min(a.size(), b.size());
    return placed_distance(place(a, q[0]), place(b, q[1])) > tol + 4 * chordal_tolerance;
}

ContactResult detect_contacts(const FclPairOracle& pair, const Eigen::Vector2d& q, const ContactRequest& request) {
    QM_REQUIRE(request.tolerance > 0 && request.normal_zero_tolerance > 0, "contact tolerances must be positive");
    ContactResult out;
    const Part& pa = pair.part(0);
    const Part& pb = pair.part(1);
    const double tol = request.tolerance * std::min(pa.size(), pb.size());
    out.tolerance = tol;
    out.fcl_distance = pair.signed_distance(q);
    const double chordal = pair.model(0).chordal_tolerance();
    if (out.fcl_distance > tol + 2 * chordal) return out;  // FCL: too far apart to touch
    if (out.fcl_distance < 0 && !pair.separable_within(q, tol)) {
        // FCL finds the meshes overlapping, and no shift of the tolerance's length parts them:
        // they overlap, rather than touch.
        out.status = ContactStatus::overlapping;
        out.message = "'" + pa.name + "' and '" + pb.name + "' overlap at this configuration by more than the contact tolerance (" +
                      std::to_string(tol) + ")";
        return out;
    }
    const Placed A = place(pa, q[0]), B = place(pb, q[1]);
    std::vector<Candidate> candidates;
    std::vector<Contact> lying;
    for (int i = 0; i < static_cast<int>(A.profiles.size()); ++i)
        for (int s = 0; s < count(A, i); ++s)
            for (int j = 0; j < static_cast<int>(B.profiles.size()); ++j)
                for (int t = 0; t < count(B, j); ++t) {
                    if (A.boxes[static_cast<std::size_t>(i)][static_cast<std::size_t>(s)].distance(B.boxes[static_cast<std::size_t>(j)][static_cast<std::size_t>(t)]) > tol)
                        continue;
                    const Segment& x = seg(A, i, s);
                    const Segment& y = seg(B, j, t);
                    const auto d = segment_distance(x, y);
                    if (d.distance > tol) continue;
                    if (const auto ends = lying_on(x, y, tol)) {
                        for (auto c : *ends) {
                            c.first.profile = i;
                            c.first.segment = s;
                            c.second.profile = j;
                            c.second.segment = t;
                            lying.push_back(c);
                        }
                        continue;
                    }
                    if (d.distance == 0) {
                        // Overlapping within the tolerance (e.g. a configuration found on the
                        // tessellated boundary): the contact is the middle of the overlap, not
                        // where the boundaries cross.
                        const auto meet = intersections(x, y, 0.0);
                        if (meet.points.size() >= 2) {
                            const Eigen::Vector2d mid = 0.5 * (meet.points[0].point + meet.points[1].point);
                            const auto ca = closest_point(x, mid), cb = closest_point(y, mid);
                            candidates.push_back({{i, s, ca.t, ca.point}, {j, t, cb.t, cb.point}});
                            continue;
                        }
                    }
                    candidates.push_back({{i, s, d.ta, d.pa}, {j, t, d.tb, d.pb}});
                }
    // Cluster the candidates by where they are: each cluster is one contact place.
    std::vector<int> cluster(candidates.size(), -1);
    int clusters = 0;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        if (cluster[k] >= 0) continue;
        cluster[k] = clusters;
        std::vector<std::size_t> todo = {k};
        while (!todo.empty()) {
            const std::size_t x = todo.back();
            todo.pop_back();
            for (std::size_t y = 0; y < candidates.size(); ++y)
                if (cluster[y] < 0 && (candidates[x].a.point - candidates[y].a.point).norm() <= 3 * tol) {
                    cluster[y] = clusters;
                    todo.push_back(y);
                }
        }
        ++clusters;
    }
    for (int c = 0; c < clusters; ++c) {
        std::vector<Hit> ha, hb;
        Eigen::Vector2d centre = Eigen::Vector2d::Zero();
        for (std::size_t k = 0; k < candidates.size(); ++k)
            if (cluster[k] == c) {
                ha.push_back(candidates[k].a);
                hb.push_back(candidates[k].b);
                centre += 0.5 * (candidates[k].a.point + candidates[k].b.point);
            }
        centre /= static_cast<double>(ha.size());
        // The end of a stretch of edges lying on each other is reported there already.
        bool covered = false;
        for (const auto& l : lying) covered = covered || (l.first.point - centre).norm() <= 3 * tol;
        if (covered) continue;
        const auto fa = side_features(A, ha, centre, tol, request.normal_zero_tolerance);
        const auto fb = side_features(B, hb, centre, tol, request.normal_zero_tolerance);
        for (const auto& x : fa)
            for (const auto& y : fb) {
                if (x.kind == FeatureKind::surface && y.kind == FeatureKind::surface && x.normal.dot(y.normal) >= 0) continue;
                out.contacts.push_back({x, y, (x.point - y.point).norm()});
            }
    }
    out.contacts.insert(out.contacts.end(), lying.begin(), lying.end());
    std::sort(out.contacts.begin(), out.contacts.end(), [](const Contact& x, const Contact& y) {
        return std::make_tuple(x.first.profile, x.first.segment, x.first.point.x(), x.first.point.y(), x.second.segment) <
               std::make_tuple(y.first.profile, y.first.segment, y.first.point.x(), y.first.point.y(), y.second.segment);
    });
    return out;
}

}  // namespace qm::geometry
