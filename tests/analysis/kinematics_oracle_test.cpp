// tests/analysis/kinematics_oracle_test.cpp: analysis/analysis.hpp - an independent test oracle for the
// kinematic laws, compared with the product's analysis on seeded random scenes without forces.
//
// Why an oracle: the product derives freedoms and motions from rule files on an ATMS. Here the same
// laws are re-implemented directly in plain C++ from the thesis text (Nielsen 1988, sections
// 2.1-2.4, Definitions 1-7, 12-14, 19, 23, 24, Law 1, Table 3.1, Table 3.2) and the conventions of
// the reading guide (/work/shared/spec/README.md), never from rules/, scene/*.cpp or analysis/*.cpp, so that a
// mistake in either shows up as a disagreement. The oracle is itself checked against real vector
// arithmetic and against the thesis' own results (Figures 7.5, 7.9, 7.13, 7.14, 7.16-7.18).
//
// Found so far: freedoms and the consistent combinations of chains without a given motion agree
// exactly. Where a motion is given, the product keeps only some of the consistent combinations
// (and now and then none): it reads a given motion as a force on what it pushes and then selects
// by nearness, which the thesis does only for forces (sections 3.2, 6.2). The two skipped cases at
// the end reproduce this; the random test reports it without failing on it.
#include "analysis/analysis.hpp"
#include "scene/scene_parser.hpp"
#include "qm/assert.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <iterator>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstdint>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// Sanitized builds (QM_SANITIZED_BUILD) run the product some 25 times slower: fewer random scenes there.
using namespace qm::scene;
using namespace qm::analysis;
using QVec = std::vector<int>;  // qualitative vector: -1, 0, +1 or oracle::amb per place

namespace oracle {

// ---------------------------------------------------------------------------------------------
// Qualitative values and arithmetic (section 2.3, Tables 2.2 and 2.3). A value is -1, 0, +1 or
// `amb` (the sum of a + and a - term: its sign is unknown).
constexpr int amb = 2;

int qadd(int a, int b) {
    if (a == 0) return b;
    if (b == 0) return a;
    if (a == amb || b == amb || a != b) return amb;
    return a;
}

int qmul(int a, int b) {
    if (a == 0 || b == 0) return 0;
    if (a == amb || b == amb) return amb;
    return a * b;
}

int qdot(const QVec& x, const QVec& y) {
    int s = 0;
    for (std::size_t i = 0; i < x.size(); ++i) s = qadd(s, qmul(x[i], y[i]));
    return s;
}

// Definition 13; an ambiguous dot product is not in the open half plane (guide: the liberal bias
// of section 7.3).
bool open_half_plane(const QVec& x, const QVec& y) { return qdot(x, y) == 1; }

int qneg(int a) { return a == amb ? amb : -a; }

QVec negated(const QVec& v) {
    QVec out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = qneg(v[i]);
    return out;
}

// Definition 14, Rotate-90(v, r): v turned a quarter turn in rotational direction r. 2-D (guide):
// (x y) -> (-y x) for (+), (y -x) for (-). 3-D: for each axis a with r_a != 0 the quarter turn
// about that axis is r_a (e_a x v), the directions of Table 2.1 (positive about x takes y to z,
// about y z to x, about z x to y); the turns about several axes are summed qualitatively. A zero
// rotation moves nothing (zero vector, which is in no open half plane).
QVec rotate90(const QVec& v, const QVec& r) {
    if (v.size() == 2) {
        if (r[0] == 1) return {qneg(v[1]), v[0]};
        if (r[0] == -1) return {v[1], qneg(v[0])};
        return {0, 0};
    }
    QVec out{0, 0, 0};
    for (int axis = 0; axis < 3; ++axis) {
        if (r[static_cast<std::size_t>(axis)] == 0) continue;
        // e_x x (x y z) = (0 -z y); e_y x v = (z 0 -x); e_z x v = (-y x 0).
        QVec turn(3, 0);
        const int x = v[0], y = v[1], z = v[2];
        if (axis == 0) turn = {0, qneg(z), y};
        if (axis == 1) turn = {z, 0, qneg(x)};
        if (axis == 2) turn = {qneg(y), x, 0};
        for (std::size_t i = 0; i < 3; ++i) out[i] = qadd(out[i], qmul(r[static_cast<std::size_t>(axis)], turn[i]));
    }
    return out;
}

QVec qvec(const Direction& d) {
    QVec out;
    for (Sign s : d) out.push_back(static_cast<int>(s));
    return out;
}

// Definitions 1 and 4: every direction of n places, in the canonical order the product documents
// (lexicographic over + 0 -, first place most significant). Index i of the list is the direction's
// id in the oracle.
std::vector<Direction> all_directions(std::size_t n) {
    std::vector<Direction> out{Direction{}};
    for (std::size_t place = 0; place < n; ++place) {
        std::vector<Direction> next;
        for (const Direction& d : out)
            for (Sign s : {Sign::plus, Sign::zero, Sign::minus}) {
                Direction e = d;
                e.push_back(s);
                next.push_back(std::move(e));
            }
        out = std::move(next);
    }
    return out;
}

bool is_zero(const Direction& d) {
    return std::all_of(d.begin(), d.end(), [](Sign s) { return s == Sign::zero; });
}

// Pattern matching of a constraint entry (guide: `?x` matches any sign in its place, nothing else
// links places), written here independently of the product's `matches`.
bool pattern_matches(const DirectionPattern& p, const Direction& d) {
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p[i].sign && *p[i].sign != d[i]) return false;
    return true;
}

// ---------------------------------------------------------------------------------------------
// The laws on one situation of a scene.

struct Freedoms {
    // [object][direction id]: constrained (Definition 23). Free = not constrained (Definition 24).
    std::vector<std::vector<bool>> trans_constrained, rot_constrained;
};

using Motion2 = std::pair<std::size_t, std::size_t>;  // (translation id, rotation id)

struct ChainResult {
    std::vector<std::size_t> objects;                   // ascending object indices
    std::vector<std::vector<Motion2>> combinations;     // sorted
    bool over_limit = false;
};

class Laws {
public:
    explicit Laws(const Scene& scene)
        : scene_(scene),
          trans_(all_directions(scene.translation_arity())),
          rot_(all_directions(scene.rotation_arity())) {}

    const std::vector<Direction>& translations() const { return trans_; }
    const std::vector<Direction>& rotations() const { return rot_; }

    std::size_t trans_id(const Direction& d) const { return id_of(trans_, d); }
    std::size_t rot_id(const Direction& d) const { return id_of(rot_, d); }

    // Translations d with Open-Half-Plane(m, d).
    std::vector<bool> into(const QVec& m) const {
        std::vector<bool> out(trans_.size());
        for (std::size_t i = 0; i < trans_.size(); ++i) out[i] = open_half_plane(m, qvec(trans_[i]));
        return out;
    }
    // Rotations r with Rotate-90(m, x, r) and Open-Half-Plane(x, origin).
    std::vector<bool> turning(const QVec& m, const QVec& origin) const {
        std::vector<bool> out(rot_.size());
        for (std::size_t i = 0; i < rot_.size(); ++i) out[i] = open_half_plane(rotate90(m, qvec(rot_[i])), origin);
        return out;
    }

