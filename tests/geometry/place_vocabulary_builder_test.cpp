// tests/geometry/place_vocabulary_builder_test.cpp: place vocabularies (geometry/place_vocabulary_builder.hpp)
// on hand-made configuration spaces whose places can be counted by hand, and their stability
// when the space is moved, scaled or turned.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "geometry/detail/place_parts.hpp"

#include <doctest/doctest.h>
#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <numbers>

using namespace qm::geometry;

namespace {

class BoxOracle final : public PairOracle {  // blocked iff q in the open box (x0,x1) x (y0,y1)
public:
    BoxOracle(double x0, double x1, double y0, double y1) : x0_(x0), x1_(x1), y0_(y0), y1_(y1) {}
    bool blocked(const Eigen::Vector2d& q) const override { return q[0] > x0_ && q[0] < x1_ && q[1] > y0_ && q[1] < y1_; }
    Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override {
        const double d[4] = {q[0] - x0_, x1_ - q[0], q[1] - y0_, y1_ - q[1]};
        const int k = static_cast<int>(std::min_element(d, d + 4) - d);
        const Eigen::Vector2d n[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
        return n[k];
    }
    std::string fingerprint() const override { return "box"; }
private:
    double x0_, x1_, y0_, y1_;
};

class BandOracle final : public PairOracle {  // blocked iff y0 < q1 < y1
public:
    BandOracle(double y0, double y1) : y0_(y0), y1_(y1) {}
    bool blocked(const Eigen::Vector2d& q) const override { return q[1] > y0_ && q[1] < y1_; }
    Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override { return {0.0, q[1] < 0.5 * (y0_ + y1_) ? -1.0 : 1.0}; }
    std::string fingerprint() const override { return "band"; }
private:
    double y0_, y1_;
};

class NothingOracle final : public PairOracle {
public:
    bool blocked(const Eigen::Vector2d&) const override { return false; }
    Eigen::Vector2d free_normal(const Eigen::Vector2d&) const override { return {0, 0}; }
    std::string fingerprint() const override { return "nothing"; }
};

// A relabelling-invariant summary: each place's kind, join kind, normals and concavity, plus
// how many adjacencies connect each pair of kinds under each motion.
std::multiset<std::string> builder_signature(const PlaceVocabulary& v) {
    std::multiset<std::string> out;
    for (const auto& p : v.places) {
        std::ostringstream s;
        s << to_string(p.kind);
        if (p.kind == PlaceKind::join) s << ' ' << to_string(p.join_kind);
        for (auto n : p.normals) s << ' ' << to_string(n);
        if (p.concave) s << (*p.concave ? " concave" : " convex");
        out.insert(s.str());
    }
    for (const auto& a : v.adjacency) {
        std::ostringstream s;
        s << "adj " << to_string(v.at(a.from).kind) << ' ' << to_string(v.at(a.to).kind) << ' ' << to_string(a.motion)
          << (a.instantaneous ? " inst" : "") << (a.constrained ? " constrained" : "");
        out.insert(s.str());
    }
    return out;
}

PlaceRequest square_request(double lo, double hi, bool periodic, int n = 40) {
    PlaceRequest r;
    r.cspace.axes = {CSpaceAxis{lo, hi, periodic, n}, CSpaceAxis{lo, hi, periodic, n}};
    return r;
}

bool has(const PlaceVocabulary& v, PlaceId from, PlaceKind to, QualDirection d, bool inst, bool constrained) {
    return std::any_of(v.adjacency.begin(), v.adjacency.end(), [&](const Adjacency& a) {
        return a.from == from && v.at(a.to).kind == to && a.motion == d && a.instantaneous == inst && a.constrained == constrained;
    });
}

}  // namespace

TEST_CASE("geometry/place_vocabulary_builder: an all-free space is one unbounded full face") {
    NothingOracle none;
    const auto res = build_place_vocabulary(none, square_request(0, 1, true));
    REQUIRE(res.status == PlaceStatus::ok);
    REQUIRE(res.vocabulary.places.size() == 1);
    CHECK(res.vocabulary.places[0].kind == PlaceKind::face);
    CHECK(res.vocabulary.adjacency.size() == 8);  // stays itself under each of the 8 motions
    for (const auto& a : res.vocabulary.adjacency) CHECK((a.from == a.to && !a.instantaneous));
}

TEST_CASE("geometry/place_vocabulary_builder: CSEGs spanning the space parallel to an axis") {
    BandOracle band(0.3, 0.6);
    auto req = square_request(0, 1, true);
    const auto res = build_place_vocabulary(band, req);
    const auto& v = res.vocabulary;
    CHECK(v.count(PlaceKind::cseg) == 2);
    CHECK(v.count(PlaceKind::join) == 0);
    CHECK(v.count(PlaceKind::fsd) == 0);
    CHECK(v.count(PlaceKind::face) == 1);  // free space wraps around q1
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::cseg) continue;
        const bool upper = p.points.front()[1] > 0.45;
        CHECK(p.normals == std::vector<QualDirection>{QualDirection{{0, static_cast<std::int8_t>(upper ? 1 : -1)}}});
        const QualDirection up{{0, 1}}, down{{0, -1}}, right{{1, 0}};
        CHECK(has(v, p.id, PlaceKind::face, upper ? up : down, true, false));      // leaves instantly
        CHECK(has(v, p.id, PlaceKind::cseg, upper ? down : up, false, true));      // Law 2
        CHECK(has(v, p.id, PlaceKind::cseg, right, false, false));                 // slides, no joins
    }
    req.cspace.axes[1].periodic = false;  // now the band splits free space in two
    CHECK(build_place_vocabulary(band, req).vocabulary.count(PlaceKind::face) == 2);
}

