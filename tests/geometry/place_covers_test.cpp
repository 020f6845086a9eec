// tests/geometry/place_covers_test.cpp: the values each face spans (Place::covers, by which Def 34
// correlates the places of pairs that share a part), against the configuration space sampled at
// twice the pair's grid with the pair's own FCL oracle, for the bundled mechanisms' pairs (the
// Geneva drive's wheel/detent always, others in a seeded sample): every free sample of a face
// lies within its values (a narrower face would drop real combinations of places), and its values
// reach no more than a grid step beyond its farthest sample. A sample's face is found apart from
// the builder: free samples are joined where the straight way between neighbours is free and
// crosses no division (Def 32: faces are bounded by CSEGs and divisions), and a component is the
// face whose own sample it holds.
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"

#include "division_pieces.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <sstream>

using namespace qm::geometry;
using qm::geometry::test::division_pieces;
using qm::geometry::test::Piece;

namespace {

constexpr int density = 2;  // dense samples per grid step

Mechanism load_mechanism(const std::string& name) {
    qm::Diagnostics d;
    auto m = read_mechanism_file((std::filesystem::path(QM_SOURCE_DIR) / "scenarios/clock" / name).string(), d);
    REQUIRE(m);
    return *m;
}

// The configuration space at `density` samples a grid step; on a periodic axis sample n wraps to 0.
struct Dense {
    const CSpaceRequest& r;
    std::array<int, 2> n{};
    explicit Dense(const CSpaceRequest& request) : r(request) {
        for (std::size_t k = 0; k < 2; ++k) {
            const auto& ax = r.axes[k];
            n[k] = ax.periodic ? ax.samples * density : (ax.samples - 1) * density + 1;
        }
    }
    [[nodiscard]] double h(int k) const { return r.axes[static_cast<std::size_t>(k)].step() / density; }
    [[nodiscard]] double at(int k, int i) const {
        const auto& ax = r.axes[static_cast<std::size_t>(k)];
        return !ax.periodic && i == n[static_cast<std::size_t>(k)] - 1 ? ax.hi : ax.lo + i * h(k);
    }
    [[nodiscard]] std::size_t index(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(j); }
};

// Is x within [lo, hi] (a copy of it a whole number of periods on, on a periodic axis)?
bool within(const CSpaceAxis& ax, double x, double lo, double hi, double slack) {
    for (int s = ax.periodic ? -2 : 0; s <= (ax.periodic ? 2 : 0); ++s) {
        const double y = x + s * ax.span();
        if (y >= lo - slack && y <= hi + slack) return true;
    }
    return false;
}

// Does the segment from p to q (q - p less than half a period on each axis) cross a division piece?
// A division ends on the boundary, which the samples see only to within the tessellation: it counts
// as reaching `reach` steps on, so that no way round its end passes between it and blocked space.
bool crosses(const CSpaceRequest& r, const std::vector<Piece>& pieces, const Eigen::Vector2d& p, const Eigen::Vector2d& q, double reach = 0.01) {
    for (const auto& d : pieces) {
        const int a = d.axis, b = 1 - a;
        const auto& axb = r.axes[static_cast<std::size_t>(b)];
        const double y0 = std::min(p[b], q[b]), y1 = std::max(p[b], q[b]);
        for (int s = axb.periodic ? -2 : 0; s <= (axb.periodic ? 2 : 0); ++s) {
            const double c = d.c + s * axb.span();
            if (c < y0 - 1e-12 || c > y1 + 1e-12) continue;
            const double t = y1 > y0 ? (c - p[b]) / (q[b] - p[b]) : 0.0;
            const double x = p[a] + std::clamp(t, 0.0, 1.0) * (q[a] - p[a]);
            if (within(r.axes[static_cast<std::size_t>(a)], x, d.a, d.b, reach * r.axes[static_cast<std::size_t>(a)].step())) return true;
        }
    }
    return false;
}

struct Report {
    std::size_t faces = 0, located = 0, ambiguous = 0, samples = 0, ends = 0, skipped = 0, slivers = 0;
    std::vector<std::string> unsound, loose;
};

// How far x lies outside a face's values along axis k, in grid steps (0 inside).
double outside(const CSpaceAxis& ax, const std::vector<Span>& covers, double x) {
    double out = std::numeric_limits<double>::infinity();
    for (const auto& s : covers)
        for (int c = ax.periodic ? -2 : 0; c <= (ax.periodic ? 2 : 0); ++c) {
            const double y = x + c * ax.span();
            out = std::min(out, std::max({0.0, s.lo - y, y - s.hi}) / ax.step());
        }
    return out;
}

// The free configurations a flood fill reaches from `seeds` on a grid `scale` times finer than the
// pair's, within a box: along axis k from `from` to `to`, along the other axis three steps either
// side of the seeds (coordinates unwrapped, as the seeds'). Free space is asked for lazily, so the
// fill costs what the face's part of the box holds. Empty if the box would be too large.
std::vector<Eigen::Vector2d> fine_fill(const PairOracle& oracle, const CSpaceRequest& r, const std::vector<Piece>& pieces,
                                       const std::vector<Eigen::Vector2d>& seeds, int k, double from, double to, int scale) {
    const int o = 1 - k;
    const auto& axk = r.axes[static_cast<std::size_t>(k)];
    const auto& axo = r.axes[static_cast<std::size_t>(o)];
    double k0 = std::min(from, to), k1 = std::max(from, to);
    double o0 = std::numeric_limits<double>::infinity(), o1 = -o0;
    for (const auto& x : seeds) {
        o0 = std::min(o0, x[o] - 3 * axo.step());
        o1 = std::max(o1, x[o] + 3 * axo.step());
    }
    if (!axk.periodic) k0 = std::max(k0, axk.lo), k1 = std::min(k1, axk.hi);
    if (!axo.periodic) o0 = std::max(o0, axo.lo), o1 = std::min(o1, axo.hi);
    const double hk = axk.step() / scale, ho = axo.step() / scale;
    const int nk = static_cast<int>(std::ceil((k1 - k0) / hk)) + 1, no = static_cast<int>(std::ceil((o1 - o0) / ho)) + 1;
    if (nk <= 0 || no <= 0 || static_cast<double>(nk) * no > 4e6) return {};
    auto point = [&](int i, int j) {
        Eigen::Vector2d p;
        p[k] = std::min(k0 + i * hk, k1);
        p[o] = std::min(o0 + j * ho, o1);
        return p;
    };
    std::vector<std::int8_t> state(static_cast<std::size_t>(nk) * static_cast<std::size_t>(no), -1);  // -1 unknown, 0 blocked, 1 free, 2 reached
    auto at = [&](int i, int j) -> std::int8_t& { return state[static_cast<std::size_t>(i) + static_cast<std::size_t>(nk) * static_cast<std::size_t>(j)]; };
    auto is_free = [&](int i, int j) {
        auto& s = at(i, j);
        if (s < 0) s = oracle.blocked(wrap(r, point(i, j))) ? 0 : 1;
        return s > 0;
    };
    std::vector<std::pair<int, int>> todo;
    for (const auto& x : seeds) {
        const int i = static_cast<int>(std::lround((x[k] - k0) / hk)), j = static_cast<int>(std::lround((x[o] - o0) / ho));
        if (i < 0 || i >= nk || j < 0 || j >= no || !is_free(i, j) || at(i, j) == 2) continue;
        const Eigen::Vector2d y = point(i, j);
        bool ok = !crosses(r, pieces, x, y);
        for (int t = 1; t < 4 && ok; ++t) ok = !oracle.blocked(wrap(r, x + (y - x) * t / 4.0));
        if (!ok) continue;
        at(i, j) = 2;
        todo.emplace_back(i, j);
    }
    std::vector<Eigen::Vector2d> out;
    while (!todo.empty()) {
        const auto [i, j] = todo.back();
        todo.pop_back();
        const Eigen::Vector2d p = point(i, j);
        out.push_back(p);
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
            const int ni = i + di, nj = j + dj;
            if (ni < 0 || ni >= nk || nj < 0 || nj >= no || at(ni, nj) == 2 || !is_free(ni, nj)) continue;
            const Eigen::Vector2d q = point(ni, nj);
            if (oracle.blocked(wrap(r, 0.5 * (p + q))) || crosses(r, pieces, p, q)) continue;
            at(ni, nj) = 2;
            todo.emplace_back(ni, nj);
        }
    }
    return out;
}