    // Frame constraints (Translational-/Rotational-Constraints patterns; never the zero direction),
    // then Table 3.1 on every contact in both directions, iterated to the least fixed point.
    Freedoms freedom(const Situation& sit) const {
        const std::size_t n = scene_.objects.size();
        Freedoms f;
        f.trans_constrained.assign(n, std::vector<bool>(trans_.size(), false));
        f.rot_constrained.assign(n, std::vector<bool>(rot_.size(), false));
        for (std::size_t o = 0; o < n; ++o) {
            const Object& obj = scene_.objects[ObjectId{static_cast<std::uint32_t>(o)}];
            for (const auto& p : obj.trans_constraints)
                for (std::size_t i = 0; i < trans_.size(); ++i)
                    if (!is_zero(trans_[i]) && pattern_matches(p, trans_[i])) f.trans_constrained[o][i] = true;
            for (const auto& p : obj.rot_constraints)
                for (std::size_t i = 0; i < rot_.size(); ++i)
                    if (!is_zero(rot_[i]) && pattern_matches(p, rot_[i])) f.rot_constrained[o][i] = true;
        }
        struct Rule {
            std::size_t obst, obj;
            std::vector<bool> obst_t, obst_r, obj_t, obj_r;
        };
        std::vector<Rule> rules;
        for (const Contact& c : sit.contacts)
            for (auto [p, q] : {std::pair{c.first, c.second}, std::pair{c.second, c.first}}) {
                // Table 3.1: sn is the normal of the obstacle's surface p.
                const Surface& sp = scene_.surfaces[p];
                const Surface& sq = scene_.surfaces[q];
                const QVec m = negated(qvec(sp.normal));
                rules.push_back({sp.object.value, sq.object.value, into(m), turning(m, qvec(sp.origin)), into(m),
                                 turning(m, qvec(sq.origin))});
            }
        for (bool changed = true; changed;) {
            changed = false;
            for (const Rule& r : rules) {
                bool sufficient = true;
                for (std::size_t i = 0; i < trans_.size(); ++i)
                    if (r.obst_t[i] && !f.trans_constrained[r.obst][i]) sufficient = false;
                for (std::size_t i = 0; i < rot_.size(); ++i)
                    if (r.obst_r[i] && !f.rot_constrained[r.obst][i]) sufficient = false;
                if (!sufficient) continue;
                for (std::size_t i = 0; i < trans_.size(); ++i)
                    if (r.obj_t[i] && !f.trans_constrained[r.obj][i]) f.trans_constrained[r.obj][i] = changed = true;
                for (std::size_t i = 0; i < rot_.size(); ++i)
                    if (r.obj_r[i] && !f.rot_constrained[r.obj][i]) f.rot_constrained[r.obj][i] = changed = true;
            }
        }
        return f;
    }

    // Kinematic chains (Definition 22): connected components of the contact graph; an object with
    // no contact is a chain of its own.
    std::vector<std::vector<std::size_t>> chains(const Situation& sit) const {
        const std::size_t n = scene_.objects.size();
        std::vector<std::size_t> parent(n);
        std::iota(parent.begin(), parent.end(), std::size_t{0});
        auto find = [&](std::size_t x) {
            while (parent[x] != x) x = parent[x] = parent[parent[x]];
            return x;
        };
        for (const Contact& c : sit.contacts)
            parent[find(scene_.surfaces[c.first].object.value)] = find(scene_.surfaces[c.second].object.value);
        std::map<std::size_t, std::vector<std::size_t>> groups;
        for (std::size_t o = 0; o < n; ++o) groups[find(o)].push_back(o);
        std::vector<std::vector<std::size_t>> out;
        for (auto& [root, members] : groups) out.push_back(members);
        std::sort(out.begin(), out.end());
        return out;
    }

    // Law 1 (exactly one translation and one rotation per object), brute force over the chain:
    // consistent iff no motion is constrained (Definition 23), every given motion holds, and on
    // every contact, both ways, Table 3.2 holds: a body moving into the object forces the object to
    // move away. Stops (over_limit) after `limit` consistent combinations.
    ChainResult motions(const Situation& sit, const Freedoms& f, const std::vector<std::size_t>& chain,
                        std::size_t limit) const {
        ChainResult res;
        res.objects = chain;
        std::vector<std::size_t> slot(scene_.objects.size(), SIZE_MAX);
        for (std::size_t i = 0; i < chain.size(); ++i) slot[chain[i]] = i;
        std::vector<std::vector<Motion2>> domain(chain.size());
        for (std::size_t i = 0; i < chain.size(); ++i) {
            const std::size_t o = chain[i];
            for (std::size_t t = 0; t < trans_.size(); ++t) {
                if (f.trans_constrained[o][t]) continue;
                for (std::size_t r = 0; r < rot_.size(); ++r) {
                    if (f.rot_constrained[o][r]) continue;
                    bool given_ok = true;
                    for (const Motion& m : sit.motions)
                        if (m.object.value == o && (trans_id(m.translation) != t || rot_id(m.rotation) != r)) given_ok = false;
                    if (given_ok) domain[i].push_back({t, r});
                }
            }
        }
        // Table 3.2 per contact orientation (body owns p, object owns q; sn is the normal of q).
        struct Push {
            std::size_t body, obj;  // chain slots
            std::vector<bool> body_t, body_r, obj_t, obj_r;
        };
        std::vector<std::vector<Push>> checks_at(chain.size());  // checked once both slots are set
        for (const Contact& c : sit.contacts)
            for (auto [p, q] : {std::pair{c.first, c.second}, std::pair{c.second, c.first}}) {
                const Surface& sp = scene_.surfaces[p];
                const Surface& sq = scene_.surfaces[q];
                if (slot[sp.object.value] == SIZE_MAX) continue;  // another chain
                const QVec m = negated(qvec(sq.normal));
                Push push{slot[sp.object.value], slot[sq.object.value], into(m), turning(m, qvec(sp.origin)), into(m),
                          turning(m, qvec(sq.origin))};
                checks_at[std::max(push.body, push.obj)].push_back(std::move(push));
            }
        std::vector<Motion2> current(chain.size());
        auto consistent_at = [&](std::size_t i) {
            for (const Push& p : checks_at[i]) {
                const Motion2 b = current[p.body], o = current[p.obj];
                const bool pushes = p.body_t[b.first] || p.body_r[b.second];
                const bool away = p.obj_t[o.first] || p.obj_r[o.second];
                if (pushes && !away) return false;
            }
            return true;
        };
        auto search = [&](auto&& self, std::size_t i) -> void {
            if (res.over_limit) return;
            if (i == chain.size()) {
                if (res.combinations.size() >= limit) {
                    res.over_limit = true;
                    return;
                }
                res.combinations.push_back(current);
                return;
            }
            for (const Motion2& m : domain[i]) {
                current[i] = m;
                if (consistent_at(i)) self(self, i + 1);
            }
        };
        search(search, 0);
        std::sort(res.combinations.begin(), res.combinations.end());
        return res;
    }

private:
    static std::size_t id_of(const std::vector<Direction>& all, const Direction& d) {
        const auto it = std::find(all.begin(), all.end(), d);
        QM_REQUIRE(it != all.end(), "direction of the wrong arity");
        return static_cast<std::size_t>(it - all.begin());
    }

    const Scene& scene_;
    std::vector<Direction> trans_, rot_;
};

}  // namespace oracle

namespace {

std::string text(const Direction& d) {
    std::string s = "(";
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (i) s += ' ';
        s += sign_char(d[i]);
    }
    return s + ")";
}

Direction opposite(const Direction& d) {
    Direction out;
    for (Sign s : d) out.push_back(static_cast<Sign>(-static_cast<int>(s)));
    return out;
}

Scene read_ok(const std::string& src) {
    qm::Diagnostics diags;
    auto s = read_scene("oracle.def", src, diags);
    std::ostringstream os;
    diags.print(os);
    INFO(src);
    INFO(os.str());
    REQUIRE(s.has_value());
    return *s;
}

Analysis analyse_ok(const Scene& scene) {
    AnalysisOptions options;
    options.rules_directory = std::string(QM_SOURCE_DIR) + "/rules";
    qm::Diagnostics diags;
    auto a = analyse(scene, options, diags);
    std::ostringstream os;
    diags.print(os);
    INFO(os.str());
    REQUIRE(a.has_value());
    return std::move(*a);
}