TEST_CASE("geometry/place_vocabulary_builder: a box obstacle has 4 CSEGs, 4 convex joins, 8 FSDs, 8 faces") {
    BoxOracle box(0.3, 0.6, 0.4, 0.7);
    const auto res = build_place_vocabulary(box, square_request(0, 1, false, 41));
    const auto& v = res.vocabulary;
    CHECK(v.count(PlaceKind::cseg) == 4);
    CHECK(v.count(PlaceKind::fsd) == 8);
    CHECK(v.count(PlaceKind::face) == 8);
    int corners = 0;
    std::set<QualDirection> normals;
    for (const auto& p : v.places) {
        if (p.kind == PlaceKind::cseg) normals.insert(p.normals.front());
        if (p.kind == PlaceKind::join && p.join_kind == JoinKind::normal_change) {
            ++corners;
            REQUIRE(p.concave.has_value());
            CHECK(!*p.concave);  // Def 30: the box's corners are convex
        }
    }
    CHECK(corners == 4);
    CHECK(normals == std::set<QualDirection>{{{-1, 0}}, {{1, 0}}, {{0, -1}}, {{0, 1}}});
    // Every adjacency names existing places and every place has a move under every motion.
    for (const auto& a : v.adjacency) CHECK(a.to.value < v.places.size());
    for (const auto& p : v.places) {
        std::set<QualDirection> moves;
        for (const auto& a : v.adjacency)
            if (a.from == p.id) moves.insert(a.motion);
        CHECK(moves.size() == 8);
    }
}

TEST_CASE("geometry/place_vocabulary_builder: a concave corner is a concave join") {
    // Blocked: the union of two bars forming an L; its inner corner is concave (Def 29).
    class Ell final : public PairOracle {
    public:
        bool blocked(const Eigen::Vector2d& q) const override {
            return (q[0] > 0.2 && q[0] < 0.4 && q[1] > 0.2 && q[1] < 0.8) || (q[0] > 0.2 && q[0] < 0.8 && q[1] > 0.2 && q[1] < 0.4);
        }
        Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override {
            // Nearest free direction among the L's six edges.
            struct E { double d; Eigen::Vector2d n; };
            std::vector<E> es = {{q[0] - 0.2, {-1, 0}}, {q[1] - 0.2, {0, -1}}, {0.8 - q[1], {0, 1}},
                                 {0.8 - q[0], {1, 0}}};
            if (q[1] > 0.4) es.push_back({std::abs(0.4 - q[0]), {1, 0}});
            if (q[0] > 0.4) es.push_back({std::abs(0.4 - q[1]), {0, 1}});
            if (q[1] >= 0.4 && q[0] <= 0.4) es.push_back({0.4 - q[0], {1, 0}});
            if (q[0] >= 0.4 && q[1] <= 0.4) es.push_back({0.4 - q[1], {0, 1}});
            return std::min_element(es.begin(), es.end(), [](const E& a, const E& b) { return std::abs(a.d) < std::abs(b.d); })->n;
        }
        std::string fingerprint() const override { return "ell"; }
    } ell;
    const auto res = build_place_vocabulary(ell, square_request(0, 1, false, 41));
    int concave = 0, convex = 0;
    for (const auto& p : res.vocabulary.places)
        if (p.kind == PlaceKind::join && p.join_kind == JoinKind::normal_change) (*p.concave ? concave : convex)++;
    CHECK(concave == 1);
    CHECK(convex == 5);
}

