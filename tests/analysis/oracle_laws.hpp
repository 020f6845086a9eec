// tests/analysis/oracle_laws.hpp: the kinematic laws written again in plain C++, for the two test
// oracles (kinematics_oracle_test.cpp checks them on their own and against the product;
// force_oracle_test.cpp builds the force laws on them).
//
// Written from the thesis text (Nielsen 1988, sections 2.1-2.4, Definitions 1-7, 12-14, 19, 21-24,
// Law 1, Tables 3.1 and 3.2) and the reading guide (/work/shared/spec/README.md), never from rules/,
// scene/*.cpp or analysis/*.cpp, so that a mistake in either shows up as a disagreement. A
// direction is a QVec: -1, 0, +1 per place, or `amb` where a sum's sign is unknown; a direction's
// id is its index in all_directions().
#pragma once
#include "scene/scene.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace oracle {
using namespace qm::scene;

// ---------------------------------------------------------------------------------------------
// Qualitative values and arithmetic (section 2.3, Tables 2.2 and 2.3). `amb` is the sum of a +
// and a - term: its sign is unknown.
using QVec = std::vector<int>;
constexpr int amb = 2;

inline int qadd(int a, int b) {
    if (a == 0) return b;
    if (b == 0) return a;
    if (a == amb || b == amb || a != b) return amb;
    return a;
}
inline int qmul(int a, int b) {
    if (a == 0 || b == 0) return 0;
    if (a == amb || b == amb) return amb;
    return a * b;
}
inline int qneg(int a) { return a == amb ? amb : -a; }
inline int qdot(const QVec& x, const QVec& y) {
    int s = 0;
    for (std::size_t i = 0; i < x.size(); ++i) s = qadd(s, qmul(x[i], y[i]));
    return s;
}
// Definition 13; an ambiguous dot product is not in the open half plane (guide: the liberal bias
// of section 7.3).
inline bool open_half_plane(const QVec& x, const QVec& y) { return qdot(x, y) == 1; }
inline QVec negated(QVec v) {
    for (int& x : v) x = qneg(x);
    return v;
}
inline bool is_zero(const QVec& v) {
    return std::all_of(v.begin(), v.end(), [](int x) { return x == 0; });
}

// Definition 14, Rotate-90(v, r): v turned a quarter turn in rotational direction r. 2-D (guide):
// (x y) -> (-y x) for (+), (y -x) for (-). 3-D: for each axis a with r_a != 0 the quarter turn
// about that axis is r_a (e_a x v), the directions of Table 2.1 (positive about x takes y to z,
// about y z to x, about z x to y); the turns about several axes are summed qualitatively. A zero
// rotation moves nothing (zero vector, which is in no open half plane).
inline QVec rotate90(const QVec& v, const QVec& r) {
    if (v.size() == 2) {
        if (r[0] == 1) return {qneg(v[1]), v[0]};
        if (r[0] == -1) return {v[1], qneg(v[0])};
        return {0, 0};
    }
    QVec out{0, 0, 0};
    for (std::size_t a = 0; a < 3; ++a) {
        if (r[a] == 0) continue;
        // e_x x (x y z) = (0 -z y); e_y x v = (z 0 -x); e_z x v = (-y x 0).
        QVec turn;
        if (a == 0) turn = {0, qneg(v[2]), v[1]};
        if (a == 1) turn = {v[2], 0, qneg(v[0])};
        if (a == 2) turn = {qneg(v[1]), v[0], 0};
        for (std::size_t i = 0; i < 3; ++i) out[i] = qadd(out[i], qmul(r[a], turn[i]));
    }
    return out;
}

inline QVec qvec(const Direction& d) {
    QVec out;
    for (Sign s : d) out.push_back(static_cast<int>(s));
    return out;
}
// Pre: no place of q is `amb`.
inline Direction direction(const QVec& q) {
    Direction out;
    for (int x : q) out.push_back(static_cast<Sign>(x));
    return out;
}

// Definitions 1 and 4: every direction of n places, in the canonical order the product documents
// (lexicographic over + 0 -, first place most significant).
inline std::vector<QVec> all_directions(std::size_t n) {
    std::vector<QVec> out{QVec{}};
    for (std::size_t place = 0; place < n; ++place) {
        std::vector<QVec> next;
        for (const QVec& d : out)
            for (int s : {1, 0, -1}) {
                QVec e = d;
                e.push_back(s);
                next.push_back(std::move(e));
            }
        out = std::move(next);
    }
    return out;
}

// Pattern matching of a constraint entry (guide: `?x` matches any sign in its place, nothing else
// links places), written here independently of the product's `matches`.
inline bool pattern_matches(const DirectionPattern& p, const QVec& d) {
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p[i].sign && static_cast<int>(*p[i].sign) != d[i]) return false;
    return true;
}

// ---------------------------------------------------------------------------------------------
// Kinematic chains (Definition 22): objects joined by a contact or a linkage (Definition 21).
struct Components {
    explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
    std::size_t find(std::size_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
    // The members of each set among 0..n-1, each ascending, the sets in ascending order.
    std::vector<std::vector<std::size_t>> groups(std::size_t n) {
        std::map<std::size_t, std::vector<std::size_t>> by_root;
        for (std::size_t o = 0; o < n; ++o) by_root[find(o)].push_back(o);
        std::vector<std::vector<std::size_t>> out;
        for (auto& [root, members] : by_root) out.push_back(std::move(members));
        std::sort(out.begin(), out.end());
        return out;
    }
    std::vector<std::size_t> parent;
};

using Motion2 = std::pair<std::size_t, std::size_t>;  // (translation id, rotation id)

struct Freedoms {
    // [object][direction id]: constrained (Definition 23). Free = not constrained (Definition 24).
    std::vector<std::vector<bool>> trans_constrained, rot_constrained;
};

// Table 3.2 on one contact, one way round: the body (owner of p) moves into the object (owner of
// q) by a translation into the open half plane of -SN (SN the normal of q) or a rotation turning
// its contact point there; the object must then move away likewise. Indexed by direction id.
struct Push {
    std::size_t body, obj;  // chain slots
    std::vector<bool> body_t, body_r, obj_t, obj_r;
};

// The consistent combinations of one chain, sorted (Law 1); over_limit when the search stopped.
struct Consistent {
    std::vector<std::vector<Motion2>> combinations;
    std::vector<Push> pushes;
    bool over_limit = false;
};

class Kinematics {
public:
    explicit Kinematics(const Scene& scene)
        : scene_(scene), trans_(all_directions(scene.translation_arity())), rot_(all_directions(scene.rotation_arity())) {}