std::vector<Direction> free_list(const std::vector<Direction>& all, const std::vector<bool>& constrained) {
    std::vector<Direction> out;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (!constrained[i]) out.push_back(all[i]);
    return out;
}

std::vector<Direction> dirs(std::initializer_list<const char*> spelled) {
    std::vector<Direction> out;
    for (const char* s : spelled) {
        Direction d;
        for (const char* c = s; *c; ++c) {
            if (*c == '+') d.push_back(Sign::plus);
            if (*c == '0') d.push_back(Sign::zero);
            if (*c == '-') d.push_back(Sign::minus);
        }
        out.push_back(d);
    }
    return out;
}

// The whole result of the oracle for one situation, in the product's vocabulary.
struct Expected {
    std::vector<Freedom> freedom;  // per object
    std::vector<oracle::ChainResult> chains;
    bool over_limit = false;
};

Expected expect(const oracle::Laws& laws, const Scene& scene, const Situation& sit, std::size_t limit) {
    Expected e;
    const oracle::Freedoms f = laws.freedom(sit);
    for (std::size_t o = 0; o < scene.objects.size(); ++o)
        e.freedom.push_back(
            {free_list(laws.translations(), f.trans_constrained[o]), free_list(laws.rotations(), f.rot_constrained[o])});
    for (const auto& chain : laws.chains(sit)) {
        e.chains.push_back(laws.motions(sit, f, chain, limit));
        if (e.chains.back().over_limit) e.over_limit = true;
    }
    return e;
}

std::string motion_text(const oracle::Laws& laws, const Scene& scene, const std::vector<std::size_t>& objects,
                        const std::vector<oracle::Motion2>& combo) {
    std::string s;
    for (std::size_t i = 0; i < objects.size(); ++i)
        s += scene.objects[ObjectId{static_cast<std::uint32_t>(objects[i])}].name + " " +
             text(laws.translations()[combo[i].first]) + " " + text(laws.rotations()[combo[i].second]) + "; ";
    return s;
}

// What one comparison found. `narrowed` and `emptied` single out chains with a given motion in
// which the product lists only some of the consistent combinations: the product does that on
// purpose (a moving body pushes with a force, then nearness selects), the thesis does not (see
// the skipped case at the end of this file).
struct Verdict {
    std::string diff;          // human-readable, empty when the product agrees exactly
    bool freedom = false;      // a free-direction list differs
    bool partition = false;    // the chains differ
    bool extra = false;        // the product lists a combination the oracle finds inconsistent (or twice)
    bool missing = false;      // the product leaves out a consistent combination of a chain with no given motion
    bool narrowed = false;     // ... of a chain with a given motion (but keeps at least one)
    bool emptied = false;      // ... all of them, for a chain with a given motion that has some
    bool facing = true;        // every narrowed or emptied chain touches only at facing surfaces
    bool summary = false;      // stable / combination_count disagree with the chains
    [[nodiscard]] bool exact() const { return diff.empty(); }
};

// Compares the product's result for one situation with the oracle's.
Verdict compare(const oracle::Laws& laws, const Scene& scene, const Situation& sit, const Expected& e,
                const SituationResult& got) {
    Verdict v;
    std::ostringstream diff;
    if (got.freedom.size() != scene.objects.size()) {
        v.freedom = true;
        diff << "freedom has " << got.freedom.size() << " objects\n";
    }
    for (std::size_t o = 0; o < scene.objects.size() && o < got.freedom.size(); ++o) {
        const Freedom& g = got.freedom[ObjectId{static_cast<std::uint32_t>(o)}];
        const std::string& name = scene.objects[ObjectId{static_cast<std::uint32_t>(o)}].name;
        auto list = [](const std::vector<Direction>& ds) {
            std::string s;
            for (const auto& d : ds) s += text(d) + " ";
            return s;
        };
        if (g.translation != e.freedom[o].translation) {
            v.freedom = true;
            diff << "translational freedom of " << name << ": product " << list(g.translation) << "| oracle "
                 << list(e.freedom[o].translation) << "\n";
        }
        if (g.rotation != e.freedom[o].rotation) {
            v.freedom = true;
            diff << "rotational freedom of " << name << ": product " << list(g.rotation) << "| oracle "
                 << list(e.freedom[o].rotation) << "\n";
        }
    }
    // Chains: the same partition, and per chain the same set of consistent combinations.
    std::map<std::vector<std::size_t>, const ChainMotions*> by_objects;
    for (const ChainMotions& c : got.chains) {
        std::vector<std::size_t> objs;
        for (ObjectId o : c.objects) objs.push_back(o.value);
        by_objects[objs] = &c;
    }
    if (by_objects.size() != e.chains.size() || got.chains.size() != e.chains.size()) {
        v.partition = true;
        diff << "product has " << got.chains.size() << " chains, oracle " << e.chains.size() << "\n";
    }
    bool stable = true;
    std::uint64_t count = 1;
    for (const auto& ec : e.chains) {
        // Saturating, as combination_count() documents.
        const std::uint64_t n = ec.combinations.size();
        count = n != 0 && count > UINT64_MAX / n ? UINT64_MAX : count * n;
        const bool all_zero = ec.combinations.size() == 1 &&
                              std::all_of(ec.combinations[0].begin(), ec.combinations[0].end(), [&](const oracle::Motion2& m) {
                                  return oracle::is_zero(laws.translations()[m.first]) &&
                                         oracle::is_zero(laws.rotations()[m.second]);
                              });
        stable = stable && all_zero;
        const auto it = by_objects.find(ec.objects);
        if (it == by_objects.end()) {
            v.partition = true;
            diff << "no product chain for the oracle's chain of " << scene.objects[ObjectId{static_cast<std::uint32_t>(ec.objects.front())}].name
                 << "\n";
            continue;
        }
        std::vector<std::vector<oracle::Motion2>> g;
        for (const auto& combo : it->second->combinations) {
            std::vector<oracle::Motion2> m;
            for (const ObjectMotion& om : combo) m.push_back({laws.trans_id(om.translation), laws.rot_id(om.rotation)});
            g.push_back(std::move(m));
        }
        std::sort(g.begin(), g.end());
        if (std::adjacent_find(g.begin(), g.end()) != g.end()) {
            v.extra = true;
            diff << "product lists a combination twice\n";
            g.erase(std::unique(g.begin(), g.end()), g.end());
        }
        if (g != ec.combinations) {
            const bool given = std::any_of(sit.motions.begin(), sit.motions.end(), [&](const Motion& m) {
                return std::find(ec.objects.begin(), ec.objects.end(), m.object.value) != ec.objects.end();
            });
            std::vector<std::vector<oracle::Motion2>> only_product, only_oracle;
            std::set_difference(g.begin(), g.end(), ec.combinations.begin(), ec.combinations.end(),
                                std::back_inserter(only_product));
            std::set_difference(ec.combinations.begin(), ec.combinations.end(), g.begin(), g.end(),
                                std::back_inserter(only_oracle));
            v.extra = v.extra || !only_product.empty();
            if (!only_oracle.empty()) {
                if (!given) v.missing = true;
                else if (g.empty()) v.emptied = true;
                else v.narrowed = true;
                // Section 3.1.1: surfaces in contact have opposite normals; other contacts are
                // outside the thesis' domain, though both tables still read them literally.
                for (const Contact& c : sit.contacts)
                    if (std::find(ec.objects.begin(), ec.objects.end(), scene.surfaces[c.first].object.value) !=
                            ec.objects.end() &&
                        scene.surfaces[c.first].normal != opposite(scene.surfaces[c.second].normal))
                        v.facing = false;
            }
            diff << "chain of " << ec.objects.size() << " objects" << (given ? " with a given motion" : "")
                 << ": product " << g.size() << " combinations, oracle " << ec.combinations.size() << "\n";
            for (std::size_t i = 0; i < only_product.size() && i < 4; ++i)
                diff << "  only product: " << motion_text(laws, scene, ec.objects, only_product[i]) << "\n";
            for (std::size_t i = 0; i < only_oracle.size() && i < 4; ++i)
                diff << "  only oracle:  " << motion_text(laws, scene, ec.objects, only_oracle[i]) << "\n";
        }
    }
    if (!v.missing && !v.extra && !v.narrowed && !v.emptied) {
        if (got.stable != stable) {
            v.summary = true;
            diff << "stable: product " << got.stable << ", oracle " << stable << "\n";
        }
        if (got.combination_count() != count) {
            v.summary = true;
            diff << "combination_count: product " << got.combination_count() << ", oracle " << count << "\n";
        }
    }
    v.diff = diff.str();
    return v;
}

