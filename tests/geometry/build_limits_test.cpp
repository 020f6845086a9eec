// tests/geometry/build_limits_test.cpp: the bounds on what the geometry builds (geometry/
// build_limits.hpp): the measures against independent computations, the scene
// checker refusing what exceeds them before anything is built (the 1e9 gear), the grid limit of
// --places, and FCL model builds that run out of memory reported, never a crash (a child process
// under an address-space limit).
#include "mechanism_text.hpp"
#include "geometry/build_limits.hpp"
#include "geometry/contact_detection.hpp"
#include "geometry/fcl_pair_oracle.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/part_generators.hpp"
#include "qm/address_sanitizer.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace qm::geometry;

namespace {

Part generated(const char* generator, const std::vector<std::pair<std::string, double>>& params, PolygonDof::Kind kind) {
    const auto r = make_shape(generator, params);
    REQUIRE(r.shape);
    Part p;
    p.name = generator;
    p.profiles = r.shape->profiles;
    p.dof.kind = kind;
    return p;
}

std::string errors(const std::string& text) {
    qm::Diagnostics d;
    const auto m = read_mechanism("l.def", text, d);
    std::ostringstream os;
    d.print(os);
    CHECK(m.has_value() == !d.has_errors());
    return os.str();
}

}  // namespace

TEST_CASE("geometry/build_limits: chords_needed is the number of chords tessellate() cuts the arcs into") {
    for (const auto& [generator, params] : std::vector<std::pair<const char*, std::vector<std::pair<std::string, double>>>>{
             {"spur-gear", {{"teeth", 17}}}, {"scape-wheel", {}}, {"anchor", {}}, {"disk-cam", {{"radius", 3}}}, {"pawl", {}}}) {
        const Part p = generated(generator, params, PolygonDof::Kind::rotation);
        for (double t : {1e-2, 1e-4, 1e-6, 1e-8}) {
            // Independently: every segment gives one vertex at its start, an arc of n chords n - 1 more.
            std::size_t vertices = 0, segments = 0, lines = 0;
            for (const auto& profile : p.profiles) {
                vertices += tessellate(profile, t).size();
                segments += profile.segments.size();
                for (const auto& s : profile.segments) lines += !s.is_arc();
            }
            INFO(generator << " at " << t);
            CHECK(chords_needed(p, t) == static_cast<double>(vertices - segments + (segments - lines)));
        }
    }
    Part circle;
    circle.profiles = {circle_profile({0, 0}, 1)};
    CHECK(std::isinf(chords_needed(circle, 0.0)));
    CHECK(std::isinf(chords_needed(circle, -1.0)));
}

TEST_CASE("geometry/build_limits: coordinate_magnitude bounds the outline at every coordinate") {
    std::mt19937 rng(19);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 40; ++trial) {
        Part p = generated(trial % 2 ? "ratchet-wheel" : "pawl", {}, static_cast<PolygonDof::Kind>(trial % 3));
        const Eigen::Isometry2d place = Eigen::Translation2d(5 * u(rng), 5 * u(rng)) * Eigen::Rotation2Dd(3 * u(rng));
        for (auto& profile : p.profiles) profile = transformed(profile, place);
        p.dof.pivot = {3 * u(rng), 3 * u(rng)};
        p.dof.axis = Eigen::Vector2d(u(rng), u(rng) + 2).normalized();
        p.lo = -2 + u(rng);
        p.hi = 2 + u(rng);
        const double bound = coordinate_magnitude(p);
        double seen = 0;
        for (int k = 0; k <= 64; ++k) {
            const double q = p.translates() ? p.lo + (p.hi - p.lo) * k / 64 : 2 * std::numbers::pi * k / 64;
            for (const auto& profile : p.profiles)
                for (const auto& x : tessellate(profile, 1e-3)) seen = std::max(seen, (p.pose(q) * x).cwiseAbs().maxCoeff());
        }
        CHECK(seen <= bound * (1 + 1e-12));
        CHECK(seen >= 0.5 * bound);  // not uselessly loose
    }
}

TEST_CASE("geometry/build_limits: the suggested chordal tolerance is just enough") {
    for (double radius : {1e7, 1e8, 1e9}) {
        const Part cam = generated("disk-cam", {{"radius", radius}}, PolygonDof::Kind::rotation);
        const double pair_size = 2.0, r = chordal_tolerance_for_limit(cam, 1e-4, pair_size);
        INFO("radius " << radius);
        CHECK(chords_needed(cam, 1e-4 * pair_size) > max_chords_per_part);
        CHECK(chords_needed(cam, r * pair_size) <= max_chords_per_part);
        CHECK(chords_needed(cam, r * (1 - 1e-5) * pair_size) > max_chords_per_part);
    }
    const Part small = generated("disk-cam", {}, PolygonDof::Kind::rotation);
    CHECK(chordal_tolerance_for_limit(small, 1e-4, 1.0) == 1e-4);  // already within
}