TEST_CASE("geometry/place_vocabulary_builder: the disk cam's vocabulary (hand count)") {
    // Boundary h = R + e sin(theta): normal (+ +) then (- +), joins at the lowest point (concave)
    // and the highest (convex); FSDs: up from both joins, and around theta from the highest.
    const auto c = disk_cam_and_follower();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    const auto v = build_place_vocabulary(c.exact, req).vocabulary;
    CHECK(v.count(PlaceKind::cseg) == 2);
    CHECK(v.count(PlaceKind::fsd) == 5);   // the loop split by the crossing, and three verticals
    CHECK(v.count(PlaceKind::face) == 4);  // the tangent at the top pinches the lower region
    int joins = 0;
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::join && p.join_kind == JoinKind::normal_change) {
            ++joins;
            CHECK(*p.concave == (p.points.front()[1] < 0.5));
        }
    CHECK(joins == 2);
}

TEST_CASE("geometry/place_vocabulary_builder: the vocabulary does not change when the space is moved or scaled") {
    for (double scale : {1e-3, 1.0, 1e3})
        for (double shift : {0.0, 7.25}) {
            // Edges off the sample grid: a sample exactly on a CSEG is on either side by rounding.
            BoxOracle base(0.31, 0.61, 0.41, 0.71);
            BoxOracle moved(shift + scale * 0.31, shift + scale * 0.61, shift + scale * 0.41, shift + scale * 0.71);
            auto req = square_request(shift, shift + scale, false, 41);
            req.cspace.boundary_tolerance = 1e-9 * scale;
            INFO("scale ", scale, " shift ", shift);
            const auto a = builder_signature(build_place_vocabulary(moved, req).vocabulary);
            const auto b = builder_signature(build_place_vocabulary(base, square_request(0, 1, false, 41)).vocabulary);
            std::vector<std::string> only_a, only_b;
            std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only_a));
            std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only_b));
            for (const auto& x : only_a) MESSAGE("only moved: ", x);
            for (const auto& x : only_b) MESSAGE("only base: ", x);
            CHECK(a == b);
        }
}

TEST_CASE("geometry/place_vocabulary_builder: rotating the whole scene by 90 degrees relabels nothing") {
    // The tessellated disk cam, drawn rotated by k * 90 degrees (pivot, polygons and follower axis):
    // the configuration space is the same, so the vocabulary must be the same.
    const auto c = disk_cam_and_follower();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    req.cspace.axes[0].samples = req.cspace.axes[1].samples = 32;
    const Polygon cam = tessellated_circle({0.2, 0}, 0.5, 1e-4);
    const Polygon follower = {{-2, 0}, {2, 0}, {2, 1}, {-2, 1}};
    std::multiset<std::string> first;
    for (int k = 0; k < 4; ++k) {
        const Eigen::Rotation2Dd rot(k * std::numbers::pi / 2);
        auto turn = [&](Polygon p) {
            for (auto& x : p) x = rot * x;
            return p;
        };
        PolygonPart a{{turn(cam)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}};
        PolygonPart b{{turn(follower)}, {PolygonDof::Kind::translation, {0, 0}, rot * Eigen::Vector2d(0, 1)}};
        const PolygonPairOracle oracle(a, b);
        const auto sig = builder_signature(build_place_vocabulary(oracle, req).vocabulary);
        if (k == 0) first = sig;
        CHECK(sig == first);
    }
}

TEST_CASE("geometry/place_vocabulary_builder: external divisions are ignored in blocked space") {
    BandOracle band(0.3, 0.6);
    auto req = square_request(0, 1, true);
    req.external.push_back({0, 0.5, "gravity flips"});  // the line q0 = 0.5, along q1
    const auto v = build_place_vocabulary(band, req).vocabulary;
    std::vector<const Place*> divs;
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::external_division) divs.push_back(&p);
    REQUIRE(divs.size() == 1);  // one free run from q1 = 0.6 around to 0.3
    CHECK(divs[0]->label == "gravity flips");
    CHECK(v.count(PlaceKind::face) == 1);  // cut once, the wrapped band is still one face
    req.external.push_back({0, 0.25, "again"});
    CHECK(build_place_vocabulary(band, req).vocabulary.count(PlaceKind::face) == 2);
    req.external.push_back({3, 0.25, "bad"});
    CHECK(build_place_vocabulary(band, req).status == PlaceStatus::bad_request);
}