// ---------------------------------------------------------------------------------------------
// Random scenes. Deterministic: std::mt19937 with fixed seeds, reduced with `%` (not the
// implementation-defined distributions).

class Random {
public:
    explicit Random(std::uint32_t seed) : rng_(seed) {}
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(rng_() % n); }
    bool chance(unsigned percent) { return below(100) < percent; }
    Sign sign() { return static_cast<Sign>(static_cast<int>(below(3)) - 1); }
    Direction direction(std::size_t n) {
        Direction d;
        for (std::size_t i = 0; i < n; ++i) d.push_back(sign());
        return d;
    }
    Direction non_zero(std::size_t n) {
        for (;;) {
            Direction d = direction(n);
            if (!oracle::is_zero(d)) return d;
        }
    }

private:
    std::mt19937 rng_;
};

// A constraint pattern as scene text: each place a fixed sign or a variable.
std::string pattern(Random& rnd, std::size_t n, unsigned variable_percent, int& var_counter) {
    std::string s = "(";
    for (std::size_t i = 0; i < n; ++i) {
        if (i) s += ' ';
        if (rnd.chance(variable_percent)) {
            // Now and then a variable name repeats inside one pattern; the guide says each `?x`
            // matches any sign in its own place, so the repeat must not link the places.
            s += "?v" + std::to_string(rnd.chance(15) && var_counter > 0 ? var_counter : ++var_counter);
        } else {
            s += sign_char(rnd.sign());
        }
    }
    return s + ")";
}

std::string all_variables(std::size_t n, int& var_counter) {
    std::string s = "(";
    for (std::size_t i = 0; i < n; ++i) s += (i ? " ?v" : "?v") + std::to_string(++var_counter);
    return s + ")";
}

// One random scene ("group"): 1-4 objects of 1-4 surfaces, frame constraints, and per situation
// 0-4 contacts between surfaces of different objects and sometimes given motions. No forces.
struct Group {
    struct Obj {
        std::vector<std::pair<Direction, Direction>> surfaces;  // (normal, origin)
        std::vector<std::string> trans, rot;                    // constraint patterns, as text
    };
    struct Touch {
        std::size_t a, sa, b, sb;  // object, surface index of each side
    };
    struct Given {
        std::size_t object;
        Direction translation, rotation;
    };
    std::vector<Obj> objects;
    std::vector<std::vector<Touch>> contacts;  // per situation
    std::vector<std::vector<Given>> motions;   // per situation
};

std::string object_name(std::size_t g, std::size_t o) { return "g" + std::to_string(g) + "o" + std::to_string(o); }
std::string surface_name(std::size_t g, std::size_t o, std::size_t s) {
    return object_name(g, o) + "-s" + std::to_string(s);
}

// Several groups side by side in one scene text: group g's names start with `g<g>`. No contact
// joins two groups, so each group's chains are its own.
std::string render(int dims, const std::vector<Group>& groups, std::size_t situations,
                   const std::vector<std::size_t>& numbers) {
    std::ostringstream os;
    os << "(Defscenario " << dims << " random\n  Individuals (";
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (std::size_t o = 0; o < groups[g].objects.size(); ++o) os << ' ' << object_name(numbers[g], o);
    os << ")\n  Surfaces (";
    std::string trans, rot;
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (std::size_t o = 0; o < groups[g].objects.size(); ++o) {
            const Group::Obj& obj = groups[g].objects[o];
            os << "\n    (" << object_name(numbers[g], o);
            for (std::size_t s = 0; s < obj.surfaces.size(); ++s)
                os << " (" << surface_name(numbers[g], o, s) << ' ' << text(obj.surfaces[s].first) << ' '
                   << text(obj.surfaces[s].second) << ')';
            os << ')';
            auto entry = [&](std::string& section, const std::vector<std::string>& ps) {
                if (ps.empty()) return;
                section += "\n    (" + object_name(numbers[g], o);
                for (const auto& p : ps) section += " " + p;
                section += ")";
            };
            entry(trans, obj.trans);
            entry(rot, obj.rot);
        }
    os << ")\n";
    if (!trans.empty()) os << "  Translational-Constraints (" << trans << ")\n";
    if (!rot.empty()) os << "  Rotational-Constraints (" << rot << ")\n";
    os << ")\n(Defstates\n";
    for (std::size_t k = 0; k < situations; ++k) {
        os << "  (";
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (const Group::Touch& t : groups[g].contacts[k])
                os << "(Contact " << surface_name(numbers[g], t.a, t.sa) << ' ' << surface_name(numbers[g], t.b, t.sb)
                   << ')';
            for (const Group::Given& m : groups[g].motions[k])
                os << "(Motion " << object_name(numbers[g], m.object) << ' ' << text(m.translation) << ' '
                   << text(m.rotation) << ')';
        }
        os << ")\n";
    }
    os << ")\n";
    return os.str();
}

Group random_group(Random& rnd, int dims, std::size_t situations) {
    const std::size_t tn = static_cast<std::size_t>(dims), rn = dims == 3 ? 3 : 1;
    Group grp;
    grp.objects.resize(1 + rnd.below(dims == 3 ? 3 : 4));
    struct Placed {
        std::size_t object, index;
        Direction normal;
    };
    std::vector<Placed> placed;
    for (std::size_t o = 0; o < grp.objects.size(); ++o) {
        Group::Obj& obj = grp.objects[o];
        const std::size_t n = 1 + rnd.below(4);
        for (std::size_t i = 0; i < n; ++i) {
            Direction normal = rnd.non_zero(tn);
            // Often the reverse of another object's normal, so that many contacts are between
            // facing surfaces (where Table 3.1's and Table 3.2's choices of SN coincide).
            std::vector<const Placed*> others;
            for (const auto& p : placed)
                if (p.object != o) others.push_back(&p);
            if (!others.empty() && rnd.chance(45)) normal = opposite(others[rnd.below(others.size())]->normal);
            const Direction origin = rnd.chance(20) ? Direction(tn, Sign::zero) : rnd.direction(tn);
            obj.surfaces.push_back({normal, origin});
            placed.push_back({o, i, normal});
        }
        int vars = 0;
        const std::size_t kind = rnd.below(100);
        if (kind < 20) {  // fixed: part of the frame
            obj.trans.push_back(all_variables(tn, vars));
            obj.rot.push_back(all_variables(rn, vars));
        } else if (kind < (dims == 3 ? 60u : 45u)) {  // pinned: turns only
            obj.trans.push_back(all_variables(tn, vars));
            if (dims == 3 || rnd.chance(30)) obj.rot.push_back(pattern(rnd, rn, 50, vars));
        } else if (kind < (dims == 3 ? 85u : 60u)) {  // does not turn, some translations constrained
            obj.rot.push_back(all_variables(rn, vars));
            for (std::size_t k = rnd.below(3); k > 0; --k) obj.trans.push_back(pattern(rnd, tn, 40, vars));
        } else {  // random patterns, possibly none
            for (std::size_t k = rnd.below(3); k > 0; --k) obj.trans.push_back(pattern(rnd, tn, 40, vars));
            for (std::size_t k = rnd.below(dims == 3 ? 3 : 2); k > 0; --k) obj.rot.push_back(pattern(rnd, rn, 40, vars));
        }
    }
    grp.contacts.resize(situations);
    grp.motions.resize(situations);
    for (std::size_t k = 0; k < situations; ++k) {
        const std::size_t contacts = grp.objects.size() < 2 ? 0 : rnd.below(5);
        std::set<std::pair<std::size_t, std::size_t>> used;
        for (std::size_t c = 0; c < contacts; ++c) {
            std::vector<std::pair<std::size_t, std::size_t>> candidates, facing;
            for (std::size_t a = 0; a < placed.size(); ++a)
                for (std::size_t b = a + 1; b < placed.size(); ++b) {
                    if (placed[a].object == placed[b].object || used.count({a, b})) continue;
                    candidates.push_back({a, b});
                    if (placed[a].normal == opposite(placed[b].normal)) facing.push_back({a, b});
                }
            if (candidates.empty()) break;
            const auto& pool = !facing.empty() && rnd.chance(60) ? facing : candidates;
            auto [a, b] = pool[rnd.below(pool.size())];
            used.insert({a, b});
            if (rnd.chance(50)) std::swap(a, b);
            grp.contacts[k].push_back({placed[a].object, placed[a].index, placed[b].object, placed[b].index});
        }
    }
    return grp;
}

