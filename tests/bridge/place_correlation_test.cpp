// tests/bridge/place_correlation_test.cpp: Def 34's metric half (bridge/place_correlation.hpp) on
// the pendulum between two stops: places reported apart cover disjoint values of the bar's angle
// (no point of one within the slack of a segment of the other), places not reported apart share a
// value, a face's sample lies in the values it covers and away from every place it is apart from,
// and the divisions where gravity flips are matched across the pairs.
#include "bridge/place_correlation.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <random>
#include <set>

using namespace qm;
namespace g = qm::geometry;

namespace {
// The bar's angles a line or join covers, sampled along its polyline (the short way round).
std::vector<double> angles(const g::Place& p) {
    std::vector<double> out;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
        out.push_back(p.points[i][0]);
        if (i + 1 < p.points.size()) {
            double x = p.points[i][0], y = p.points[i + 1][0];
            while (y - x > M_PI) y -= 2 * M_PI;
            while (x - y > M_PI) y += 2 * M_PI;
            for (int k = 1; k < 8; ++k) out.push_back(x + (y - x) * k / 8.0);
        }
    }
    return out;
}
double circular_gap(double a, double b) {
    double d = std::fmod(std::abs(a - b), 2 * M_PI);
    return std::min(d, 2 * M_PI - d);
}
// Whether angle x lies in one of a face's spans (each standing for its copies a turn apart).
bool in_covers(const g::Place& face, double x) {
    for (const auto& c : face.covers[0])
        for (int k = -1; k <= 1; ++k)
            if (x + k * 2 * M_PI >= c.lo && x + k * 2 * M_PI <= c.hi) return true;
    return false;
}
}  // namespace

TEST_CASE("bridge/place_correlation: the pendulum's places in its two pairs") {
    Diagnostics d;
    const auto m = g::read_mechanism_file((std::filesystem::path(QM_SOURCE_DIR) / "tests/envision/scenes/pendulum_stops.def").string(), d);
    REQUIRE(m.has_value());
    const auto pairs = g::kinematic_pairs(*m).modelled;
    REQUIRE(pairs.size() == 2);
    std::vector<g::PlaceVocabulary> v;
    std::vector<g::PlaceRequest> r;
    for (const auto& p : pairs) {
        r.push_back(g::place_request(*m, p));
        v.push_back(g::build_place_vocabulary(*g::pair_oracle(*m, p), r.back()).vocabulary);
    }
    const auto apart = bridge::places_apart(v[0], 0, r[0].cspace.axes[0], v[1], 0, r[1].cspace.axes[0]);
    const std::set<std::pair<g::PlaceId, g::PlaceId>> set(apart.begin(), apart.end());
    CHECK(!apart.empty());
    const double slack = 1e-6 * 2 * M_PI;
    std::size_t shared = 0, faces_apart = 0;
    for (const auto& a : v[0].places)
        for (const auto& b : v[1].places) {
            const bool is_apart = set.count({a.id, b.id}) == 1;
            if (a.kind == g::PlaceKind::face || b.kind == g::PlaceKind::face) {
                CAPTURE(a.id.value);
                CAPTURE(b.id.value);
                for (const auto* f : {&a, &b})
                    if (f->kind == g::PlaceKind::face) CHECK(in_covers(*f, f->points.front()[0]));
                if (!is_apart) continue;
                ++faces_apart;
                // The face's own sample is not where the other place is.
                const g::Place& face = a.kind == g::PlaceKind::face ? a : b;
                const g::Place& other = a.kind == g::PlaceKind::face ? b : a;
                if (other.kind == g::PlaceKind::face) CHECK(!in_covers(other, face.points.front()[0]));
                else
                    for (const double y : angles(other)) CHECK(!in_covers(face, y));
                continue;
            }
            double nearest = 10;
            for (const double x : angles(a))
                for (const double y : angles(b)) nearest = std::min(nearest, circular_gap(x, y));
            CAPTURE(a.id.value);
            CAPTURE(b.id.value);
            if (is_apart) CHECK(nearest > slack);
            else {
                CHECK(nearest < 0.2);  // a point and a segment's sample meet within a sampling step
                ++shared;
            }
        }
    CHECK(shared > 0);
    CHECK(faces_apart > 0);
    // A vocabulary against itself: every line and join overlaps itself.
    for (const auto& [x, y] : bridge::places_apart(v[0], 0, r[0].cspace.axes[0], v[0], 0, r[0].cspace.axes[0])) CHECK(x != y);
    // Axes that differ are not compared.
    g::CSpaceAxis other = r[1].cspace.axes[0];
    other.hi = other.lo + 1.0;
    CHECK(bridge::places_apart(v[0], 0, r[0].cspace.axes[0], v[1], 0, other).empty());
}

