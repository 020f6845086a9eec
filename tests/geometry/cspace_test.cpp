// tests/geometry/cspace_test.cpp: classification and boundary location (geometry/cspace.hpp),
// checked against the closed-form contact functions of closed_form_pairs.hpp.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/cspace.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <numbers>

using namespace qm::geometry;

namespace {
// Blocked iff q1 lies in (a, b): a CSEG pair spanning the space parallel to axis 0.
class Band final : public PairOracle {
public:
    Band(double a, double b) : a_(a), b_(b) {}
    bool blocked(const Eigen::Vector2d& q) const override { return q[1] > a_ && q[1] < b_; }
    Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override {
        return {0.0, q[1] < 0.5 * (a_ + b_) ? -1.0 : 1.0};
    }
    std::string fingerprint() const override { return "band"; }
private:
    double a_, b_;
};
class Nothing final : public PairOracle {
public:
    bool blocked(const Eigen::Vector2d&) const override { return false; }
    Eigen::Vector2d free_normal(const Eigen::Vector2d&) const override { return {0, 0}; }
    std::string fingerprint() const override { return "nothing"; }
};
}  // namespace

TEST_CASE("geometry/cspace: boundary points of the closed-form pairs lie within the requested tolerance") {
    for (const auto& c : {bar_and_block(), disk_cam_and_follower(), two_disks(), pin_in_slot()}) {
        for (double tol : {1e-3, 1e-6, 1e-9}) {
            CSpaceRequest req;
            req.axes = c.axes;
            req.boundary_tolerance = tol;
            const auto res = classify_cspace(c.exact, req);
            REQUIRE(res.status == CSpaceStatus::ok);
            REQUIRE(!res.boundary.empty());
            for (const auto& p : res.boundary) {
                INFO(c.name, " tol ", tol, " q ", p.q.transpose());
                CHECK(c.exact.crossing_error(p.q, p.axis) <= 0.5 * tol + 1e-12);
                // The normal comes from the geometry and points from the blocked sample to the free one.
                const double along = p.normal[p.axis];
                CHECK((p.low_side_blocked ? along >= 0 : along <= 0));
            }
        }
    }
}

TEST_CASE("geometry/cspace: classification matches the oracle at every sample") {
    const auto c = two_disks();
    CSpaceRequest req;
    req.axes = c.axes;
    const auto res = classify_cspace(c.exact, req);
    for (int j = 0; j < req.axes[1].samples; ++j)
        for (int i = 0; i < req.axes[0].samples; ++i)
            CHECK(res.is_blocked(i, j) == c.exact.blocked({req.axes[0].sample(i), req.axes[1].sample(j)}));
}

TEST_CASE("geometry/cspace: the tessellated pair agrees with the exact one to the chordal tolerance") {
    const auto c = disk_cam_and_follower();
    const auto poly = c.tessellated(1e-5);
    CSpaceRequest req;
    req.axes = c.axes;
    req.axes[0].samples = req.axes[1].samples = 24;
    req.boundary_tolerance = 1e-9;
    const auto res = classify_cspace(poly, req);
    REQUIRE(!res.boundary.empty());
    for (const auto& p : res.boundary) {
        CHECK(c.exact.normal_distance(p.q) <= 2e-5);
        // Qualitative normals agree with the exact gradient away from its zero crossings.
        const Eigen::Vector2d exact = c.exact.free_normal(p.q).normalized();
        for (int k = 0; k < 2; ++k)
            if (std::abs(exact[k]) > 0.05) CHECK(p.qual.s[static_cast<std::size_t>(k)] == (exact[k] > 0 ? 1 : -1));
    }
}

TEST_CASE("geometry/cspace: periodic axes wrap, so boundary crossing the seam is found") {
    // Blocked band across q1 = 0 on a periodic axis [-1, 1): it crosses the seam at q1 = +-1.
    class Seam final : public PairOracle {
    public:
        bool blocked(const Eigen::Vector2d& q) const override { return std::abs(q[1]) > 0.9; }
        Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override { return {0.0, q[1] > 0 ? -1.0 : 1.0}; }
        std::string fingerprint() const override { return "seam"; }
    } seam;
    CSpaceRequest req;
    req.axes = {CSpaceAxis{-1, 1, true, 8}, CSpaceAxis{-1, 1, true, 16}};
    const auto res = classify_cspace(seam, req);
    REQUIRE(res.boundary.size() == 16);  // two crossings per column of 8
    for (const auto& p : res.boundary) {
        CHECK(std::abs(std::abs(p.q[1]) - 0.9) < 1e-8);
        CHECK(p.qual == QualDirection{{0, static_cast<std::int8_t>(p.q[1] > 0 ? -1 : 1)}});
    }
}

TEST_CASE("geometry/cspace: a normal within tolerance of an axis has sign 0") {
    Band band(0.3, 0.6);
    CSpaceRequest req;
    req.axes = {CSpaceAxis{0, 1, true, 16}, CSpaceAxis{0, 1, false, 16}};
    const auto res = classify_cspace(band, req);
    for (const auto& p : res.boundary) CHECK(p.qual.s[0] == 0);
    CHECK(qualitative({1e-9, 1.0}, 1e-6) == QualDirection{{0, 1}});
    CHECK(qualitative({-1e-9, -1.0}, 1e-6) == QualDirection{{0, -1}});
    CHECK(qualitative({1e-3, 1.0}, 1e-6) == QualDirection{{1, 1}});
}

TEST_CASE("geometry/cspace: an all-free space has no boundary") {
    Nothing none;
    CSpaceRequest req;
    req.axes = {CSpaceAxis{0, 1, true, 8}, CSpaceAxis{0, 1, true, 8}};
    const auto res = classify_cspace(none, req);
    CHECK(res.all_free());
    CHECK(res.boundary.empty());
}

TEST_CASE("geometry/cspace: bad requests are reported in the result, not thrown") {
    Nothing none;
    CSpaceRequest req;
    req.axes = {CSpaceAxis{0, 1, true, 8}, CSpaceAxis{0, 1, true, 8}};
    auto bad = req;
    bad.boundary_tolerance = 0;
    CHECK(classify_cspace(none, bad).status == CSpaceStatus::bad_request);
    bad = req;
    bad.boundary_tolerance = -1;
    CHECK(classify_cspace(none, bad).status == CSpaceStatus::bad_request);
    bad = req;
    bad.axes[0].samples = 1;
    CHECK(classify_cspace(none, bad).status == CSpaceStatus::bad_request);
    bad = req;
    bad.axes[1].hi = bad.axes[1].lo;
    CHECK(classify_cspace(none, bad).status == CSpaceStatus::bad_request);
    bad = req;
    bad.normal_zero_tolerance = 0;
    CHECK(!classify_cspace(none, bad).message.empty());
    CHECK(classify_cspace(none, req).status == CSpaceStatus::ok);
}

TEST_CASE("geometry/cspace: bisection ends at a bracket one ulp wide, whatever the tolerance") {
    // With a tolerance finer than a double can resolve, the midpoint comes to equal an end and a
    // loop on the tolerance alone never ends; the scene checker refuses such settings, but the
    // algorithm must not rely on it.
    const Band band(0.3, 0.6);
    std::uint64_t calls = 0;
    const Eigen::Vector2d q = bisect_contact(band, {0.5, 0.25}, false, {0.5, 0.35}, 1e-300, calls);
    CHECK(q[1] == doctest::Approx(0.3).epsilon(1e-15));
    CHECK(calls < 200);  // about 53 halvings to exhaust a double's mantissa
}
