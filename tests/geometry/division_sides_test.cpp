// tests/geometry/division_sides_test.cpp: a division's piece borders one full face on each side
// and a face's values come from the lines that bound it (thesis 8.1.2, Def 32, Def 34), checked
// on bundled pairs with the pair's own FCL oracle, apart from the builder's faces:
//  - walking the length of a division's piece just beside it, on either side, through free space,
//    the walk crosses no other division (one ending on the piece splits it there: the faces
//    either side of that end are different faces, and each piece names one as next);
//  - a face thinner than a grid step spans no more of an axis than a fine flood fill from its own
//    sample reaches, give or take two steps (a CSEG that a division ends on is cut there, so the
//    face does not take the whole CSEG's values).
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"

#include "division_pieces.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <vector>

using namespace qm::geometry;
using qm::geometry::test::division_pieces;
using qm::geometry::test::Piece;

namespace {

struct Built {
    Mechanism mechanism;
    std::unique_ptr<PairOracle> oracle;
    PlaceRequest request;
    PlaceResult result;
};

Built build(const std::string& file, const std::string& a, const std::string& b) {
    qm::Diagnostics d;
    auto m = read_mechanism_file((std::filesystem::path(QM_SOURCE_DIR) / "scenarios/clock" / file).string(), d);
    REQUIRE(m);
    Built out{*m, nullptr, {}, {}};
    const auto pairs = kinematic_pairs(out.mechanism).modelled;
    const auto spec = std::find_if(pairs.begin(), pairs.end(), [&](const PairSpec& p) {
        return out.mechanism.parts[p.a].name == a && out.mechanism.parts[p.b].name == b;
    });
    REQUIRE(spec != pairs.end());
    out.oracle = pair_oracle(out.mechanism, *spec);
    out.request = place_request(out.mechanism, *spec);
    out.result = build_place_vocabulary(*out.oracle, out.request);
    REQUIRE(out.result.status == PlaceStatus::ok);
    return out;
}

// Is x within [lo, hi], or a copy of it a period on?
bool within(const CSpaceAxis& ax, double x, double lo, double hi) {
    for (int s = ax.periodic ? -2 : 0; s <= (ax.periodic ? 2 : 0); ++s)
        if (x + s * ax.span() >= lo && x + s * ax.span() <= hi) return true;
    return false;
}

// The division pieces a short segment from p to q parallel to an axis crosses, other than `not_this`.
std::vector<std::uint32_t> crossed(const CSpaceRequest& r, const std::vector<Piece>& pieces, const Eigen::Vector2d& p,
                                   const Eigen::Vector2d& q, std::uint32_t not_this) {
    std::vector<std::uint32_t> out;
    for (const auto& d : pieces) {
        if (d.id == not_this) continue;
        const int across = 1 - d.axis;  // the segment runs along this axis if it can cross d
        if (std::abs(p[d.axis] - q[d.axis]) > 0) continue;
        const auto& axc = r.axes[static_cast<std::size_t>(across)];
        const double lo = std::min(p[across], q[across]), hi = std::max(p[across], q[across]);
        if (within(axc, d.c, lo, hi) && within(r.axes[static_cast<std::size_t>(d.axis)], p[d.axis], d.a, d.b)) out.push_back(d.id);
    }
    return out;
}

// Walks along each division piece a hundredth of a cell to either side, from a sixth of a cell
// past one end to as far short of the other, in twentieths of a cell, over free space.
std::vector<std::string> divided_sides(const Built& b) {
    const CSpaceRequest& r = b.request.cspace;
    const auto& v = b.result.vocabulary;
    const auto pieces = division_pieces(r, v);
    std::vector<std::string> out;
    for (const auto& d : pieces) {
        const int across = 1 - d.axis;
        const double step = r.axes[static_cast<std::size_t>(d.axis)].step(), off = 0.01 * r.axes[static_cast<std::size_t>(across)].step();
        for (const double side : {-1.0, 1.0}) {
            Eigen::Vector2d last;
            bool have = false;
            for (double t = d.a + step / 6; t <= d.b - step / 6; t += step / 20) {
                Eigen::Vector2d q;
                q[d.axis] = t;
                q[across] = d.c + side * off;
                if (b.oracle->blocked(wrap(r, q))) {
                    have = false;
                    continue;
                }
                if (have)
                    for (const auto other : crossed(r, pieces, last, q, d.id)) {
                        std::ostringstream os;
                        os << "division " << d.id << " (along axis " << d.axis << " at " << d.c << ") is met on side " << side << " at "
                           << t << " by division " << other;
                        out.push_back(os.str());
                    }
                last = q;
                have = true;
            }
        }
    }
    return out;
}

// Faces thinner than a step along an axis whose values along some axis reach more than two steps
// beyond a flood fill from their own sample, on a grid anchored there.
std::vector<std::string> loose_slivers(const Built& b) {
    const CSpaceRequest& r = b.request.cspace;
    const auto& v = b.result.vocabulary;
    const auto pieces = division_pieces(r, v);
    std::vector<std::string> out;
    for (const auto& f : v.places) {
        if (f.kind != PlaceKind::face) continue;
        std::array<double, 2> width{};
        bool single = true;
        for (std::size_t k = 0; k < 2; ++k) {
            single = single && f.covers[k].size() == 1;
            if (single) width[k] = f.covers[k].front().hi - f.covers[k].front().lo;
        }
        if (!single || (width[0] >= r.axes[0].step() && width[1] >= r.axes[1].step())) continue;
        Eigen::Vector2d h;  // a sixteenth of a step, or a quarter of the face's values if narrower
        for (int k = 0; k < 2; ++k) h[k] = std::min(r.axes[static_cast<std::size_t>(k)].step() / 16, std::max(width[static_cast<std::size_t>(k)], 1e-9) / 4);
        const int n0 = static_cast<int>(std::ceil(width[0] / h[0])) + 64, n1 = static_cast<int>(std::ceil(width[1] / h[1])) + 64;
        if (static_cast<double>(n0) * n1 > 2e6) continue;
        // Offsets (i, j) from the seed, each within n0, n1 of it.
        struct Fill {
            std::size_t size = 0;
            std::array<double, 2> lo{}, hi{};
        };
        auto fill = [&](const Eigen::Vector2d& s) {
            std::vector<std::pair<int, int>> stack{{0, 0}};
            std::set<std::pair<int, int>> seen{{0, 0}};
            Fill out{1, {s[0], s[1]}, {s[0], s[1]}};
            while (!stack.empty() && seen.size() <= 20000) {
                const auto [i, j] = stack.back();
                stack.pop_back();
                const Eigen::Vector2d p = s + Eigen::Vector2d(i * h[0], j * h[1]);
                for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
                    const int ni = i + di, nj = j + dj;
                    if (std::abs(ni) > n0 || std::abs(nj) > n1 || seen.count({ni, nj})) continue;
                    const Eigen::Vector2d q = s + Eigen::Vector2d(ni * h[0], nj * h[1]);
                    bool inside = true;
                    for (int k = 0; k < 2; ++k) {
                        const auto& ax = r.axes[static_cast<std::size_t>(k)];
                        inside = inside && (ax.periodic || (q[k] >= ax.lo && q[k] <= ax.hi));
                    }
                    if (!inside || b.oracle->blocked(wrap(r, q)) || b.oracle->blocked(wrap(r, 0.5 * (p + q))) ||
                        !crossed(r, pieces, p, q, std::uint32_t(-1)).empty())
                        continue;
                    seen.insert({ni, nj});
                    stack.emplace_back(ni, nj);
                    for (std::size_t k = 0; k < 2; ++k) {
                        out.lo[k] = std::min(out.lo[k], q[static_cast<Eigen::Index>(k)]);
                        out.hi[k] = std::max(out.hi[k], q[static_cast<Eigen::Index>(k)]);
                    }
                }
            }
            out.size = seen.size();
            return out;
        };
        // From the face's sample, and half a fill step from it either way along each axis (a
        // sample on a line the grid put at a CSEG's value lies on the boundary, where the fill's
        // first steps meet blocked space by rounding): the largest fill.
        const Eigen::Vector2d s0 = f.points.front();
        Fill best = fill(s0);
        for (int k = 0; k < 2; ++k)
            for (const double dir : {-0.5, 0.5}) {
                Eigen::Vector2d s = s0;
                s[k] += dir * h[k];
                if (b.oracle->blocked(wrap(r, s)) || !crossed(r, pieces, s0, s, std::uint32_t(-1)).empty()) continue;
                if (const Fill x = fill(s); x.size > best.size) best = x;
            }
        if (best.size > 20000) continue;  // not a sliver after all
        const auto& lo = best.lo;
        const auto& hi = best.hi;
        for (std::size_t k = 0; k < 2; ++k) {
            const auto& ax = r.axes[k];
            const Span c = f.covers[k].front();
            // The fill's range moved by whole periods to lie over the values, on a periodic axis.
            double a = lo[k], z = hi[k];
            if (ax.periodic) {
                const double shift = ax.span() * std::round((0.5 * (c.lo + c.hi) - 0.5 * (a + z)) / ax.span());
                a += shift;
                z += shift;
            }
            const double slack = 2 * ax.step();
            if (c.lo < a - slack || c.hi > z + slack) {
                std::ostringstream os;
                os << "face " << f.id.value << " axis " << k << " values [" << c.lo << ", " << c.hi << "], filled [" << a << ", " << z << "]";
                out.push_back(os.str());
            }
        }
    }
    return out;
}

std::string lines(const std::vector<std::string>& xs) {
    std::string out;
    for (const auto& x : xs) out += x + "\n";
    return out;
}

}  // namespace

TEST_CASE("geometry/division_sides: the pawl's lever/ratchet-wheel divisions each border one face a side") {
    const Built b = build("pawl_ratchet.def", "lever", "ratchet-wheel");
    const auto found = divided_sides(b);
    INFO(lines(found));
    CHECK(found.empty());
}

TEST_CASE("geometry/division_sides: [large] the Geneva drive's divisions each border one face a side") {
    for (const auto& [a, c] : {std::pair{"driver", "wheel"}, std::pair{"wheel", "detent"}}) {
        const Built b = build("geneva_detent.def", a, c);
        const auto found = divided_sides(b);
        INFO((std::string(a) + "/" + c + "\n" + lines(found)));
        CHECK(found.empty());
    }
}

TEST_CASE("geometry/division_sides: [large] the Geneva drive's driver/wheel slivers span no more than their fill") {
    const Built b = build("geneva_detent.def", "driver", "wheel");
    const auto found = loose_slivers(b);
    INFO(lines(found));
    CHECK(found.empty());
}