// Given motions (Motion descriptors): mostly a motion the object is free to make, sometimes any
// motion at all (then usually nothing is consistent). `scene` is the group read on its own.
void add_given_motions(Random& rnd, Group& grp, const Scene& scene, const oracle::Laws& laws) {
    for (std::size_t k = 0; k < grp.motions.size(); ++k) {
        if (!rnd.chance(30)) continue;
        const oracle::Freedoms f = laws.freedom(scene.situations[k]);
        for (std::size_t n = rnd.chance(20) ? 2 : 1; n > 0; --n) {
            const std::size_t o = rnd.below(grp.objects.size());
            // One Motion per object and situation: a second is an input error (scene checker).
            const bool given = std::any_of(grp.motions[k].begin(), grp.motions[k].end(), [&](const Group::Given& g) { return g.object == o; });
            Group::Given m{o, {}, {}};
            if (rnd.chance(75)) {
                const auto ts = free_list(laws.translations(), f.trans_constrained[o]);
                const auto rs = free_list(laws.rotations(), f.rot_constrained[o]);
                m.translation = ts[rnd.below(ts.size())];
                m.rotation = rs[rnd.below(rs.size())];
            } else {
                m.translation = rnd.direction(scene.translation_arity());
                m.rotation = rnd.direction(scene.rotation_arity());
            }
            if (!given) grp.motions[k].push_back(std::move(m));
        }
    }
}

const char* const gears_text = R"(Gears 2
Individuals : (driver, follower)
Descriptions : rigid-ob(driver), rigid-ob(follower)
Translational-Constraints : driver (?x1 ?y1), follower (?x3 ?y3)
Surfaces : follower (l-1 (- -) (0 +)), (l-2 (0 -) (0 +)), (l-3 (+ -) (0 +))
           driver (d-1 (+ +) (0 -)), (d-2 (0 +) (0 -)), (d-3 (- +) (0 -))
Situation : Contact (l-1 d-1)
)";

const char* const block_text = R"((Defscenario 2 block
  Individuals (block table)
  Descriptions ((rigid-ob block) (rigid-ob table))
  Translational-Constraints ((table (?x1 ?y1)))
  Rotational-Constraints ((table (?r1)))
  Surfaces ((block (block-t-l (0 +) (+ -)) (block-t-m (0 +) (0 -)) (block-t-r (0 +) (- -))
                   (block-l-t (- 0) (+ -)) (block-l-m (- 0) (+ 0)) (block-l-b (- 0) (+ +))
                   (block-r-t (+ 0) (- -)) (block-r-m (+ 0) (- 0)) (block-r-b (+ 0) (- +))
                   (block-b-l (0 -) (+ +)) (block-b-m (0 -) (0 +)) (block-b-r (0 -) (- +)))
            (table (tb (0 +) (0 0)))))
(Defstates
  ()
  ((Contact tb block-b-l) (Contact tb block-b-m) (Contact tb block-b-r)))
)";

const char* const arch_text = R"((Defscenario 2 arch
  Individuals (cross-bar left right table)
  Surfaces ((cross-bar (cb-l (0 -) (+ +)) (cb-r (0 -) (- +)))
            (left (lt-t-l (0 +) (+ -)) (lt-t-m (0 +) (0 -)) (lt-t-r (0 +) (- -))
                  (lt-b-l (0 -) (+ +)) (lt-b-m (0 -) (0 +)) (lt-b-r (0 -) (- +)))
            (right (rt-t-l (0 +) (+ -)) (rt-t-m (0 +) (0 -)) (rt-t-r (0 +) (- -))
                   (rt-b-l (0 -) (+ +)) (rt-b-m (0 -) (0 +)) (rt-b-r (0 -) (- +)))
            (table (tb (0 +) (0 0))))
  Translational-Constraints ((table (?x1 ?y1)))
  Rotational-Constraints ((table (?r1))))
(Defstates
  ((Contact tb lt-b-l) (Contact tb lt-b-m) (Contact tb lt-b-r)
   (Contact tb rt-b-l) (Contact tb rt-b-m) (Contact tb rt-b-r)
   (Contact cb-l lt-t-l) (Contact cb-l lt-t-m) (Contact cb-l lt-t-r)
   (Contact cb-r rt-t-l) (Contact cb-r rt-t-m) (Contact cb-r rt-t-r)))
)";

const char* const recoil_text = R"(Recoil 2
Individuals : scape-wheel, pallet, gear
Descriptions : rigid-ob(scape-wheel), rigid-ob(pallet), rigid-ob(gear)
Translational-Constraints : scape-wheel (?x1 ?y1), pallet (?x2 ?y2), gear (?x3 ?y3)
Surfaces : pallet (p-1 (0 -) (+ +)), (p-2 (- 0) (- +))
           scape-wheel (s-w-1 (0 +) (+ -)), (s-w-2 (+ 0) (- -)), (s-w-b-1 (- -) (0 +)),
             (s-w-b-2 (0 -) (0 +)), (s-w-b-3 (+ -) (0 +))
           gear (gear-top-1 (+ +) (0 -)), (gear-top-2 (0 +) (0 -)), (gear-top-3 (- +) (0 -))
Situation : Contact (s-w-b-3 gear-top-3), Contact (s-w-1 p-1)
Situation : Contact (s-w-b-3 gear-top-3), Contact (s-w-1 p-1), Motion (pallet (0 0) (+))
)";

// A 3-D block standing on a table on four bottom corners: it may spin about the vertical axis but
// not tip (Table 2.1 rotations; a physical check of the 3-D Rotate-90, not a thesis figure).
const char* const block3d_text = R"((Defscenario 3 block-3d
  Individuals (block table)
  Surfaces ((block (b-ll (0 0 -) (+ + +)) (b-lr (0 0 -) (- + +)) (b-ul (0 0 -) (+ - +)) (b-ur (0 0 -) (- - +)))
            (table (tb (0 0 +) (0 0 0))))
  Translational-Constraints ((table (?x ?y ?z)))
  Rotational-Constraints ((table (?a ?b ?c))))
(Defstates ((Contact tb b-ll) (Contact tb b-lr) (Contact tb b-ul) (Contact tb b-ur)))
)";