// One end of span s of face p's values along axis k (dir: which end), against the face's samples
// `xs` and a fine fill from those nearest the end: a configuration reached beyond the values is
// unsound; an end more than a step beyond the farthest one reached is loose, unless the face
// narrowed there to less than the fill's grid (a wedge between two lines meeting at a shallow
// angle goes on as a sliver no sample finds). A face the dense samples missed is checked for
// soundness only.
void check_end(const PairOracle& oracle, const CSpaceRequest& r, const std::vector<Piece>& pieces, const Place& p, bool located,
               const std::vector<Eigen::Vector2d>& xs, int k, const Span& s, int dir, Report& out) {
    const auto& ax = r.axes[static_cast<std::size_t>(k)];
    const auto& covers = p.covers[static_cast<std::size_t>(k)];
    const double tol = ax.step(), end = dir > 0 ? s.hi : s.lo;
    if (ax.periodic && s.hi - s.lo >= ax.span() * (1 - 1e-9)) return;
    std::ostringstream where;
    where << "face " << p.id.value << " axis " << k << " values";
    for (const auto& c : covers) where << " [" << c.lo << ", " << c.hi << "]";
    std::vector<Eigen::Vector2d> near;  // the samples in the span, shifted to it
    for (const auto& x : xs)
        for (int c = ax.periodic ? -2 : 0; c <= (ax.periodic ? 2 : 0); ++c) {
            Eigen::Vector2d y = x;
            y[k] += c * ax.span();
            if (y[k] >= s.lo - tol && y[k] <= s.hi + tol) near.push_back(y);
        }
    if (near.empty()) {
        if (located && dir > 0) out.loose.push_back(where.str() + ": no sample in [" + std::to_string(s.lo) + ", " + std::to_string(s.hi) + "]");
        return;
    }
    auto farthest = [&](const std::vector<Eigen::Vector2d>& ys, double from) {
        for (const auto& y : ys) from = dir > 0 ? std::max(from, y[k]) : std::min(from, y[k]);
        return from;
    };
    double far = farthest(near, near.front()[k]);
    std::vector<Eigen::Vector2d> seeds;
    for (const auto& y : near)
        if (dir * (far - y[k]) <= tol) seeds.push_back(y);
    ++out.ends;
    auto reached = fine_fill(oracle, r, pieces, seeds, k, far - dir * tol, end + dir * 3 * tol, located ? 16 : 64);
    if (reached.empty()) ++out.skipped;
    // Short of the end: a sliver thinner than the fill's grid, perhaps; finer, from the front.
    if (const double front_at = farthest(reached, far); dir * (end - front_at) > tol) {
        std::vector<Eigen::Vector2d> front;
        for (const auto& y : reached.empty() ? seeds : reached)
            if (dir * (front_at - y[k]) <= tol / 8) front.push_back(y);
        const auto finer = fine_fill(oracle, r, pieces, front, k, front_at - dir * tol, end + dir * 3 * tol, 128);
        reached.insert(reached.end(), finer.begin(), finer.end());
    }
    far = farthest(reached, far);
    double worst = 0;
    for (const auto& y : reached) worst = std::max(worst, outside(ax, covers, y[k]));
    if (worst > 0) out.unsound.push_back(where.str() + ": the fill at an end reaches " + std::to_string(worst) + " steps outside");
    if (!located || dir * (end - far) <= tol) return;
    std::size_t last = 0;  // reached at the farthest column
    for (const auto& y : reached) last += std::abs(y[k] - far) < 1e-12 ? 1 : 0;
    if (!reached.empty() && last <= 2) ++out.slivers;
    else out.loose.push_back(where.str() + ": the end " + std::to_string(end) + " lies " + std::to_string(dir * (end - far) / tol) + " steps past the farthest sample");
}