TEST_CASE("geometry/place_vocabulary_builder: an external division free at an axis limit runs from that limit") {
    // On a non-periodic q1 axis [0, 1] with a band blocked at (y0, y1), the division line q0 = 0.5
    // has two free runs, one from each limit to the band; the run from the low limit starts at the
    // limit, not at a blocked-to-free change. Mirrored bands must give the same.
    for (const auto& [y0, y1] : {std::pair{0.3, 0.6}, std::pair{0.4, 0.7}}) {
        CAPTURE(y0);
        BandOracle band(y0, y1);
        auto req = square_request(0, 1, true);
        req.cspace.axes[1].periodic = false;
        req.external.push_back({0, 0.5, "torque changes sign"});
        const auto v = build_place_vocabulary(band, req).vocabulary;
        std::vector<double> lows, highs;
        for (const auto& p : v.places)
            if (p.kind == PlaceKind::external_division) {
                REQUIRE(p.points.size() >= 2);
                lows.push_back(std::min(p.points.front()[1], p.points.back()[1]));
                highs.push_back(std::max(p.points.front()[1], p.points.back()[1]));
            }
        REQUIRE(lows.size() == 2);
        std::sort(lows.begin(), lows.end());
        std::sort(highs.begin(), highs.end());
        CHECK(lows[0] == doctest::Approx(0.0));
        CHECK(highs[0] == doctest::Approx(y0).epsilon(1e-6));
        CHECK(lows[1] == doctest::Approx(y1).epsilon(1e-6));
        CHECK(highs[1] == doctest::Approx(1.0));
    }
}

TEST_CASE("geometry/place_vocabulary_builder: 8.1.6 merge epsilon absorbs a short run of another normal") {
    // A flat boundary with a tiny notch: blocked iff q1 < 0.5, or q1 < 0.52 for q0 in (0.5, 0.52).
    class Notch final : public PairOracle {
    public:
        bool blocked(const Eigen::Vector2d& q) const override { return q[1] < 0.5 || (q[1] < 0.52 && q[0] > 0.5 && q[0] < 0.52); }
        Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override {
            if (q[1] > 0.505 && q[1] < 0.5195 && std::min(std::abs(q[0] - 0.5), std::abs(q[0] - 0.52)) < 1e-6) return std::abs(q[0] - 0.5) < std::abs(q[0] - 0.52) ? Eigen::Vector2d(-1, 0) : Eigen::Vector2d(1, 0);
            return {0, 1};
        }
        std::string fingerprint() const override { return "notch"; }
    } notch;
    auto req = square_request(0, 1, true, 100);
    req.cspace.axes[1].periodic = false;
    req.cspace.axes[1].lo = 0.25;
    const auto fine = build_place_vocabulary(notch, req).vocabulary;
    req.merge_epsilon = 0.1;
    const auto coarse = build_place_vocabulary(notch, req).vocabulary;
    CHECK(fine.count(PlaceKind::cseg) > 1);
    CHECK(coarse.count(PlaceKind::cseg) == 1);
    CHECK(coarse.count(PlaceKind::join) == 0);
    req.merge_epsilon = -1;
    CHECK(build_place_vocabulary(notch, req).status == PlaceStatus::bad_request);
}

TEST_CASE("geometry/place_vocabulary_builder: zero play leaves no free face and does not fail") {
    // The crank pin in a slot exactly its width: free only on the curve q1 = 0.6 cos q0.
    const AnalyticOracle tight(
        "tight-pin", [](const Eigen::Vector2d& q) { return std::abs(0.6 * std::cos(q[0]) - q[1]); },
        [](const Eigen::Vector2d& q) {
            const double sg = 0.6 * std::cos(q[0]) - q[1] >= 0 ? 1.0 : -1.0;
            return Eigen::Vector2d(-sg * 0.6 * std::sin(q[0]), -sg);
        });
    PlaceRequest req;
    req.cspace.axes = pin_in_slot().axes;
    const auto res = build_place_vocabulary(tight, req);
    REQUIRE(res.status == PlaceStatus::ok);
    CHECK(res.vocabulary.count(PlaceKind::face) == 0);
    CHECK(res.space.boundary.empty());
}

