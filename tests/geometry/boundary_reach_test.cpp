// tests/geometry/boundary_reach_test.cpp: what a motion meets first is a place the adjacency names
// (thesis 8.1.3), checked on every bundled pair with the pair's own FCL oracle, apart from the
// builder:
//  - from each face's own sample, along each motion (the axes, and the diagonals in cells), a walk
//    through free space meets first either a division (crossed) or the boundary (blocked; bisected
//    here to the contact): that division, or a CSEG, join or stop passing within a twentieth of a
//    cell of the contact, is among the face's next places under that motion (no gap in the
//    boundary between two joins, however close);
//  - a CSEG's points run from its start join to its end join; a motion along it (its dot product
//    with every chord of the path has one sign) goes to the join at the end it moves towards, also
//    where the CSEG runs more than half round a periodic axis.
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"

#include "../support/random_mechanism.hpp"
#include "division_pieces.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

using namespace qm::geometry;
using qm::geometry::test::division_pieces;
using qm::geometry::test::Piece;

namespace {

struct PairBuild {
    std::string name;
    CSpaceRequest request;
    std::unique_ptr<PairOracle> oracle;
    PlaceVocabulary vocabulary;
};

// Every modelled pair of a mechanism with more than one place; a pair whose vocabulary the
// geometry refuses (a random drawing whose parts never touch) is left out, unless `all` is asked.
std::vector<PairBuild> pairs_of(const Mechanism& m, const std::string& name, bool all) {
    std::vector<PairBuild> out;
    for (const auto& spec : kinematic_pairs(m).modelled) {
        const auto request = place_request(m, spec);
        auto oracle = pair_oracle(m, spec);
        auto result = build_place_vocabulary(*oracle, request);
        if (all) REQUIRE(result.status == PlaceStatus::ok);
        if (result.status != PlaceStatus::ok || result.vocabulary.places.size() < 2) continue;
        out.push_back({name + " " + m.parts[spec.a].name + "/" + m.parts[spec.b].name, request.cspace, std::move(oracle),
                       std::move(result.vocabulary)});
    }
    return out;
}

std::vector<PairBuild> bundled_pairs(const std::string& file) {
    qm::Diagnostics d;
    auto m = read_mechanism_file((std::filesystem::path(QM_SOURCE_DIR) / "scenarios/clock" / file).string(), d);
    REQUIRE(m);
    return pairs_of(*m, file, true);
}

Eigen::Vector2d cell_of(const CSpaceRequest& r) { return {r.axes[0].step(), r.axes[1].step()}; }

// Distance in cells from q to a place's polyline (a join: its point), the short way round.
double cells_to(const CSpaceRequest& r, const Place& p, const Eigen::Vector2d& q) {
    const Eigen::Vector2d cell = cell_of(r);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < p.points.size(); ++k) {
        const Eigen::Vector2d a = difference(r, q, p.points[k]).cwiseQuotient(cell);
        if (k + 1 == p.points.size()) {
            best = std::min(best, a.norm());
            break;
        }
        const Eigen::Vector2d ab = difference(r, p.points[k], p.points[k + 1]).cwiseQuotient(cell);
        const double t = ab.squaredNorm() > 0 ? std::clamp(-a.dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
        best = std::min(best, (a + t * ab).norm());
    }
    return best;
}

// Where along the segment p + t (q - p), t in (0, 1], it crosses a division piece first, if it does.
std::optional<std::pair<double, std::uint32_t>> first_crossing(const CSpaceRequest& r, const std::vector<Piece>& pieces,
                                                               const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    std::optional<std::pair<double, std::uint32_t>> best;
    for (const auto& d : pieces) {
        const int across = 1 - d.axis;
        const double span = r.axes[static_cast<std::size_t>(across)].span();
        const bool periodic = r.axes[static_cast<std::size_t>(across)].periodic;
        const double dc = q[across] - p[across];
        if (dc == 0) continue;
        // The copy of the piece's line the segment passes, a whole number of periods on.
        for (int s = periodic ? -2 : 0; s <= (periodic ? 2 : 0); ++s) {
            const double t = (d.c + s * span - p[across]) / dc;
            if (!(t > 1e-12 && t <= 1)) continue;
            const double x = p[d.axis] + t * (q[d.axis] - p[d.axis]);
            const auto& ax = r.axes[static_cast<std::size_t>(d.axis)];
            for (int u = ax.periodic ? -2 : 0; u <= (ax.periodic ? 2 : 0); ++u)
                if (x + u * ax.span() >= d.a && x + u * ax.span() <= d.b && (!best || t < best->first)) best = std::pair{t, d.id};
        }
    }
    return best;
}

bool in_domain(const CSpaceRequest& r, const Eigen::Vector2d& q) {
    for (std::size_t k = 0; k < 2; ++k) {
        const auto& a = r.axes[k];
        if (!a.periodic && (q[static_cast<Eigen::Index>(k)] < a.lo || q[static_cast<Eigen::Index>(k)] > a.hi)) return false;
    }
    return true;
}

struct FaceWalks {
    int walks = 0, to_divisions = 0, to_contacts = 0, unchecked = 0;
    std::vector<std::string> missed;
};

// FaceWalks from each face's sample along each motion, in steps under a quarter cell, to the first division or
// contact, and checks it against the face's next places under that motion.
FaceWalks walk_from_faces(const PairBuild& b) {
    const CSpaceRequest& r = b.request;
    const auto& v = b.vocabulary;
    const auto pieces = division_pieces(r, v);
    const Eigen::Vector2d cell = cell_of(r);
    FaceWalks out;
    for (const auto& f : v.places) {
        if (f.kind != PlaceKind::face || f.points.empty()) continue;
        for (int s0 = -1; s0 <= 1; ++s0)
            for (int s1 = -1; s1 <= 1; ++s1) {
                if (s0 == 0 && s1 == 0) continue;
                const QualDirection motion{{static_cast<std::int8_t>(s0), static_cast<std::int8_t>(s1)}};
                std::set<std::uint32_t> next;
                for (const auto& a : v.adjacency)
                    if (a.from == f.id && a.motion == motion) next.insert(a.to.value);
                // Steps of a little under a quarter cell, a length no run of them makes a whole number of
                // cells (the faces' samples and many lines lie on the grid: a step ending exactly on a
                // line would cross it at neither step).
                const Eigen::Vector2d delta = Eigen::Vector2d(s0, s1).normalized().cwiseProduct(cell) * 0.2371;
                const int limit = 5 * (r.axes[0].samples + r.axes[1].samples);
                Eigen::Vector2d p = f.points.front();
                std::optional<std::uint32_t> met;
                Eigen::Vector2d at;
                bool contact = false, ended = false;
                for (int step = 0; step < limit && !met && !ended; ++step) {
                    const Eigen::Vector2d q = p + delta;
                    const auto crossing = first_crossing(r, pieces, p, q);
                    double t_block = 2;
                    if (!in_domain(r, q)) {
                        ended = true;  // a translation limit: its stops are another test's
                    } else if (b.oracle->blocked(wrap(r, q))) {
                        double lo = 0, hi = 1;  // free at lo, blocked at hi
                        for (int i = 0; i < 60; ++i) {
                            const double mid = 0.5 * (lo + hi);
                            (b.oracle->blocked(wrap(r, p + mid * delta)) ? hi : lo) = mid;
                        }
                        t_block = hi;
                    }
                    if (crossing && crossing->first <= t_block) {
                        met = crossing->second;
                        ended = false;
                    } else if (t_block <= 1) {
                        at = wrap(r, p + t_block * delta);
                        contact = true;
                        ended = true;
                    }
                    p = q;
                }
                if (!met && !contact) {
                    ++out.unchecked;
                    continue;
                }
                ++out.walks;
                bool named = false;
                std::ostringstream what;
                if (met) {
                    ++out.to_divisions;
                    named = next.count(*met) > 0;
                    what << "crosses division " << *met;
                } else {
                    ++out.to_contacts;
                    what << "meets the boundary at (" << at.x() << ", " << at.y() << "), near";
                    for (const auto& p2 : v.places) {
                        const bool contact_place = p2.kind == PlaceKind::cseg || p2.kind == PlaceKind::join || p2.kind == PlaceKind::stop;
                        if (!contact_place || cells_to(r, p2, at) > 0.05) continue;
                        what << " " << p2.id.value;
                        named = named || next.count(p2.id.value) > 0;
                    }
                }
                if (!named) {
                    std::ostringstream os;
                    os << b.name << ": face " << f.id.value << " under (" << s0 << " " << s1 << ") " << what.str() << "; next places:";
                    for (const auto n : next) os << " " << n;
                    out.missed.push_back(os.str());
                }
            }
    }
    return out;
}

// Slides along CSEGs that reach the join at the other end from the one they move towards.
std::vector<std::string> wrong_way_slides(const PairBuild& b, int& checked) {
    const CSpaceRequest& r = b.request;
    const auto& v = b.vocabulary;
    auto join_at = [&](const Eigen::Vector2d& q) -> std::optional<std::uint32_t> {
        for (const auto& p : v.places)
            if (p.kind == PlaceKind::join && difference(r, p.points.front(), q).cwiseQuotient(cell_of(r)).norm() < 1e-9) return p.id.value;
        return std::nullopt;
    };
    std::vector<std::string> out;
    for (const auto& c : v.places) {
        if (c.kind != PlaceKind::cseg || c.points.size() < 2) continue;
        const auto start = join_at(c.points.front()), end = join_at(c.points.back());
        if (!start || !end || *start == *end) continue;
        for (const auto& a : v.adjacency) {
            if (a.from != c.id || a.instantaneous || a.constrained || a.to == c.id) continue;
            int sign = 0;
            bool one_sign = true;
            for (std::size_t k = 0; k + 1 < c.points.size(); ++k) {
                const Eigen::Vector2d chord = difference(r, c.points[k], c.points[k + 1]).cwiseQuotient(cell_of(r));
                const double dot = chord.x() * a.motion.s[0] + chord.y() * a.motion.s[1];
                const int s = dot > 1e-9 * chord.norm() ? 1 : (dot < -1e-9 * chord.norm() ? -1 : 0);
                if (s == 0 || (sign != 0 && s != sign)) one_sign = false;
                sign = s;
            }
            if (!one_sign) continue;
            ++checked;
            const std::uint32_t towards = sign > 0 ? *end : *start;
            if (a.to.value != towards) {
                std::ostringstream os;
                os << b.name << ": CSEG " << c.id.value << " (from join " << *start << " to join " << *end << ") under ("
                   << int(a.motion.s[0]) << " " << int(a.motion.s[1]) << ") leads to " << a.to.value << ", not " << towards;
                out.push_back(os.str());
            }
        }
    }
    return out;
}

void check_walks(const PairBuild& b) {
    const FaceWalks w = walk_from_faces(b);
    MESSAGE(b.name << ": " << w.walks << " walks (" << w.to_divisions << " to divisions, " << w.to_contacts << " to contacts), "
                   << w.unchecked << " ending at a limit or nowhere");
    CHECK(w.walks > 0);
    for (const auto& m : w.missed) FAIL_CHECK(m);
}

// The walks from the faces of every pair of these mechanisms.
void check_walks(const std::vector<std::string>& files) {
    for (const auto& file : files)
        for (const auto& b : bundled_pairs(file)) check_walks(b);
}

// The pairs of the first 200 random drawings (tests/support/random_mechanism.hpp) the geometry
// takes, each handed to `check`; how many there were.
int for_random_pairs(const std::function<void(const PairBuild&)>& check) {
    int pairs = 0;
    for (int seed = 1; pairs < 200 && seed < 4000; ++seed) {
        const std::string text = qm::test::random_mechanism_text(seed);
        CAPTURE(text);
        qm::Diagnostics d;
        const auto m = read_mechanism("random-" + std::to_string(seed) + ".def", text, d);
        if (!m) continue;
        for (const auto& b : pairs_of(*m, "random-" + std::to_string(seed), false)) {
            ++pairs;
            check(b);
        }
    }
    return pairs;
}

}  // namespace