// The dense check of one pair's faces.
Report check_pair(const PairOracle& oracle, const CSpaceRequest& r, const PlaceVocabulary& v) {
    Report out;
    const Dense g(r);
    const auto pieces = division_pieces(r, v);
    const int n0 = g.n[0], n1 = g.n[1];
    std::vector<std::uint8_t> free(g.index(0, n1), 0);
    for (int j = 0; j < n1; ++j)
        for (int i = 0; i < n0; ++i) free[g.index(i, j)] = !oracle.blocked({g.at(0, i), g.at(1, j)});
    // Components over edges whose midpoint is free and that cross no division (union-find).
    std::vector<std::size_t> parent(free.size());
    for (std::size_t s = 0; s < parent.size(); ++s) parent[s] = s;
    auto root = [&](std::size_t s) {
        while (parent[s] != s) s = parent[s] = parent[parent[s]];
        return s;
    };
    for (int j = 0; j < n1; ++j)
        for (int i = 0; i < n0; ++i) {
            if (!free[g.index(i, j)]) continue;
            for (int k = 0; k < 2; ++k) {
                int ni = i + (k == 0), nj = j + (k == 1);
                int& m = k == 0 ? ni : nj;
                if (m == g.n[static_cast<std::size_t>(k)]) {
                    if (!r.axes[static_cast<std::size_t>(k)].periodic) continue;
                    m = 0;
                }
                if (!free[g.index(ni, nj)]) continue;
                const Eigen::Vector2d p(g.at(0, i), g.at(1, j));
                const Eigen::Vector2d q = p + Eigen::Vector2d(k == 0 ? g.h(0) : 0.0, k == 1 ? g.h(1) : 0.0);
                if (oracle.blocked(wrap(r, 0.5 * (p + q))) || crosses(r, pieces, p, q)) continue;
                parent[root(g.index(i, j))] = root(g.index(ni, nj));
            }
        }
    // Each face's own sample, to the nearest dense sample the straight way reaches freely.
    std::vector<std::set<std::uint32_t>> faces_of(free.size());
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::face) continue;
        ++out.faces;
        const Eigen::Vector2d q = p.points.front();
        std::array<int, 2> c{};
        for (int k = 0; k < 2; ++k) c[static_cast<std::size_t>(k)] = static_cast<int>(std::floor((q[k] - r.axes[static_cast<std::size_t>(k)].lo) / g.h(k)));
        std::optional<std::size_t> best;
        double best_d = 0;
        for (int di = -1; di <= 2; ++di)
            for (int dj = -1; dj <= 2; ++dj) {
                int i = c[0] + di, j = c[1] + dj;
                Eigen::Vector2d y(r.axes[0].lo + i * g.h(0), r.axes[1].lo + j * g.h(1));
                bool ok = true;
                for (int k = 0; k < 2; ++k) {
                    int& m = k == 0 ? i : j;
                    const int n = g.n[static_cast<std::size_t>(k)];
                    if (r.axes[static_cast<std::size_t>(k)].periodic) m = ((m % n) + n) % n;
                    else ok = ok && m >= 0 && m < n;
                }
                if (!ok || !free[g.index(i, j)]) continue;
                if (!r.axes[0].periodic && i == n0 - 1) y[0] = r.axes[0].hi;
                if (!r.axes[1].periodic && j == n1 - 1) y[1] = r.axes[1].hi;
                for (int t = 1; t < 8 && ok; ++t) ok = !oracle.blocked(wrap(r, q + (y - q) * t / 8.0));
                if (!ok || crosses(r, pieces, q, y)) continue;
                const double d = (y - q).cwiseQuotient(Eigen::Vector2d(g.h(0), g.h(1))).norm();
                if (!best || d < best_d) {
                    best = g.index(i, j);
                    best_d = d;
                }
            }
        if (!best) continue;
        ++out.located;
        faces_of[root(*best)].insert(p.id.value);
    }
    // Every sample against the values of its component's faces; each face alone in its component
    // keeps its samples, for the ends of its values.
    std::vector<std::vector<Eigen::Vector2d>> seen(v.places.size());
    std::vector<std::array<double, 2>> worst(v.places.size(), {0.0, 0.0});  // how far outside, in steps
    for (int j = 0; j < n1; ++j)
        for (int i = 0; i < n0; ++i) {
            if (!free[g.index(i, j)]) continue;
            const auto& fs = faces_of[root(g.index(i, j))];
            if (fs.empty()) continue;
            ++out.samples;
            const Eigen::Vector2d x(g.at(0, i), g.at(1, j));
            if (fs.size() == 1) seen[*fs.begin()].push_back(x);
            for (std::size_t k = 0; k < 2; ++k) {
                double far = std::numeric_limits<double>::infinity();
                for (const auto f : fs) far = std::min(far, outside(r.axes[k], v.places[f].covers[k], x[static_cast<Eigen::Index>(k)]));
                if (far > 1e-9)
                    for (const auto f : fs) worst[f][k] = std::max(worst[f][k], far);
            }
        }
    for (const auto& fs : faces_of) out.ambiguous += fs.size() > 1 ? fs.size() : 0;
    std::vector<bool> located(v.places.size(), false);
    for (const auto& fs : faces_of)
        for (const auto f : fs) located[f] = true;
    // Each end of each span of a face's values, with the fine fill from its samples nearest that end
    // (a face too thin for the dense samples: from its own sample).
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::face || (located[p.id.value] && seen[p.id.value].empty())) continue;
        const auto& xs = located[p.id.value] ? seen[p.id.value] : p.points;
        for (int k = 0; k < 2; ++k)
            for (const auto& s : p.covers[static_cast<std::size_t>(k)])
                for (const int dir : {-1, 1}) check_end(oracle, r, pieces, p, located[p.id.value], xs, k, s, dir, out);
    }
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::face)
            for (std::size_t k = 0; k < 2; ++k)
                if (worst[p.id.value][k] > 0) {
                    std::ostringstream spans;
                    for (const auto& s : p.covers[k]) spans << " [" << s.lo << ", " << s.hi << "]";
                    out.unsound.push_back("face " + std::to_string(p.id.value) + " axis " + std::to_string(k) + " values" + spans.str() +
                                          ": a sample " + std::to_string(worst[p.id.value][k]) + " steps outside");
                }
    return out;
}