TEST_CASE("geometry/build_limits: a gear of pitch radius 1e9 is refused where the scene is read, at the suggested tolerance not") {
    // Built, it would exhaust FCL's memory for its BVH, after which fcl::collide crashes.
    auto train = [](const std::string& settings) {
        return "(Defmechanism gear-train Settings (" + settings +
               ") Parts ((gear-1 (spur-gear (teeth 12) (pitch-radius 1e9) (play 0.02)) (rotation))"
               " (gear-2 (spur-gear (teeth 18) (pitch-radius 1.5) (play 0.02)) (at 2.5 0) (turn 10) (rotation)))"
               " Pairs ((gear-1 gear-2)))";
    };
    const std::string e = errors(train(""));
    CHECK(e.find("l.def:1:") == 0);
    CHECK(e.find("part 'gear-1' would be cut into") != std::string::npos);
    CHECK(e.find("raise chordal-tolerance to at least 0.071") != std::string::npos);
    CHECK(errors(train("(chordal-tolerance 0.071)")).empty());
    CHECK(errors(train("(chordal-tolerance 0.070)")).find("part 'gear-1'") != std::string::npos);  // rounded up to 2 digits
}

TEST_CASE("geometry/build_limits: every candidate pair is bounded without a Pairs section, declared pairs exactly") {
    const std::string parts = " Parts ((big (circle (0 0) 1e7) (rotation)) (small (block) (at 3e7 0) (rotation)) (other (block) (at -3e7 0) (rotation)))";
    // Undeclared, 'big' may pair with a part 1.4 across: too many chords; declared with nothing small, fine.
    CHECK(errors("(Defmechanism u" + parts + ")").find("part 'big' would be cut into") != std::string::npos);
    CHECK(errors("(Defmechanism d" + parts + " Pairs ((small other)))").empty());
}

TEST_CASE("geometry/build_limits: the grids of all pairs together are bounded, located at the largest") {
    auto scene = [](int n) {
        return "(Defmechanism g Parts ((a (block) (rotation)) (b (block) (at 1.3 0) (rotation)) (c (block) (at 0 1.3) (rotation)))"
               " Pairs ((a b (grid " + std::to_string(n) + " 4096)) (a c (grid 16 16))))";
    };
    const auto fits = qm::geometry::test::read(scene(4092));
    qm::Diagnostics d;
    CHECK(check_grid_limit(fits, kinematic_pairs(fits), d));  // 4092 x 4096 + 256 <= 4096^2
    CHECK(d.items().empty());
    const auto over = qm::geometry::test::read(scene(4096));
    CHECK(!check_grid_limit(over, kinematic_pairs(over), d));
    std::ostringstream os;
    d.print(os);
    CHECK(os.str().find("v.def:1:") == 0);
    CHECK(os.str().find("16777472 samples together, more than the limit of 16777216; this pair's grid is 4096 x 4096") != std::string::npos);
}

#ifndef QM_UNDER_ASAN
namespace {

// The process's address space now (VmSize), in bytes.
std::size_t address_space() {
    std::ifstream in("/proc/self/status");
    std::string key;
    std::size_t kb = 0;
    while (in >> key)
        if (key == "VmSize:" && in >> kb) return kb * 1024;
    return 0;
}

// In a child under an address-space limit of `extra` bytes above what it uses, build the FCL
// oracle of two disks near the chord limit and query it. Exit status: 0 built and queried, 3 FCL
// reported the failure (ModelBuildError naming its status), 4 our own allocation failed
// (ModelBuildError from bad_alloc), 5 any other exception. A signal means a crash.
int child_status(std::size_t extra) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        std::freopen("/dev/null", "w", stderr);  // FCL prints its failure on std::cerr
        const rlimit limit{address_space() + extra, address_space() + extra};
        ::setrlimit(RLIMIT_AS, &limit);
        try {
            Part a, b;
            a.profiles = {circle_profile({0, 0}, 1)};
            b.profiles = {circle_profile({2.5, 0}, 1)};
            a.dof.kind = b.dof.kind = PolygonDof::Kind::rotation;
            b.dof.pivot = {2.5, 0};
            const double chordal = 8e-9;  // about 2 x 26,000 chords: a few tens of MB
            REQUIRE(chords_needed(a, chordal) <= max_chords_per_part);
            const FclPairOracle oracle(a, b, chordal);
            (void)oracle.blocked({0.1, 0.2});
            (void)detect_contacts(oracle, {0.1, 0.2}, {1e-3, 1e-6});
            ::_exit(0);
        } catch (const ModelBuildError& e) {
            ::_exit(std::string(e.what()).find("returned BVH_ERR_MODEL_OUT_OF_MEMORY") != std::string::npos ? 3 : 4);
        } catch (...) {
            ::_exit(5);
        }
    }
    int raw = 0;
    ::waitpid(pid, &raw, 0);
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -WTERMSIG(raw);
}

}  // namespace

TEST_CASE("geometry/build_limits: an FCL model build that runs out of memory is reported, never a crash") {
    std::set<int> seen;
    for (std::size_t mb : {1, 2, 4, 8, 12, 16, 24, 32, 48, 64, 256}) {
        const int status = child_status(mb << 20);
        INFO(mb << " MB more address space: status " << status);
        CHECK(status >= 0);  // no signal
        CHECK(status != 5);
        seen.insert(status);
    }
    CHECK(seen.count(3) == 1);  // FCL's own failure was among them, caught
    CHECK(seen.count(0) == 1);  // and with room enough, it builds
}
#endif