ObjectId id(const Scene& s, const char* name) {
    const auto o = s.find_object(name);
    REQUIRE(o.has_value());
    return *o;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The oracle on its own: its arithmetic against real vectors, its laws against the thesis.

TEST_CASE("analysis/kinematics_oracle: qualitative Rotate-90 and half planes agree with real vectors") {
    std::mt19937 rng(20240501);
    auto real_sign = [](double x) { return x > 0 ? 1 : x < 0 ? -1 : 0; };
    auto component = [&](int sign) {
        // Magnitudes spread over six orders so that every qualitatively possible outcome occurs.
        static const double mags[] = {0.001, 0.1, 1.0, 10.0, 1000.0};
        return sign * mags[rng() % 5];
    };
    std::size_t checked = 0, ambiguous_seen = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        std::array<double, 3> v{}, w{}, o{};
        QVec qv(3), qw(3), qo(3);
        for (std::size_t i = 0; i < 3; ++i) {
            qv[i] = static_cast<int>(rng() % 3) - 1;
            qw[i] = static_cast<int>(rng() % 3) - 1;
            qo[i] = static_cast<int>(rng() % 3) - 1;
            v[i] = component(qv[i]);
            w[i] = component(qw[i]);
            o[i] = component(qo[i]);
        }
        // Real quarter turn: w x v (w the rotation vector, Table 2.1's right-handed axes).
        const std::array<double, 3> c{w[1] * v[2] - w[2] * v[1], w[2] * v[0] - w[0] * v[2], w[0] * v[1] - w[1] * v[0]};
        const QVec q = oracle::rotate90(qv, qw);
        const int axes = (qw[0] != 0) + (qw[1] != 0) + (qw[2] != 0);
        for (std::size_t i = 0; i < 3; ++i) {
            if (q[i] == oracle::amb) {
                ++ambiguous_seen;
                CHECK(axes >= 2);  // one axis alone is exact
            } else {
                CHECK(q[i] == real_sign(c[i]));
            }
        }
        // Open half plane: whenever it holds, every real instance has a positive dot product.
        if (oracle::open_half_plane(q, qo)) CHECK(c[0] * o[0] + c[1] * o[1] + c[2] * o[2] > 0);
        // 2-D is the z-axis case of 3-D.
        if (qw[0] == 0 && qw[1] == 0) {
            const QVec q2 = oracle::rotate90({qv[0], qv[1]}, {qw[2]});
            CHECK(q2[0] == q[0]);
            CHECK(q2[1] == q[1]);
        }
        ++checked;
    }
    CHECK(ambiguous_seen > 0);
    // Exactness of the open half plane on sign vectors: it holds iff every term is >= 0 and one is +.
    for (int x = 0; x < 81; ++x)
        for (int y = 0; y < 81; ++y) {
            QVec a(4), b(4);
            int pos = 0, neg = 0;
            for (int i = 0, xx = x, yy = y; i < 4; ++i, xx /= 3, yy /= 3) {
                a[static_cast<std::size_t>(i)] = xx % 3 - 1;
                b[static_cast<std::size_t>(i)] = yy % 3 - 1;
                const int t = a[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(i)];
                pos += t > 0;
                neg += t < 0;
            }
            CHECK(oracle::open_half_plane(a, b) == (pos > 0 && neg == 0));
        }
    // The guide's 2-D formulas, literally.
    CHECK(oracle::rotate90({1, 0}, {1}) == QVec{0, 1});
    CHECK(oracle::rotate90({1, 0}, {-1}) == QVec{0, -1});
    CHECK(oracle::rotate90({1, 1}, {0}) == QVec{0, 0});
    MESSAGE("real-vector trials: " << checked);
}

TEST_CASE("analysis/kinematics_oracle: the oracle reproduces the thesis' own results") {
    SUBCASE("block on table: Figures 7.3 and 7.5") {
        const Scene s = read_ok(block_text);
        const oracle::Laws laws(s);
        const ObjectId block = id(s, "block"), table = id(s, "table");
        const Expected free_fall = expect(laws, s, s.situations[0], 100000);
        CHECK(free_fall.freedom[block.value].translation == laws.translations());  // Figure 7.3: all nine
        CHECK(free_fall.freedom[block.value].rotation == laws.rotations());
        const Expected on_table = expect(laws, s, s.situations[1], 100000);
        CHECK(on_table.freedom[block.value].translation == dirs({"++", "+0", "0+", "00", "-+", "-0"}));
        CHECK(on_table.freedom[block.value].rotation == dirs({"0"}));
        CHECK(on_table.freedom[table.value].translation == dirs({"00"}));
        CHECK(on_table.freedom[table.value].rotation == dirs({"0"}));
    }
    SUBCASE("arch: Figure 7.9") {
        const Scene s = read_ok(arch_text);
        const oracle::Laws laws(s);
        const Expected e = expect(laws, s, s.situations[0], 100000);
        for (const char* o : {"cross-bar", "left", "right"}) {
            CHECK(e.freedom[id(s, o).value].translation == dirs({"++", "+0", "0+", "00", "-+", "-0"}));
            CHECK(e.freedom[id(s, o).value].rotation == dirs({"0"}));
        }
    }
    SUBCASE("gear pair: Figures 7.13 and 7.14, six combinations") {
        const Scene s = read_ok(gears_text);
        const oracle::Laws laws(s);
        const Expected e = expect(laws, s, s.situations[0], 100000);
        for (const char* o : {"driver", "follower"}) {
            CHECK(e.freedom[id(s, o).value].translation == dirs({"00"}));
            CHECK(e.freedom[id(s, o).value].rotation == dirs({"+", "0", "-"}));
        }
        REQUIRE(e.chains.size() == 1);
        // Figure 7.14 as (driver, follower) rotations; the translations are zero.
        std::set<std::pair<std::string, std::string>> expected{{"+", "+"}, {"+", "-"}, {"+", "0"},
                                                               {"-", "+"}, {"0", "+"}, {"0", "0"}};
        std::set<std::pair<std::string, std::string>> got;
        const std::size_t d = id(s, "driver").value, f = id(s, "follower").value;
        const auto& objs = e.chains[0].objects;
        const std::size_t di = static_cast<std::size_t>(std::find(objs.begin(), objs.end(), d) - objs.begin());
        const std::size_t fi = static_cast<std::size_t>(std::find(objs.begin(), objs.end(), f) - objs.begin());
        for (const auto& combo : e.chains[0].combinations)
            got.insert({std::string(1, sign_char(laws.rotations()[combo[di].second][0])),
                        std::string(1, sign_char(laws.rotations()[combo[fi].second][0]))});
        CHECK(e.chains[0].combinations.size() == 6);
        CHECK(got == expected);
    }
    SUBCASE("recoil escapement: Figure 7.17, ten combinations, one with the pallet given (+) (Figure 7.18)") {
        const Scene s = read_ok(recoil_text);
        const oracle::Laws laws(s);
        const Expected e = expect(laws, s, s.situations[0], 100000);
        for (const char* o : {"scape-wheel", "pallet", "gear"}) {
            CHECK(e.freedom[id(s, o).value].translation == dirs({"00"}));
            CHECK(e.freedom[id(s, o).value].rotation == dirs({"+", "0", "-"}));
        }
        REQUIRE(e.chains.size() == 1);
        CHECK(e.chains[0].combinations.size() == 10);
        const Expected given = expect(laws, s, s.situations[1], 100000);
        REQUIRE(given.chains.size() == 1);
        REQUIRE(given.chains[0].combinations.size() == 1);
        const auto& objs = given.chains[0].objects;
        const auto& combo = given.chains[0].combinations[0];
        for (std::size_t i = 0; i < objs.size(); ++i) {
            const std::string& name = s.objects[ObjectId{static_cast<std::uint32_t>(objs[i])}].name;
            const Sign r = laws.rotations()[combo[i].second][0];
            CHECK(oracle::is_zero(laws.translations()[combo[i].first]));
            CHECK(r == (name == "gear" ? Sign::minus : Sign::plus));  // Figure 7.18
        }
    }
    SUBCASE("3-D block on four corners may spin about z but not tip") {
        const Scene s = read_ok(block3d_text);
        const oracle::Laws laws(s);
        const Expected e = expect(laws, s, s.situations[0], 100000);
        CHECK(e.freedom[id(s, "block").value].rotation == dirs({"00+", "000", "00-"}));
        for (const auto& t : e.freedom[id(s, "block").value].translation) CHECK(t[2] != Sign::minus);
        CHECK(e.freedom[id(s, "block").value].translation.size() == 18);
    }
}