struct PairCase {
    std::string file, a, b;
};

Report check(const PairCase& c) {
    const auto m = load_mechanism(c.file);
    const auto pairs = kinematic_pairs(m).modelled;
    const auto spec = std::find_if(pairs.begin(), pairs.end(), [&](const PairSpec& p) { return m.parts[p.a].name == c.a && m.parts[p.b].name == c.b; });
    REQUIRE(spec != pairs.end());
    const auto oracle = pair_oracle(m, *spec);
    const auto request = place_request(m, *spec);
    const auto built = build_place_vocabulary(*oracle, request);
    REQUIRE(built.status == PlaceStatus::ok);
    return check_pair(*oracle, request.cspace, built.vocabulary);
}

std::string said(const PairCase& c, const Report& rep) {
    std::ostringstream os;
    os << c.file << " " << c.a << "/" << c.b << ": " << rep.faces << " faces, " << rep.located << " located (" << rep.ambiguous
       << " sharing a component), " << rep.samples << " samples, " << rep.ends << " ends filled (" << rep.skipped << " too large for a fill, "
       << rep.slivers << " narrowing to a sliver)\n";
    for (const auto& s : rep.unsound) os << "  unsound: " << s << "\n";
    for (const auto& s : rep.loose) os << "  loose: " << s << "\n";
    return os.str();
}

}  // namespace