namespace {
g::Place face_over(std::uint32_t id, std::vector<g::Span> spans) {
    g::Place p;
    p.id = g::PlaceId{id};
    p.kind = g::PlaceKind::face;
    p.points = {Eigen::Vector2d(spans.front().lo, 0.0)};
    p.covers[0] = std::move(spans);
    p.covers[1] = {{0.0, 1.0}};
    return p;
}
}  // namespace

TEST_CASE("bridge/place_correlation: places go round a periodic axis only when their values cover all of it") {
    g::CSpaceAxis turn;
    turn.lo = 0.0;
    turn.hi = 2 * M_PI;
    turn.periodic = true;
    g::PlaceVocabulary v;
    v.places = {face_over(0, {{0.0, 3.0}}), face_over(1, {{2.9, 2 * M_PI + 0.05}}), face_over(2, {{-0.4, 2.0}})};
    g::Place seg;  // a CSEG from 5.9 across the seam to 0.3, the short way round
    seg.id = g::PlaceId{3};
    seg.kind = g::PlaceKind::cseg;
    seg.points = {Eigen::Vector2d(5.9, 0.5), Eigen::Vector2d(6.2, 0.5), Eigen::Vector2d(0.3, 0.5)};
    v.places.push_back(seg);
    g::Place unknown;  // no values known: taken to cover them all
    unknown.id = g::PlaceId{4};
    unknown.kind = g::PlaceKind::face;
    v.places.push_back(unknown);
    auto round = [&](std::vector<std::uint32_t> ids, const g::CSpaceAxis& axis) {
        std::vector<g::PlaceId> p;
        for (const auto i : ids) p.push_back(g::PlaceId{i});
        return bridge::places_go_round(v, p, 0, axis);
    };
    CHECK(round({0, 1}, turn));
    CHECK(!round({0}, turn));
    CHECK(!round({1}, turn));         // 0.05 past the seam leaves [0.05, 2.9) out
    CHECK(!round({2, 1}, turn));      // -0.4 stands for 2 pi - 0.4 across the seam; (2.0, 2.9) left out
    CHECK(round({2, 1, 0}, turn));
    CHECK(!round({0, 3}, turn));      // [0, 3] and [5.9, 2 pi + 0.3] leave (3, 5.9) out
    CHECK(round({4}, turn));
    g::CSpaceAxis stroke = turn;
    stroke.periodic = false;
    CHECK(!round({0, 1, 4}, stroke));  // a bounded coordinate never comes round
}

TEST_CASE("bridge/place_correlation: places_go_round agrees with sampling the circle (random seeded faces)") {
    g::CSpaceAxis turn;
    turn.lo = -1.0;
    turn.hi = 3.0;
    turn.periodic = true;
    std::mt19937 random(20261204);
    auto draw = [&](int n) { return static_cast<int>(random() % static_cast<unsigned>(n)); };
    for (int trial = 0; trial < 500; ++trial) {
        g::PlaceVocabulary v;
        std::vector<g::PlaceId> ids;
        const int n = 1 + draw(4);
        for (int k = 0; k < n; ++k) {
            // Endpoints on a lattice of 1/8, anywhere within two periods, so that no gap is
            // thinner than the slack.
            const double lo = -5.0 + draw(80) / 8.0, len = draw(20) / 8.0;
            v.places.push_back(face_over(static_cast<std::uint32_t>(k), {{lo, lo + len}}));
            ids.push_back(g::PlaceId{static_cast<std::uint32_t>(k)});
        }
        bool all = true;
        for (int i = 0; i < 4000 && all; ++i) {
            const double x = turn.lo + (i + 0.5) * turn.span() / 4000;
            bool in = false;
            for (const auto& p : v.places)
                for (int k = -3; k <= 3; ++k) in = in || (x + k * turn.span() >= p.covers[0][0].lo && x + k * turn.span() <= p.covers[0][0].hi);
            all = in;
        }
        CAPTURE(trial);
        CHECK(bridge::places_go_round(v, ids, 0, turn) == all);
    }
}