// ---------------------------------------------------------------------------------------------
// The product against the oracle.

TEST_CASE("analysis/kinematics_oracle: the product agrees with the oracle on the thesis' scenes") {
    for (const char* src : {block_text, arch_text, gears_text, recoil_text, block3d_text}) {
        const Scene s = read_ok(src);
        const oracle::Laws laws(s);
        Analysis a = analyse_ok(s);
        REQUIRE(a.situations().size() == s.situations.size());
        for (std::size_t k = 0; k < s.situations.size(); ++k) {
            INFO(s.name << " situation " << k + 1);
            const Expected e = expect(laws, s, s.situations[k], 100000);
            CHECK(compare(laws, s, s.situations[k], e, a.situations()[k]).diff == "");
        }
    }
}

// The kinematically consistent combinations (SituationResult::kinematic, `--kinematic`) are
// what blocking and pushing alone allow, before the forces choose: on scenes with forces they must be
// exactly the oracle's consistent combinations, which know no force. The thesis' scenes get gravity
// on every movable object; the crate on a shim on an incline is scenarios/alex/crate_shim.def.
TEST_CASE("analysis/kinematics_oracle: with forces, the kinematically consistent set is the oracle's") {
    auto with_gravity = [](std::string text, std::initializer_list<const char*> objects) {
        std::string forces = " Forces (";
        for (const char* o : objects) forces += std::string("(") + o + " (0 -) (0 0)) ";
        const std::size_t defstates = text.find("\n(Defstates");
        REQUIRE(defstates != std::string::npos);
        text.insert(defstates - 1, forces + ")");  // inside the Defscenario's last parenthesis
        return text;
    };
    std::ifstream crate(std::string(QM_SOURCE_DIR) + "/scenarios/alex/crate_shim.def");
    const std::string crate_text((std::istreambuf_iterator<char>(crate)), std::istreambuf_iterator<char>());
    REQUIRE(!crate_text.empty());
    std::size_t narrowed = 0;  // situations whose forces select fewer combinations than kinematics allows
    for (const std::string& src : {with_gravity(block_text, {"block"}), with_gravity(arch_text, {"cross-bar", "left", "right"}),
                                   crate_text}) {
        const Scene s = read_ok(src);
        REQUIRE(!s.forces.empty());
        const oracle::Laws laws(s);
        Analysis a = analyse_ok(s);
        for (std::size_t k = 0; k < s.situations.size(); ++k) {
            INFO(s.name << " situation " << k + 1);
            const Expected e = expect(laws, s, s.situations[k], 100000);
            SituationResult kinematic = a.situations()[k];
            REQUIRE(kinematic.kinematic_computed);
            CHECK(kinematic.kinematic_complete);
            const std::uint64_t selected = kinematic.combination_count();
            kinematic.chains = kinematic.kinematic;
            const Verdict v = compare(laws, s, s.situations[k], e, kinematic);
            INFO(v.diff);
            CHECK_FALSE((v.freedom || v.partition || v.extra || v.missing || v.narrowed || v.emptied));
            std::uint64_t count = 1;
            for (const auto& chain : e.chains) count *= chain.combinations.size();
            CHECK(kinematic.kinematic_count() == count);
            CHECK(selected <= count);
            if (selected < count) ++narrowed;
            if (s.name == "crate-on-shim") {
                CHECK(selected == 1);
                CHECK(count == 150);
            }
        }
    }
    CHECK(narrowed >= 3);  // the forces do select somewhere: block 2, arch, crate
}

TEST_CASE("analysis/kinematics_oracle: the product agrees with the oracle on seeded random scenes") {
    // Each random scene is a group of 1-4 objects with 2-6 situations; every analysed scene holds
    // `per_pack` groups side by side (no contact joins two groups, so their chains stay apart),
    // because loading the rule files costs more than analysing a small group. A group with a chain
    // of more than `chain_limit` consistent combinations is replaced by another: it would test
    // nothing new and cost most of the time budget. A Debug+ASan build analyses far more slowly
    // than Release, so the optimised build checks 1,200 scenes and the others 80;
    // QM_ORACLE_PACKS=N in the environment runs N packs (soak runs).
    // Must agree exactly: every free-direction list, the chains, and the combinations of every chain
    // without a given motion. In a chain with a given motion the product may list fewer (never
    // other) combinations than the oracle: that known disagreement is counted and shown, and
    // reproduced by the skipped cases below.
    constexpr std::size_t chain_limit = 1000, per_pack = 4;
#if defined(NDEBUG) && !defined(QM_SANITIZED_BUILD)
    std::size_t packs = 300;
#else
    std::size_t packs = 20;
#endif
    if (const char* env = std::getenv("QM_ORACLE_PACKS"))
        if (const std::size_t n = std::strtoul(env, nullptr, 10); n > 0) packs = n;
    std::size_t groups_checked = 0, groups_3d = 0, replaced = 0, situations = 0, contacts = 0, given = 0, combos = 0;
    std::size_t failures = 0, narrowed = 0, emptied = 0, narrowed_facing = 0, emptied_facing = 0, facing = 0;
    std::string report, narrowed_example, emptied_example;
    bool emptied_example_facing = false;
    for (std::uint32_t p = 0; p < packs; ++p) {
        Random rnd(0x9e3779b9u ^ (p * 2654435761u));
        const int dims = rnd.chance(80) ? 2 : 3;
        const std::size_t sits = 2 + rnd.below(5);
        std::vector<Group> groups;
        std::vector<std::size_t> numbers;
        for (std::size_t g = 0; g < per_pack; ++g) {
            for (int attempt = 0; attempt < 10; ++attempt) {
                Group grp = random_group(rnd, dims, sits);
                const Scene bare = read_ok(render(dims, {grp}, sits, {g}));
                add_given_motions(rnd, grp, bare, oracle::Laws(bare));
                const Scene alone = read_ok(render(dims, {grp}, sits, {g}));
                const oracle::Laws laws(alone);
                bool over = false;
                for (const Situation& sit : alone.situations) over = over || expect(laws, alone, sit, chain_limit).over_limit;
                if (over) {
                    ++replaced;
                    continue;
                }
                groups.push_back(std::move(grp));
                numbers.push_back(g);
                break;
            }
        }
        const std::string src = render(dims, groups, sits, numbers);
        const Scene scene = read_ok(src);
        const oracle::Laws laws(scene);
        Analysis a = analyse_ok(scene);
        REQUIRE(a.situations().size() == scene.situations.size());
        groups_checked += groups.size();
        groups_3d += dims == 3 ? groups.size() : 0;
        // Groups analysed on their own, for reports that show small scenes.
        auto alone_reports = [&](auto&& wanted) {
            std::string out;
            for (std::size_t g = 0; g < groups.size(); ++g) {
                const std::string alone_src = render(dims, {groups[g]}, sits, {numbers[g]});
                const Scene alone = read_ok(alone_src);
                const oracle::Laws alone_laws(alone);
                Analysis b = analyse_ok(alone);
                for (std::size_t k = 0; k < alone.situations.size(); ++k) {
                    const Verdict v = compare(alone_laws, alone, alone.situations[k],
                                              expect(alone_laws, alone, alone.situations[k], chain_limit), b.situations()[k]);
                    if (wanted(v))
                        out += "pack " + std::to_string(p) + ", situation " + std::to_string(k + 1) + ":\n" + alone_src +
                               v.diff + "\n";
                }
            }
            return out;
        };
        auto fails = [](const Verdict& v) { return v.freedom || v.partition || v.extra || v.missing || v.summary; };
        bool pack_failed = false, pack_narrowed = false, pack_emptied = false, pack_emptied_facing = false;
        for (std::size_t k = 0; k < scene.situations.size(); ++k) {
            const Situation& sit = scene.situations[k];
            const Expected e = expect(laws, scene, sit, chain_limit * per_pack);
            REQUIRE_FALSE(e.over_limit);
            situations += groups.size();
            contacts += sit.contacts.size();
            given += sit.motions.size();
            for (const auto& c : e.chains) combos += c.combinations.size();
            const Verdict v = compare(laws, scene, sit, e, a.situations()[k]);
            narrowed += v.narrowed;
            emptied += v.emptied;
            narrowed_facing += v.narrowed && v.facing;
            emptied_facing += v.emptied && v.facing;
            for (const Contact& c : sit.contacts)
                facing += scene.surfaces[c.first].normal == opposite(scene.surfaces[c.second].normal);
            pack_narrowed = pack_narrowed || v.narrowed;
            pack_emptied = pack_emptied || v.emptied;
            pack_emptied_facing = pack_emptied_facing || (v.emptied && v.facing);
            if (fails(v)) {
                ++failures;
                pack_failed = true;
            }
        }
        if (pack_failed && report.size() < 6000) report += alone_reports(fails);
        if (pack_narrowed && narrowed_example.empty())
            narrowed_example = alone_reports([](const Verdict& v) { return v.narrowed; });
        if (pack_emptied_facing && !emptied_example_facing) {
            emptied_example = alone_reports([](const Verdict& v) { return v.emptied && v.facing; });
            emptied_example_facing = true;
        } else if (pack_emptied && emptied_example.empty()) {
            emptied_example = alone_reports([](const Verdict& v) { return v.emptied; });
        }
    }
    MESSAGE("random scenes (groups) checked: " << groups_checked << " (" << groups_3d << " in 3-D) in " << packs
                                               << " analyses; situations (of single scenes): " << situations << ", contacts: " << contacts << " (" << facing << " between facing surfaces)"
                                               << ", given motions: " << given
                                               << ", consistent combinations compared: " << combos
                                               << "; groups replaced (a chain over " << chain_limit
                                               << " combinations): " << replaced);
    MESSAGE("situations where the product keeps only some consistent combinations of a chain with a given motion: "
            << narrowed << " (" << narrowed_facing << " touching only at facing surfaces); that keep none: "
            << emptied << " (" << emptied_facing << " touching only at facing surfaces)\n"
            << narrowed_example << emptied_example);
    INFO(report);
    CHECK(failures == 0);
    // With no forces, a given motion selects nothing: every consistent combination is listed.
    CHECK(narrowed == 0);
    CHECK(emptied == 0);
    CHECK(groups_checked == packs * per_pack);
}