TEST_CASE("geometry/boundary_reach: [large] a slide along a CSEG reaches the join it moves towards, on every bundled pair") {
    int checked = 0;
    for (const auto* file : {"geneva_detent.def", "escapement.def", "ratchet.def", "pawl_ratchet.def", "cam.def", "scotch_yoke.def", "crank_latch.def"})
        for (const auto& b : bundled_pairs(file))
            for (const auto& m : wrong_way_slides(b, checked)) FAIL_CHECK(m);
    MESSAGE(checked << " slides checked");
    CHECK(checked > 100);
}

TEST_CASE("geometry/boundary_reach: [large] the Geneva drive's, the escapement's and the pawl's motions meet the places their adjacency names") {
    check_walks({"geneva_detent.def", "escapement.def", "pawl_ratchet.def"});
}

TEST_CASE("geometry/boundary_reach: the ratchet's, cams', Scotch yoke's and crank latch's motions meet the places their adjacency names") {
    check_walks({"ratchet.def", "cam.def", "cam_free.def", "scotch_yoke.def", "crank_latch.def"});
}

TEST_CASE("geometry/boundary_reach: [large] random mechanisms' slides reach the joins they move towards") {
    int slides = 0;
    const int pairs = for_random_pairs([&](const PairBuild& b) {
        for (const auto& problem : wrong_way_slides(b, slides)) FAIL_CHECK(problem);
    });
    MESSAGE(pairs << " random pairs, " << slides << " slides checked");
    CHECK(pairs == 200);
    CHECK(slides > 1000);
}

// Known holes, which is why this check may fail: at the random drawings' grid (48 x 48) blocked
// features thinner than a cell go unseen (a walk meets blocked space with no boundary place within
// a twentieth of a cell), and faces bordered by such features, or by lines closer than a cell,
// lead elsewhere than the walk goes.
TEST_CASE("geometry/boundary_reach: [large] random mechanisms' motions meet the places their adjacency names" * doctest::may_fail()) {
    int walks = 0, missed = 0, unseen = 0, elsewhere = 0;
    const int pairs = for_random_pairs([&](const PairBuild& b) {
        const FaceWalks w = walk_from_faces(b);
        walks += w.walks;
        for (const auto& miss : w.missed) {
            ++missed;
            (miss.find("near;") != std::string::npos ? unseen : elsewhere) += 1;
            FAIL_CHECK(miss);
        }
    });
    MESSAGE(pairs << " random pairs, " << walks << " walks, " << missed << " missed: " << unseen << " into blocked space no place lies near, "
                  << elsewhere << " to a place not named");
    CHECK(pairs == 200);
    CHECK(missed == 0);
}