    const std::vector<QVec>& translations() const { return trans_; }
    const std::vector<QVec>& rotations() const { return rot_; }
    std::size_t trans_id(const QVec& d) const { return id_of(trans_, d); }
    std::size_t rot_id(const QVec& d) const { return id_of(rot_, d); }

    // Translations d with Open-Half-Plane(m, d).
    std::vector<bool> into(const QVec& m) const {
        std::vector<bool> out;
        for (const QVec& d : trans_) out.push_back(open_half_plane(m, d));
        return out;
    }
    // Rotations r with Rotate-90(m, x, r) and Open-Half-Plane(x, origin).
    std::vector<bool> turning(const QVec& m, const QVec& origin) const {
        std::vector<bool> out;
        for (const QVec& r : rot_) out.push_back(open_half_plane(rotate90(m, r), origin));
        return out;
    }

    // Frame constraints (Translational-/Rotational-Constraints patterns; never the zero direction),
    // then Table 3.1 on every contact in both directions, iterated to the least fixed point: an
    // obstacle sufficiently constrained (every translation into the open half plane of -SN, SN the
    // normal of its surface p, and every rotation turning p's origin there) constrains the same for
    // the object.
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

    // Objects joined by the situation's contacts and the scene's linkages.
    Components contacts_and_linkages(const Situation& sit, std::size_t extra = 0) const {
        Components c(scene_.objects.size() + extra);
        for (const Contact& k : sit.contacts) c.join(scene_.surfaces[k.first].object.value, scene_.surfaces[k.second].object.value);
        for (const Linkage& l : scene_.linkages) c.join(l.first.value, l.second.value);
        return c;
    }
    std::vector<std::vector<std::size_t>> chains(const Situation& sit) const {
        return contacts_and_linkages(sit).groups(scene_.objects.size());
    }

    // Law 1 (exactly one translation and one rotation per object), brute force over the chain:
    // consistent iff no motion is constrained (Definition 23), every given motion holds, linked
    // objects move alike (Definition 21), and on every contact, both ways, Table 3.2 holds. Stops
    // (over_limit) after `limit` consistent combinations.
    Consistent consistent(const Situation& sit, const Freedoms& f, const std::vector<std::size_t>& chain,
                          std::size_t limit) const {
        Consistent res;
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
                        if (m.object.value == o && (trans_id(qvec(m.translation)) != t || rot_id(qvec(m.rotation)) != r))
                            given_ok = false;
                    if (given_ok) domain[i].push_back({t, r});
                }
            }
        }
        for (const Contact& c : sit.contacts)
            for (auto [p, q] : {std::pair{c.first, c.second}, std::pair{c.second, c.first}}) {
                const Surface& sp = scene_.surfaces[p];
                const Surface& sq = scene_.surfaces[q];
                if (slot[sp.object.value] == SIZE_MAX) continue;  // another chain
                const QVec m = negated(qvec(sq.normal));
                res.pushes.push_back({slot[sp.object.value], slot[sq.object.value], into(m), turning(m, qvec(sp.origin)),
                                      into(m), turning(m, qvec(sq.origin))});
            }
        std::vector<std::vector<const Push*>> checks_at(chain.size());  // checked once both slots are set
        for (const Push& p : res.pushes) checks_at[std::max(p.body, p.obj)].push_back(&p);
        std::vector<std::vector<std::size_t>> linked_at(chain.size());
        for (const Linkage& l : scene_.linkages)
            if (slot[l.first.value] != SIZE_MAX) {
                const std::size_t x = slot[l.first.value], y = slot[l.second.value];
                linked_at[std::max(x, y)].push_back(std::min(x, y));
            }
        std::vector<Motion2> current(chain.size());
        auto consistent_at = [&](std::size_t i) {
            for (std::size_t j : linked_at[i])
                if (current[j] != current[i]) return false;
            for (const Push* p : checks_at[i]) {
                const Motion2 b = current[p->body], o = current[p->obj];
                if ((p->body_t[b.first] || p->body_r[b.second]) && !(p->obj_t[o.first] || p->obj_r[o.second])) return false;
            }
            return true;
        };
        auto search = [&](auto&& self, std::size_t i) -> void {
            if (res.over_limit) return;
            if (i == chain.size()) {
                if (res.combinations.size() >= limit) res.over_limit = true;
                else res.combinations.push_back(current);
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

protected:
    const Surface& surface(SurfaceId s) const { return scene_.surfaces[s]; }

    const Scene& scene_;
    std::vector<QVec> trans_, rot_;

private:
    static std::size_t id_of(const std::vector<QVec>& all, const QVec& d) {
        const auto it = std::find(all.begin(), all.end(), d);
        QM_REQUIRE(it != all.end(), "direction of the wrong arity");
        return static_cast<std::size_t>(it - all.begin());
    }
};

}  // namespace oracle