// Disagreement found by the oracle (skipped until the product or the reading changes). Thesis
// section 3.2, Figure 3.4: a block moving right into a boulder; "the boulder must move in one of the
// following directions: translationally right, translationally down right, translationally up right,
// clockwise about a point down from the contact, ... down right ...". Section 6.2: "Given objects
// with current motion, Alex tests to see which possible motions, if any, are consistent (Figure 3.2).
// If motion is possible Alex will determine all potential the directions of motions"; only "Given
// forces acting on objects" does it prefer some motions to others. Here there is no force, so every
// consistent combination must be listed: the boulder may go right, up right or down right, or turn
// clockwise about its centre down right of the contact, or both (9 combinations; it may not go left
// or turn counter-clockwise, which would push the block back, Table 3.2 the other way). Reading the
// given motion as a force on the boulder would keep only the motion nearest to it.
TEST_CASE("analysis/kinematics_oracle: without forces a given motion selects nothing: Figure 3.4") {
    const Scene s = read_ok(R"((Defscenario 2 block-boulder-no-forces
  Individuals (block boulder)
  Surfaces ((block (bk-r (+ 0) (0 0)))
            (boulder (bo-l (- 0) (+ -)))))
(Defstates ((Contact bk-r bo-l) (Motion block (+ 0) (0))))
)");
    const oracle::Laws laws(s);
    const Expected e = expect(laws, s, s.situations[0], 100000);
    REQUIRE(e.chains.size() == 1);
    CHECK(e.chains[0].combinations.size() == 9);
    Analysis a = analyse_ok(s);
    const Verdict v = compare(laws, s, s.situations[0], e, a.situations()[0]);
    INFO(v.diff);
    CHECK(v.exact());
    // The boulder motions of Figure 3.4's list, each with the block's given motion.
    const std::size_t block = id(s, "block").value;
    std::set<std::pair<std::string, std::string>> boulder;
    for (const ChainMotions& c : a.situations()[0].chains)
        for (const auto& combo : c.combinations)
            for (std::size_t i = 0; i < c.objects.size(); ++i)
                if (c.objects[i].value != block) boulder.insert({text(combo[i].translation), text(combo[i].rotation)});
    for (const char* t : {"(+ 0)", "(+ -)", "(+ +)"}) CHECK(boulder.count({t, "(0)"}) == 1);
    CHECK(boulder.count({"(0 0)", "(-)"}) == 1);
}

// Second disagreement, the same cause with a stronger symptom (skipped likewise): a given motion
// that Table 3.2 continues in exactly one way, and the product finds no combination at all, i.e.
// it calls the situation impossible. Found by the random test (pack 2461 of a soak run), reduced by
// hand; every contact is between facing surfaces (section 3.1.1). `a` can only move up, up-left or
// left and cannot turn; it moves up-left into `b` at two places: its up-left face against b's
// down-right face, and its top against b's bottom. Blocking (Table 3.1, a sufficiently constrained
// obstacle at both contacts) leaves b free to go (+ +), (- 0) or stay, and to turn (-) or not.
// Pushing (Table 3.2): at the first contact b can only give way by going left, (- 0); at the second
// it must then turn clockwise about its centre to the right of its bottom, (-). So the one
// consistent combination is a (- +) (0), b (- 0) (-); the product lists none.
TEST_CASE("analysis/kinematics_oracle: a consistent given motion is never impossible") {
    const Scene s = read_ok(R"((Defscenario 2 push-two-faces
  Individuals (a b)
  Surfaces ((a (a-up-left (- +) (- 0)) (a-top (0 +) (- -)))
            (b (b-bottom (0 -) (+ 0)) (b-down-right (+ -) (+ -))))
  Translational-Constraints ((a (+ ?y) (?x -)) (b (0 +) (- +)))
  Rotational-Constraints ((a (?r))))
(Defstates ((Contact b-down-right a-up-left) (Contact a-top b-bottom) (Motion a (- +) (0))))
)");
    const oracle::Laws laws(s);
    const Expected e = expect(laws, s, s.situations[0], 100000);
    CHECK(e.freedom[id(s, "b").value].translation == dirs({"++", "00", "-0"}));
    CHECK(e.freedom[id(s, "b").value].rotation == dirs({"0", "-"}));
    REQUIRE(e.chains.size() == 1);
    CHECK(e.chains[0].combinations.size() == 1);
    Analysis a = analyse_ok(s);
    const Verdict v = compare(laws, s, s.situations[0], e, a.situations()[0]);
    INFO(v.diff);
    CHECK(v.exact());
    CHECK(a.situations()[0].combination_count() == 1);
}