TEST_CASE("geometry/place_vocabulary_builder: the tessellated closed-form pairs reach the exact pairs' place counts") {
    // Stability as tolerance shrinks (docs/ACCURACY.md): fine tessellation gives the smooth count.
    for (const auto& c : {disk_cam_and_follower(), pin_in_slot()}) {
        PlaceRequest req;
        req.cspace.axes = c.axes;
        req.cspace.axes[0].samples = req.cspace.axes[1].samples = 48;
        const auto exact = build_place_vocabulary(c.exact, req).vocabulary;
        const auto poly = c.tessellated(1e-4);
        const auto tess = build_place_vocabulary(poly, req).vocabulary;
        INFO(c.name);
        for (auto k : {PlaceKind::cseg, PlaceKind::join, PlaceKind::fsd, PlaceKind::face}) CHECK(tess.count(k) == exact.count(k));
    }
}

namespace {

// The face each side of a division place reaches (motion across it, both ways).
std::pair<std::optional<PlaceId>, std::optional<PlaceId>> sides(const PlaceVocabulary& v, const Place& d) {
    QualDirection up, down;
    up.s[static_cast<std::size_t>(1 - d.axis)] = 1;
    down.s[static_cast<std::size_t>(1 - d.axis)] = -1;
    std::optional<PlaceId> a, b;
    for (const auto& x : v.adjacency)
        if (x.from == d.id && v.at(x.to).kind == PlaceKind::face) (x.motion == up ? a : x.motion == down ? b : a) = x.to;
    return {a, b};
}

}  // namespace

TEST_CASE("geometry/place_vocabulary_builder: a division through grid samples still separates its two faces") {
    // On a grid of 64 samples per turn, the disk cam's FSDs from its highest and lowest points
    // (q0 = pi/2, 3 pi/2) run through sample columns. The samples on such a line belong to the
    // face below it (the cuts go between them and the next column); naming the face a third of
    // a cell above it by a zero offset put that point in the face below too: the FSD had one
    // face on both sides, and a face beside it no way out under (- 0). At 60 and 66 samples (off
    // the columns) and 64 the vocabulary must be the same. (Not at every grid: at 61, 63 and 65
    // the join at the tangent top lands a quarter cell off the top and its FSD along q0 is lost
    // or doubled, the sub-cell case of docs/ACCURACY.md.)
    const auto c = disk_cam_and_follower();
    std::multiset<std::string> first;
    for (int n : {64, 60, 66}) {
        PlaceRequest req;
        req.cspace.axes = c.axes;
        req.cspace.axes[0].samples = n;
        const auto v = build_place_vocabulary(c.exact, req).vocabulary;
        INFO("samples ", n);
        for (const auto& p : v.places)
            if (p.kind == PlaceKind::fsd) {
                const auto [a, b] = sides(v, p);
                REQUIRE(a);
                REQUIRE(b);
                CHECK(*a != *b);
            }
        if (n == 64) first = builder_signature(v);
        else CHECK(builder_signature(v) == first);
    }
}

TEST_CASE("geometry/place_vocabulary_builder: the ends of an axis that stops are stop places, blocked beyond") {
    // The disk cam with the follower's axis (q1, 0.2 .. 1) ending in stops: the top end is free
    // everywhere above the cam, so it is a stop of normal (0 -), split by the limit joins of the
    // two vertical FSDs that reach it; the bottom end lies in blocked space (no stop there).
    const auto c = disk_cam_and_follower();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    const auto without = build_place_vocabulary(c.exact, req).vocabulary;
    req.cspace.axes[1].stops = true;
    const auto v = build_place_vocabulary(c.exact, req).vocabulary;
    CHECK(without.count(PlaceKind::stop) == 0);
    REQUIRE(v.count(PlaceKind::stop) == 2);
    CHECK(v.places.size() == without.places.size() + 2);
    // Without stops a face at the top stays itself for ever under (0 +) (the follower rising
    // for ever); with them no face keeps a motion that moves the follower.
    auto faces_keep_rising = [](const PlaceVocabulary& x) {
        return std::count_if(x.adjacency.begin(), x.adjacency.end(), [&](const Adjacency& a) {
            return a.from == a.to && x.at(a.from).kind == PlaceKind::face && a.motion.s[1] != 0;
        });
    };
    CHECK(faces_keep_rising(without) > 0);
    CHECK(faces_keep_rising(v) == 0);
    for (const auto& p : v.places) {
        if (p.kind == PlaceKind::join && p.join_kind == JoinKind::limit) {
            INFO("limit join at ", p.points.front().transpose());
            CHECK(std::count(p.normals.begin(), p.normals.end(), QualDirection{{0, -1}}) == 1);
        }
        if (p.kind != PlaceKind::stop) continue;
        CHECK(p.normals == std::vector<QualDirection>{QualDirection{{0, -1}}});
        CHECK(p.axis == 0);
        for (const auto& pt : p.points) CHECK(pt[1] == doctest::Approx(1.0));
        for (const auto& a : v.adjacency) {
            if (a.from != p.id) continue;
            INFO("motion ", to_string(a.motion));
            if (a.motion.s[1] > 0) CHECK((a.constrained && a.to == p.id));              // out past the stop: Law 2
            if (a.motion.s[1] < 0) CHECK((a.instantaneous && v.at(a.to).kind == PlaceKind::face));  // back into free space
            if (a.motion.s[1] == 0) CHECK((!a.instantaneous && v.at(a.to).kind == PlaceKind::join));  // along it
        }
    }
}