TEST_CASE("geometry/place_covers: [large] the Geneva drive's wheel/detent faces span their samples' values and no more") {
    // Among them face 47, which ends at a division at wheel 0.1288, well short of where its rows
    // widened by two grid steps reached.
    const PairCase c{"geneva_detent.def", "wheel", "detent"};
    const Report rep = check(c);
    INFO(said(c, rep));
    CHECK(rep.located * 2 >= rep.faces);  // the rest: strips thinner than the dense samples
    CHECK(rep.unsound.empty());
    CHECK(rep.loose.empty());
}

// The small pairs in full, so that the sanitizer tree, which leaves out the [large] cases, checks
// the same code.
TEST_CASE("geometry/place_covers: the small pairs' faces span their samples' values and no more") {
    for (const PairCase& c : {PairCase{"cam.def", "cam", "follower"}, PairCase{"scotch_yoke.def", "crank", "yoke"},
                              PairCase{"crank_latch.def", "crank", "slider"}, PairCase{"crank_latch.def", "latch", "stop"}}) {
        const Report rep = check(c);
        INFO(said(c, rep));
        CHECK(rep.located == rep.faces);
        CHECK(rep.unsound.empty());
        CHECK(rep.loose.empty());
    }
}

// A few ends lie more than a step past what the test's flood fill reaches where it and the builder
// see a face differently: a division that crosses another with no join there (the T-junction of
// tests/envision/multi_pair_test.cpp) divides the test's face but not the builder's.
TEST_CASE("geometry/place_covers: [large] a seeded sample of the other bundled pairs' faces span their samples' values and no more") {
    std::vector<PairCase> others{{"geneva_detent.def", "driver", "wheel"},  {"pawl_ratchet.def", "crank", "lever"},
                                 {"pawl_ratchet.def", "lever", "ratchet-wheel"}, {"crank_latch.def", "crank", "slider"},
                                 {"crank_latch.def", "slider", "latch"},     {"crank_latch.def", "latch", "stop"},
                                 {"ratchet.def", "ratchet-wheel", "pawl"},    {"cam.def", "cam", "follower"},
                                 {"scotch_yoke.def", "crank", "yoke"},        {"escapement.def", "scape-wheel", "pallets"},
                                 {"gear_pair.def", "gear-1", "gear-2"}};
    // Fisher-Yates on the generator's own numbers (std::shuffle's use of them is the library's).
    std::mt19937 seeded(842);
    for (std::size_t i = others.size() - 1; i > 0; --i) std::swap(others[i], others[seeded() % (i + 1)]);
    for (std::size_t k = 0; k < 4; ++k) {
        const Report rep = check(others[k]);
        INFO(said(others[k], rep));
        CHECK(rep.located * 2 >= rep.faces);
        CHECK(rep.unsound.empty());
        CHECK(rep.loose.size() * 20 <= rep.ends);
    }
}