TEST_CASE("geometry/place_vocabulary_builder: stops on two ending axes meet at the domain's corners") {
    // A box obstacle in the middle of [0, 1] x [0, 1], both axes ending in stops: each end is a
    // stop split where the box's FSDs reach it; the four corners of the domain are limit joins
    // with both stops' normals, and every motion out of the domain from one is constrained.
    BoxOracle box(0.31, 0.61, 0.41, 0.71);
    auto req = square_request(0, 1, false, 41);
    for (auto& a : req.cspace.axes) a.stops = true;
    const auto v = build_place_vocabulary(box, req).vocabulary;
    CHECK(v.count(PlaceKind::stop) == 4 * 3);  // each side cut by the two FSDs that reach it
    int corners = 0;
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::join || p.normals.size() != 2 || p.join_kind != JoinKind::limit) continue;
        ++corners;
        const Eigen::Vector2d x = p.points.front();
        const QualDirection out{{static_cast<std::int8_t>(x[0] < 0.5 ? -1 : 1), static_cast<std::int8_t>(x[1] < 0.5 ? -1 : 1)}};
        for (const auto& a : v.adjacency)
            if (a.from == p.id && (a.motion.s[0] == out.s[0] || a.motion.s[1] == out.s[1]) &&
                !(a.motion.s[0] == -out.s[0] || a.motion.s[1] == -out.s[1]))
                CHECK(a.constrained);
    }
    CHECK(corners == 4);
}

TEST_CASE("geometry/place_vocabulary_builder: a place without a next place or a constraint under some motion is incomplete") {
    // Every vocabulary the builder returns is complete (the box, the band, a space with stops),
    // and the check names what a broken one lacks.
    for (const PlaceVocabulary& v : {build_place_vocabulary(BoxOracle(0.31, 0.61, 0.41, 0.71), square_request(0, 1, false, 41)).vocabulary,
                                     build_place_vocabulary(BandOracle(0.4, 0.6), square_request(0, 1, true)).vocabulary})
        CHECK(!detail::incompleteness(square_request(0, 1, false).cspace, v));
    PlaceVocabulary v = build_place_vocabulary(BoxOracle(0.31, 0.61, 0.41, 0.71), square_request(0, 1, false, 41)).vocabulary;
    const QualDirection up{{0, 1}};
    const auto dropped = std::find_if(v.adjacency.begin(), v.adjacency.end(), [&](const Adjacency& a) { return a.from == PlaceId{0} && a.motion == up; });
    REQUIRE(dropped != v.adjacency.end());
    v.adjacency.erase(std::remove_if(v.adjacency.begin(), v.adjacency.end(), [&](const Adjacency& a) { return a.from == PlaceId{0} && a.motion == up; }),
                      v.adjacency.end());
    const auto why = detail::incompleteness(square_request(0, 1, false).cspace, v);
    REQUIRE(why);
    CHECK(*why == "place 0 (join) under motion (0 +) has neither a next place nor a constraint");
    // A face that leads only back to itself along an axis ending in stops: incomplete there.
    auto stops = square_request(0, 1, false);
    stops.cspace.axes[1].stops = true;
    PlaceVocabulary one;
    one.places.push_back(Place{});
    for (std::int8_t a = -1; a <= 1; ++a)
        for (std::int8_t b = -1; b <= 1; ++b)
            if (a != 0 || b != 0) one.adjacency.push_back({PlaceId{0}, PlaceId{0}, QualDirection{{a, b}}, false, false});
    CHECK(detail::incompleteness(stops.cspace, one).has_value());
    stops.cspace.axes[1].stops = false;
    CHECK(!detail::incompleteness(stops.cspace, one));
}
