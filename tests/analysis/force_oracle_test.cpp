// tests/analysis/force_oracle_test.cpp: analysis/analysis.hpp - an independent test oracle for the force
// laws, compared with the product's analysis on seeded random scenes with forces.
//
// Why an oracle: the product derives the motions that forces produce from rule files on an ATMS.
// Here the same laws are written directly in plain C++ from the thesis (Nielsen 1988: Defs 8-11,
// section 3.3 and Table 3.3, section 5.3.2 and Law 5, section 6.2, section 8.3.4 and Def 38) and
// from the readings docs/LAWS.md states ("Forces", "Which motion a force produces", "Given current
// motion"), never from rules/, scene/*.cpp or analysis/*.cpp, so that a mistake in either shows up as a
// disagreement. The kinematic part (Table 3.1 blocking fixed point, Table 3.2 motion transfer,
// Law 1, Def 23) is oracle_laws.hpp's, which tests/analysis/kinematics_oracle_test.cpp checks on its
// own. On the thesis' scenes with forces (Figures 7.4, 7.6, 7.10; section 6.1's lever; Figure 3.2;
// Figure 5.2) it agrees with the product, which agrees with the thesis (tests/scenarios/).
//
// Readings chosen where docs/LAWS.md leaves room (see `Readings`; each one is the thesis' text
// taken literally where it speaks, and each is checked to matter: flipping it makes the random
// families disagree with the product):
// - every torque of Table 3.3 counts in the net torque, constrained or not (Table 3.3 has no
//   constraint test on torques; on the wedge of Figure 3.2 the block's weight gives opposite
//   torques that must cancel by Law 5); a net torque is passed on only when the body may turn so;
// - an ambiguous component of a net force stands for any of +, 0, - (Table 2.2's `?`);
// - a pushed force (a torque passed on one contact) makes its object driven, like any force;
// - Def 38 lists v and -v apart from the half planes that also hold them: v is nearest, -v furthest;
// - what is pushed along (Table 3.2) by something a given motion pushes is exempt from its forces'
//   threshold too, and linked objects share every force, pushed ones included (the two cases
//   below are scenes where a narrower reading of either would differ).
// - section 8.3.4's threshold ends the order: every motion past zero ranks alike (so a pushed
//   object's force does not choose among the ways it is pushed);
// - section 2.3's branching: along an axis where exactly two causes act, oppositely, the answer to
//   "which is larger?" (+, 0, -) decides the sign; one answer per pair of causes for every object
//   of the situation; answers must be realisable by magnitudes (no cycle); three or more causes
//   along an axis in both directions keep `amb`. The selection is made per answer and united;
//   chains sharing a compared cause are taken together. (Written from docs/LAWS.md "Opposing
//   causes", not from rules/cause_comparison.rules: cycles are found by a closure matrix here, by
//   rules there.)
// Found: everything else agrees exactly (see the MESSAGEs; soak runs with QM_FORCE_ORACLE_PACKS).
#include "oracle_laws.hpp"
#include "oracle_scenes.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace qm::scene;
using namespace qm::analysis;
using namespace oracle;

namespace force_oracle {

// Where docs/LAWS.md leaves room; the defaults are the readings this file argues for (top of file).
struct Readings {
    bool torque_needs_freedom = false;   // a constrained torque does not count (Table 3.3 keeps it)
    bool turn_needs_freedom = true;      // a net torque is passed on only when the body may turn so
    bool ambiguous_includes_zero = true; // `?` resolves to +, 0 or - (else + or -)
    bool pushed_force_drives = true;     // a pushed force makes its object driven
    bool given_push_transitive = true;   // what a body pushed by a given motion pushes is exempt too
    bool into_by_body_normal = false;    // "into the object" by the body's normal (else Table 3.2's)
    int linked_share = 2;                // a linked pair shares 0: external, 1: also transmitted, 2: every force
    bool compare_causes = true;          // two opposing causes branch on which prevails (else the sum stays `amb`)
    bool ranks_stop_at_zero = true;      // past the zero threshold every motion ranks alike (else Def 38 on to -v)
};

// One force on one object (Def 8): an external one (the scene's), one transmitted through a contact
// (section 5.3.2), or a pushed one (a torque passed on one contact; counted, never passed on).
struct ForceOn {
    enum Kind : int { external = 0, transmitted = 1, pushed = 2 };
    std::size_t object;
    QVec dir, origin;
    std::uint32_t cause;
    Kind kind;
    auto key() const { return std::tie(object, dir, origin, cause, kind); }
    friend bool operator<(const ForceOn& a, const ForceOn& b) { return a.key() < b.key(); }
};

struct ChainResult {
    std::vector<std::size_t> objects;                // ascending object indices
    std::vector<std::vector<Motion2>> consistent;    // kinematically consistent (sorted)
    std::vector<std::vector<Motion2>> selected;      // what the forces leave (sorted)
    std::size_t branches = 0;                        // realisable answers to the comparisons here
    std::size_t kinematic_chains = 1;                // kinematic chains (Def 22) taken together here
    bool over_limit = false;
};

// What the forces come to on one object.
struct Drive {
    bool driven = false;
    QVec net_trans, net_rot;  // may hold `amb`
    // Each cause's own sums after Law 5 (never `amb`): what a comparison of causes compares.
    std::map<std::uint32_t, QVec> cause_trans, cause_rot;
};

// Two causes (smaller id first) and how their magnitudes compare: +1 the first is larger, 0 equal,
// -1 the second is larger (section 2.3).
using CausePair = std::pair<std::uint32_t, std::uint32_t>;
using Comparison = std::map<CausePair, int>;

struct SituationResult : Freedoms {
    std::vector<ForceOn> forces;
    std::vector<Drive> drive;
    std::vector<ChainResult> chains;
    bool over_limit = false;
};

class Oracle : public Kinematics {
public:
    Oracle(const Scene& scene, Readings readings) : Kinematics(scene), readings_(readings) {}

    SituationResult solve(const Situation& sit, std::size_t limit) const {
        SituationResult res;
        static_cast<Freedoms&>(res) = freedom(sit);
        forces(sit, res);
        std::vector<std::size_t> kinematic;
        const auto groups = chains(sit, res, &kinematic);
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const auto& chain = groups[g];
            res.chains.push_back(motions(sit, res, chain, limit));
            res.chains.back().kinematic_chains = kinematic[g];
            res.over_limit = res.over_limit || res.chains.back().over_limit;
        }
        return res;
    }

    // Definition 38: 0 for v itself, 1 for the open half plane of v, 2 for zero, 3 perpendicular,
    // 4 the opposite half plane, 5 for -v, 6 for none of these. The list runs from nearest to
    // furthest, so v and -v, which also lie in the half planes, take their own places (v nearest,
    // -v furthest). Section 8.3.4's threshold is zero (rank 2). An ambiguous v branches over its
    // resolutions; the nearest rank counts.
    int rank(const QVec& x, const QVec& v) const {
        std::vector<QVec> resolutions{QVec{}};
        for (int c : v) {
            std::vector<QVec> next;
            std::vector<int> values;
            if (c == amb) values = readings_.ambiguous_includes_zero ? std::vector<int>{1, 0, -1} : std::vector<int>{1, -1};
            else values = {c};
            for (const QVec& r : resolutions)
                for (int s : values) {
                    QVec e = r;
                    e.push_back(s);
                    next.push_back(std::move(e));
                }
            resolutions = std::move(next);
        }
        int best = 6;  // in none of Def 38's sets
        for (const QVec& w : resolutions) {
            // A 2-D rotation has one place: nothing is perpendicular to it. 3-D rotations are
            // vectors like translations.
            const bool perpendicular = w.size() >= 2 && std::any_of(rot_.begin(), rot_.end(), [&](const QVec& r) {
                                           return !is_zero(r) && rotate90(w, r) == x;
                                       });
            if (x == w) best = std::min(best, 0);
            else if (open_half_plane(w, x)) best = std::min(best, 1);
            else if (is_zero(x)) best = std::min(best, 2);
            else if (perpendicular) best = std::min(best, 3);
            else if (x == negated(w)) best = std::min(best, 5);
            else if (open_half_plane(negated(w), x)) best = std::min(best, 4);
        }
        // Section 8.3.4: directions are selected "until ... we exceed some threshold", zero: past it
        // the force prefers none of them.
        return readings_.ranks_stop_at_zero ? std::min(best, 3) : best;
    }

    // Section 2.3 as docs/LAWS.md ("Opposing causes") reads it: along an axis where exactly two
    // causes act, in opposite directions, their comparison decides the sign. The pair, if any.
    std::optional<CausePair> deciding(const std::map<std::uint32_t, QVec>& by_cause, std::size_t axis) const {
        if (!readings_.compare_causes) return std::nullopt;
        std::vector<std::pair<std::uint32_t, int>> acting;
        for (const auto& [cause, sum] : by_cause)
            if (sum[axis] != 0) acting.push_back({cause, sum[axis]});
        if (acting.size() != 2 || acting[0].second != -acting[1].second) return std::nullopt;
        return CausePair{std::min(acting[0].first, acting[1].first), std::max(acting[0].first, acting[1].first)};
    }

    // The net force (or torque) with the comparisons applied: each decided axis takes the larger
    // cause's sign (0 when equal); the other axes keep the sum (`amb` where three or more causes
    // act in both directions).
    QVec resolved(const QVec& net, const std::map<std::uint32_t, QVec>& by_cause, const Comparison& w) const {
        QVec out = net;
        for (std::size_t i = 0; i < net.size(); ++i)
            if (const auto pair = deciding(by_cause, i)) {
                const int cmp = w.at(*pair);
                out[i] = cmp == 0 ? 0 : by_cause.at(cmp > 0 ? pair->first : pair->second)[i];
            }
        return out;
    }

    // Comparisons of magnitudes must be realisable by magnitudes: no cycle of "at least" through a
    // "larger". Closure of "at least" (reflexive, transitive), then each "larger" edge checked.
    static bool realisable(const Comparison& w) {
        std::vector<std::uint32_t> causes;
        for (const auto& [pair, cmp] : w) {
            causes.push_back(pair.first);
            causes.push_back(pair.second);
        }
        std::sort(causes.begin(), causes.end());
        causes.erase(std::unique(causes.begin(), causes.end()), causes.end());
        const std::size_t n = causes.size();
        auto at = [&](std::uint32_t c) { return static_cast<std::size_t>(std::lower_bound(causes.begin(), causes.end(), c) - causes.begin()); };
        std::vector<std::vector<bool>> ge(n, std::vector<bool>(n, false));
        std::vector<std::pair<std::size_t, std::size_t>> larger;
        for (std::size_t i = 0; i < n; ++i) ge[i][i] = true;
        for (const auto& [pair, cmp] : w) {
            const std::size_t a = at(pair.first), b = at(pair.second);
            if (cmp >= 0) ge[a][b] = true;
            if (cmp <= 0) ge[b][a] = true;
            if (cmp > 0) larger.push_back({a, b});
            if (cmp < 0) larger.push_back({b, a});
        }
        for (std::size_t k = 0; k < n; ++k)
            for (std::size_t i = 0; i < n; ++i)
                for (std::size_t j = 0; j < n; ++j)
                    if (ge[i][k] && ge[k][j]) ge[i][j] = true;
        return std::none_of(larger.begin(), larger.end(), [&](const auto& e) { return ge[e.second][e.first]; });
    }

private:
    bool trans_free(const SituationResult& res, std::size_t o, const QVec& d) const {
        return !res.trans_constrained[o][trans_id(d)];
    }

    // Table 3.3, translational part: every unconstrained direction in the open half plane of df.
    std::vector<QVec> distributed(const SituationResult& res, std::size_t o, const QVec& df) const {
        std::vector<QVec> out;
        for (std::size_t i = 0; i < trans_.size(); ++i)
            if (open_half_plane(df, trans_[i]) && !res.trans_constrained[o][i]) out.push_back(trans_[i]);
        return out;
    }

    // Table 3.3, rotational part: every rotation r turning df, applied at a point whose direction to
    // the centre is `origin`, into that origin's open half plane. Kept only when free (Readings).
    std::vector<std::size_t> torques(const SituationResult& res, const ForceOn& f) const {
        std::vector<std::size_t> out;
        for (std::size_t i = 0; i < rot_.size(); ++i)
            if (open_half_plane(rotate90(f.dir, rot_[i]), f.origin) &&
                (!readings_.torque_needs_freedom || !res.rot_constrained[f.object][i]))
                out.push_back(i);
        return out;
    }

    // docs/LAWS.md: one force counts in its own direction when that is free, else as the sum of its
    // distributed directions (nothing when all are blocked). Returned as the directions to sum.
    std::vector<QVec> effective(const SituationResult& res, const ForceOn& f) const {
        if (trans_free(res, f.object, f.dir)) return {f.dir};
        return distributed(res, f.object, f.dir);
    }

    // Law 5 then Table 2.2 (Def 11): per cause, a component with both + and - terms is zero; the
    // causes are then added, opposite components giving `amb`.
    static QVec net(std::size_t arity, const std::map<std::uint32_t, std::vector<QVec>>& by_cause) {
        QVec total(arity, 0);
        for (const auto& [cause, terms] : by_cause) {
            for (std::size_t i = 0; i < arity; ++i) {
                bool plus = false, minus = false;
                for (const QVec& t : terms) {
                    plus = plus || t[i] == 1 || t[i] == amb;
                    minus = minus || t[i] == -1 || t[i] == amb;
                }
                total[i] = qadd(total[i], plus && minus ? 0 : plus ? 1 : minus ? -1 : 0);
            }
        }
        return total;
    }

    // Section 5.3.2 as docs/LAWS.md reads it. A force (external or transmitted) moves its body into
    // the object at a contact when its own direction is free and points into the object (Table 3.2's
    // "into": the open half plane of minus the object's normal), or, its own direction blocked, when
    // one of its distributed directions does; the object then receives a force of the same cause in
    // the reverse of its own normal, at that surface's origin. This goes on to a fixed point. Then
    // each object's net torque per cause (Law 5 cancellation) turns it into the objects at its
    // contacts (Table 3.2's rotational "into"), each of which receives a pushed force, one hop only.
    void forces(const Situation& sit, SituationResult& res) const {
        std::set<ForceOn> all;
        auto add_external = [&](const Force& f) {
            all.insert({f.object.value, qvec(f.direction), qvec(f.origin), f.cause.value, ForceOn::external});
        };
        for (const Force& f : scene_.forces) add_external(f);
        for (const Force& f : sit.forces) add_external(f);
        struct Side {
            std::size_t body, obj;
            QVec into;  // -SN, SN the object's normal
            QVec body_origin, obj_origin;
        };
        std::vector<Side> sides;
        for (const Contact& c : sit.contacts)
            for (auto [p, q] : {std::pair{c.first, c.second}, std::pair{c.second, c.first}})
                sides.push_back({surface(p).object.value, surface(q).object.value,
                                 readings_.into_by_body_normal ? qvec(surface(p).normal) : negated(qvec(surface(q).normal)),
                                 qvec(surface(p).origin), qvec(surface(q).origin)});
        // Def 21 as docs/LAWS.md reads it: linked objects share their forces.
        auto share = [&](const ForceOn& f) {
            bool added = false;
            if (static_cast<int>(f.kind) > readings_.linked_share) return added;
            for (const Linkage& l : scene_.linkages)
                for (auto [x, y] : {std::pair{l.first.value, l.second.value}, std::pair{l.second.value, l.first.value}})
                    if (f.object == x) {
                        ForceOn g = f;
                        g.object = y;
                        added = all.insert(g).second || added;
                    }
            return added;
        };
        for (bool changed = true; changed;) {
            changed = false;
            const std::vector<ForceOn> now(all.begin(), all.end());
            for (const ForceOn& f : now) {
                if (share(f)) changed = true;
                if (f.kind == ForceOn::pushed) continue;
                const std::vector<QVec> moves =
                    trans_free(res, f.object, f.dir) ? std::vector<QVec>{f.dir} : distributed(res, f.object, f.dir);
                for (const Side& s : sides) {
                    if (s.body != f.object) continue;
                    if (std::none_of(moves.begin(), moves.end(), [&](const QVec& d) { return open_half_plane(s.into, d); })) continue;
                    if (all.insert({s.obj, s.into, s.obj_origin, f.cause, ForceOn::transmitted}).second) changed = true;
                }
            }
        }
        // Net torque per (object, cause) over the forces that are passed on.
        std::map<std::pair<std::size_t, std::uint32_t>, std::map<std::uint32_t, std::vector<QVec>>> per_cause;
        for (const ForceOn& f : all) {
            if (f.kind == ForceOn::pushed) continue;
            auto& terms = per_cause[{f.object, f.cause}][f.cause];
            for (std::size_t r : torques(res, f)) terms.push_back(rot_[r]);
        }
        std::vector<ForceOn> pushed;
        for (const auto& [key, by_cause] : per_cause) {
            const QVec r = net(rot_.front().size(), by_cause);
            if (is_zero(r)) continue;
            if (readings_.turn_needs_freedom && res.rot_constrained[key.first][rot_id(r)]) continue;
            for (const Side& s : sides)
                if (s.body == key.first && open_half_plane(rotate90(s.into, r), s.body_origin))
                    pushed.push_back({s.obj, s.into, s.obj_origin, key.second, ForceOn::pushed});
        }
        all.insert(pushed.begin(), pushed.end());
        for (const ForceOn& f : pushed) share(f);
        res.forces.assign(all.begin(), all.end());
        // Net force and torque (Def 11 with Law 5), and which objects are driven.
        const std::size_t n = scene_.objects.size();
        std::vector<std::map<std::uint32_t, std::vector<QVec>>> trans_terms(n), rot_terms(n);
        res.drive.assign(n, Drive{});
        for (const ForceOn& f : res.forces) {
            if (f.kind != ForceOn::pushed || readings_.pushed_force_drives) res.drive[f.object].driven = true;
            auto& tt = trans_terms[f.object][f.cause];
            for (const QVec& d : effective(res, f)) tt.push_back(d);
            auto& rt = rot_terms[f.object][f.cause];
            for (std::size_t r : torques(res, f)) rt.push_back(rot_[r]);
        }
        for (std::size_t o = 0; o < n; ++o) {
            res.drive[o].net_trans = net(trans_.front().size(), trans_terms[o]);
            res.drive[o].net_rot = net(rot_.front().size(), rot_terms[o]);
            for (const auto& [cause, terms] : trans_terms[o])
                res.drive[o].cause_trans[cause] = net(trans_.front().size(), {{cause, terms}});
            for (const auto& [cause, terms] : rot_terms[o])
                res.drive[o].cause_rot[cause] = net(rot_.front().size(), {{cause, terms}});
        }
    }

    // Kinematic chains (Def 22, with linkages). Chains whose objects have axes decided by comparisons
    // of causes connected through shared causes are taken together: a comparison has one answer for
    // every object (docs/LAWS.md, "Opposing causes"). kinematic_chains: how many kinematic chains
    // each group holds.
    std::vector<std::vector<std::size_t>> chains(const Situation& sit, const SituationResult& res,
                                                 std::vector<std::size_t>* kinematic_chains = nullptr) const {
        const std::size_t n = scene_.objects.size();
        std::map<std::uint32_t, std::size_t> cause_node;  // a node per cause, after the objects
        std::vector<std::pair<std::size_t, std::uint32_t>> decided;  // (object, cause)
        for (std::size_t o = 0; o < n; ++o)
            for (const auto* by_cause : {&res.drive[o].cause_trans, &res.drive[o].cause_rot})
                for (std::size_t i = 0; !by_cause->empty() && i < by_cause->begin()->second.size(); ++i)
                    if (const auto pair = deciding(*by_cause, i))
                        for (std::uint32_t c : {pair->first, pair->second}) {
                            cause_node.try_emplace(c, n + cause_node.size());
                            decided.push_back({o, c});
                        }
        Components c = contacts_and_linkages(sit, cause_node.size());
        std::vector<std::size_t> kinematic(n);
        for (std::size_t o = 0; o < n; ++o) kinematic[o] = c.find(o);
        for (const auto& [o, cause] : decided) c.join(o, cause_node.at(cause));
        auto out = c.groups(n);
        if (kinematic_chains)
            for (const auto& members : out) {
                std::set<std::size_t> roots;
                for (std::size_t o : members) roots.insert(kinematic[o]);
                kinematic_chains->push_back(roots.size());
            }
        return out;
    }

    // Law 1 as oracle_laws.hpp checks it (Kinematics::consistent). Then section 6.2 / Def 38 as
    // docs/LAWS.md reads them: a driven object's motion past the zero threshold of its net force is
    // impossible (unless given as current), and of the rest the combinations that no other beats in
    // nearness (Pareto over every driven object's translation and rotation ranks) remain.
    ChainResult motions(const Situation& sit, const SituationResult& res, const std::vector<std::size_t>& chain,
                        std::size_t limit) const {
        ChainResult out;
        out.objects = chain;
        Consistent kinematic = consistent(sit, res, chain, limit);
        out.consistent = std::move(kinematic.combinations);
        out.over_limit = kinematic.over_limit;
        const std::vector<Push>& pushes = kinematic.pushes;

        // Nearness ranks of the driven objects' motions; the threshold; Pareto.
        std::vector<std::size_t> driven;
        for (std::size_t i = 0; i < chain.size(); ++i)
            if (res.drive[chain[i]].driven) driven.push_back(i);
        auto given = [&](std::size_t o) {
            return std::any_of(sit.motions.begin(), sit.motions.end(), [&](const Motion& m) { return m.object.value == o; });
        };
        // Section 2.3: every realisable answer to the comparisons that decide an axis here is a branch;
        // the selection is made in each, and the branches' selections are united.
        std::vector<CausePair> pairs;
        for (std::size_t i : driven)
            for (const auto* by_cause : {&res.drive[chain[i]].cause_trans, &res.drive[chain[i]].cause_rot})
                for (std::size_t axis = 0; !by_cause->empty() && axis < by_cause->begin()->second.size(); ++axis)
                    if (const auto pair = deciding(*by_cause, axis)) pairs.push_back(*pair);
        std::sort(pairs.begin(), pairs.end());
        pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
        std::set<std::vector<Motion2>> selected;
        std::vector<int> answer(pairs.size(), -1);
        for (;;) {
            Comparison w;
            for (std::size_t k = 0; k < pairs.size(); ++k) w[pairs[k]] = answer[k];
            if (realisable(w)) {
                ++out.branches;
                for (const auto& combo : select(sit, res, chain, driven, pushes, out.consistent, w, given)) selected.insert(combo);
            }
            std::size_t k = 0;
            while (k < answer.size() && answer[k] == 1) answer[k++] = -1;
            if (k == answer.size()) break;
            ++answer[k];
        }
        out.selected.assign(selected.begin(), selected.end());
        return out;
    }

    // In one branch w: the driven objects' ranks against their resolved net force and torque; the
    // threshold (unless moved by a given motion); Pareto.
    template <class Given>
    std::vector<std::vector<Motion2>> select(const Situation& sit, const SituationResult& res,
                                             const std::vector<std::size_t>& chain, const std::vector<std::size_t>& driven,
                                             const std::vector<Push>& pushes,
                                             const std::vector<std::vector<Motion2>>& consistent, const Comparison& w,
                                             const Given& given) const {
        // docs/LAWS.md, "Given current motion": what a given motion pushes (Table 3.2 in this
        // combination), and what that pushes in turn, is moved by being pushed, not held back by
        // its own forces' threshold.
        auto kinematically_moved = [&](const std::vector<Motion2>& combo) {
            std::vector<bool> moved(chain.size(), false);
            for (std::size_t i = 0; i < chain.size(); ++i) moved[i] = given(chain[i]);
            const std::vector<bool> from_given = moved;
            for (bool changed = true; changed;) {
                changed = false;
                for (const Push& p : pushes) {
                    const bool source = readings_.given_push_transitive ? moved[p.body] : from_given[p.body];
                    if (source && !moved[p.obj] && (p.body_t[combo[p.body].first] || p.body_r[combo[p.body].second]))
                        moved[p.obj] = changed = true;
                }
            }
            return moved;
        };
        std::vector<QVec> net_t, net_r;
        for (std::size_t i : driven) {
            const Drive& d = res.drive[chain[i]];
            net_t.push_back(resolved(d.net_trans, d.cause_trans, w));
            net_r.push_back(resolved(d.net_rot, d.cause_rot, w));
        }
        std::vector<std::pair<std::vector<int>, const std::vector<Motion2>*>> ranked;
        for (const auto& combo : consistent) {
            std::vector<int> ranks;
            bool within = true;
            const std::vector<bool> moved = sit.motions.empty() ? std::vector<bool>(chain.size(), false) : kinematically_moved(combo);
            for (std::size_t k = 0; k < driven.size(); ++k) {
                const std::size_t i = driven[k];
                const int rt = rank(trans_[combo[i].first], net_t[k]), rr = rank(rot_[combo[i].second], net_r[k]);
                if ((rt > 2 || rr > 2) && !moved[i]) within = false;
                ranks.push_back(rt);
                ranks.push_back(rr);
            }
            if (within) ranked.push_back({std::move(ranks), &combo});
        }
        std::vector<std::vector<Motion2>> out;
        for (const auto& [ranks, combo] : ranked) {
            bool dominated = false;
            for (const auto& other : ranked) {
                bool no_worse = true, better = false;
                for (std::size_t k = 0; k < ranks.size(); ++k) {
                    no_worse = no_worse && other.first[k] <= ranks[k];
                    better = better || other.first[k] < ranks[k];
                }
                if (no_worse && better) {
                    dominated = true;
                    break;
                }
            }
            if (!dominated) out.push_back(*combo);
        }
        return out;
    }

    Readings readings_;
};

}  // namespace force_oracle

namespace {

using force_oracle::Oracle;
using force_oracle::Readings;

std::string qtext(const QVec& d) {
    std::string s = "(";
    for (std::size_t i = 0; i < d.size(); ++i)
        s += (i ? " " : "") + std::string(d[i] == amb ? "?" : d[i] == 1 ? "+" : d[i] == 0 ? "0" : "-");
    return s + ")";
}
// Readings from the environment for exploratory runs (each token flips one field of `Readings`):
// t1 torque_needs_freedom, f0 turn_needs_freedom, z0 ambiguous_includes_zero, p0
// pushed_force_drives, g0 given_push_transitive, n1 into_by_body_normal, l0/l1 linked_share, c0
// compare_causes, r0 ranks_stop_at_zero.
Readings readings_from_env() {
    Readings r;
    if (const char* env = std::getenv("QM_FORCE_READING")) {
        const std::string s = env;
        if (s.find("t0") != std::string::npos) r.torque_needs_freedom = false;
        if (s.find("z0") != std::string::npos) r.ambiguous_includes_zero = false;
        if (s.find("p0") != std::string::npos) r.pushed_force_drives = false;
        if (s.find("t1") != std::string::npos) r.torque_needs_freedom = true;
        if (s.find("f0") != std::string::npos) r.turn_needs_freedom = false;
        if (s.find("g0") != std::string::npos) r.given_push_transitive = false;
        if (s.find("n1") != std::string::npos) r.into_by_body_normal = true;
        if (s.find("l0") != std::string::npos) r.linked_share = 0;
        if (s.find("l1") != std::string::npos) r.linked_share = 1;
        if (s.find("c0") != std::string::npos) r.compare_causes = false;
        if (s.find("r0") != std::string::npos) r.ranks_stop_at_zero = false;
    }
    return r;
}

std::string combo_text(const Oracle& o, const Scene& scene, const std::vector<std::size_t>& objects,
                       const std::vector<Motion2>& combo) {
    std::string s;
    for (std::size_t i = 0; i < objects.size(); ++i)
        s += scene.objects[ObjectId{static_cast<std::uint32_t>(objects[i])}].name + " " +
             qtext(o.translations()[combo[i].first]) + " " + qtext(o.rotations()[combo[i].second]) + "; ";
    return s;
}

// One situation compared: per chain, the product's combinations against the oracle's selection.
struct Verdict {
    std::string diff;
    std::size_t chains = 0, chains_driven = 0, differing = 0;
    std::size_t branched = 0;   // oracle chains with more than one realisable answer to their comparisons
    std::size_t together = 0;   // oracle chains of several kinematic chains (sharing a compared cause)
    bool partition = false;
};

Verdict compare(const Oracle& o, const Scene& scene, const force_oracle::SituationResult& e,
                const SituationResult& got) {
    Verdict v;
    std::ostringstream diff;
    std::map<std::vector<std::size_t>, const ChainMotions*> by_objects;
    for (const ChainMotions& c : got.chains) {
        std::vector<std::size_t> objs;
        for (ObjectId id : c.objects) objs.push_back(id.value);
        by_objects[objs] = &c;
    }
    auto motions_of = [&](const std::vector<ObjectMotion>& combo) {
        std::vector<Motion2> m;
        for (const ObjectMotion& om : combo)
            m.push_back({o.trans_id(qvec(om.translation)), o.rot_id(qvec(om.rotation))});
        return m;
    };
    // Every product chain lies within one oracle chain (the oracle takes together every chain that
    // shares a compared cause; the product only those whose branches are not independent).
    std::map<std::size_t, std::size_t> oracle_chain_of;
    for (std::size_t k = 0; k < e.chains.size(); ++k)
        for (std::size_t x : e.chains[k].objects) oracle_chain_of[x] = k;
    std::vector<std::vector<const ChainMotions*>> inside(e.chains.size());
    for (const ChainMotions& c : got.chains) {
        std::set<std::size_t> homes;
        for (ObjectId id : c.objects) homes.insert(oracle_chain_of.at(id.value));
        if (homes.size() != 1) {
            v.partition = true;
            diff << "a product chain of " << c.objects.size() << " objects spans " << homes.size() << " oracle chains\n";
            continue;
        }
        inside[*homes.begin()].push_back(&c);
    }
    for (std::size_t k = 0; k < e.chains.size(); ++k) {
        const auto& ec = e.chains[k];
        ++v.chains;
        const bool driven = std::any_of(ec.objects.begin(), ec.objects.end(), [&](std::size_t x) { return e.drive[x].driven; });
        v.chains_driven += driven;
        v.branched += ec.branches > 1;
        v.together += ec.kinematic_chains > 1;
        std::size_t covered = 0;
        for (const ChainMotions* c : inside[k]) covered += c->objects.size();
        if (covered == ec.objects.size() && inside[k].size() > 1) {
            // The oracle's selection must be the product of these chains' selections: as many
            // combinations, each projecting into every one of them.
            std::uint64_t expected = 1;
            for (const ChainMotions* c : inside[k]) expected *= c->combinations.size();
            std::vector<std::set<std::vector<Motion2>>> theirs;
            for (const ChainMotions* c : inside[k]) {
                theirs.emplace_back();
                for (const auto& g : c->combinations) theirs.back().insert(motions_of(g));
            }
            std::size_t outside = 0;
            std::string example;
            for (const auto& combo : ec.selected)
                for (std::size_t j = 0; j < inside[k].size(); ++j) {
                    std::vector<Motion2> part;
                    for (ObjectId id : inside[k][j]->objects)
                        part.push_back(combo[static_cast<std::size_t>(
                            std::find(ec.objects.begin(), ec.objects.end(), id.value) - ec.objects.begin())]);
                    if (theirs[j].count(part) == 0) {
                        ++outside;
                        if (example.empty()) example = combo_text(o, scene, ec.objects, combo);
                        break;
                    }
                }
            if (expected == ec.selected.size() && outside == 0) continue;
            ++v.differing;
            diff << "chain of " << ec.objects.size() << " objects, " << inside[k].size()
                 << " product chains: product " << expected << " combinations, oracle " << ec.selected.size() << " (of "
                 << ec.consistent.size() << " consistent, " << ec.branches << " branches); " << outside
                 << " oracle combinations not in the product's\n";
            if (!example.empty()) diff << "  only oracle:  " << example << "\n";
            continue;
        }
        const auto it = by_objects.find(ec.objects);
        if (it == by_objects.end()) {
            v.partition = true;
            diff << "no product chain for the oracle's chain of "
                 << scene.objects[ObjectId{static_cast<std::uint32_t>(ec.objects.front())}].name << "\n";
            continue;
        }
        std::vector<std::vector<Motion2>> g;
        for (const auto& combo : it->second->combinations) g.push_back(motions_of(combo));
        std::sort(g.begin(), g.end());
        if (g == ec.selected) continue;
        ++v.differing;
        std::vector<std::vector<Motion2>> only_product, only_oracle;
        std::set_difference(g.begin(), g.end(), ec.selected.begin(), ec.selected.end(), std::back_inserter(only_product));
        std::set_difference(ec.selected.begin(), ec.selected.end(), g.begin(), g.end(), std::back_inserter(only_oracle));
        diff << "chain of " << ec.objects.size() << " objects: product " << g.size() << " combinations, oracle "
             << ec.selected.size() << " (of " << ec.consistent.size() << " consistent, " << ec.branches << " branches)\n";
        for (std::size_t x : ec.objects) {
            const force_oracle::Drive& d = e.drive[x];
            if (d.driven)
                diff << "  oracle: " << scene.objects[ObjectId{static_cast<std::uint32_t>(x)}].name << " driven, net force "
                     << qtext(d.net_trans) << " torque " << qtext(d.net_rot) << "\n";
        }
        for (const auto& f : e.forces)
            if (std::find(ec.objects.begin(), ec.objects.end(), f.object) != ec.objects.end())
                diff << "  oracle force on " << scene.objects[ObjectId{static_cast<std::uint32_t>(f.object)}].name << " "
                     << qtext(f.dir) << " at " << qtext(f.origin) << " cause " << f.cause
                     << (f.kind == force_oracle::ForceOn::external ? " external"
                         : f.kind == force_oracle::ForceOn::transmitted ? " transmitted"
                                                                        : " pushed")
                     << "\n";
        for (std::size_t i = 0; i < only_product.size() && i < 4; ++i)
            diff << "  only product: " << combo_text(o, scene, ec.objects, only_product[i]) << "\n";
        for (std::size_t i = 0; i < only_oracle.size() && i < 4; ++i)
            diff << "  only oracle:  " << combo_text(o, scene, ec.objects, only_oracle[i]) << "\n";
    }
    v.diff = diff.str();
    return v;
}

// ---------------------------------------------------------------------------------------------
// Random scenes (oracle_scenes.hpp).

// Families of scenes, from the simplest reading to the most involved.
enum class Family {
    direct,       // objects with no contact: forces act directly, nothing is transmitted
    fixed,        // one movable object touching fixed ones (frame): forces on it only
    chain,        // 2-4 objects, contacts, forces anywhere: transmission, several driven objects
    given,        // as `chain`, with given current motions
    linked,       // as `chain`, two of the objects linked (Def 21)
    causes,       // 2-4 objects, few contacts, pairs of opposite forces from three shared causes (2.3)
};
const char* family_name(Family f) {
    switch (f) {
    case Family::direct: return "direct";
    case Family::fixed: return "fixed";
    case Family::chain: return "chain";
    case Family::given: return "given";
    case Family::linked: return "linked";
    case Family::causes: return "causes";
    }
    return "?";
}

// A random force: often gravity-like ((0 -) at the centre), else any direction, at the centre or
// off it; its own cause or one of two shared names.
Group::F random_force(Random& rnd, std::size_t object, std::size_t tn) {
    Group::F f{object, rnd.non_zero(tn), Direction(tn, Sign::zero), -1};
    if (rnd.chance(30)) {
        f.dir = Direction(tn, Sign::zero);
        f.dir[tn - 1] = Sign::minus;
    }
    if (rnd.chance(50)) f.origin = rnd.direction(tn);
    if (rnd.chance(40)) f.cause = static_cast<int>(rnd.below(2));
    return f;
}

// One random scene of a family: 1-4 objects of 1-3 surfaces (normals often facing another
// object's), frame constraints, scene forces, and per situation contacts and forces.
Group random_group(Random& rnd, Family family, int dims, std::size_t situations) {
    const std::size_t tn = static_cast<std::size_t>(dims), rn = dims == 3 ? 3 : 1;
    Group grp;
    std::size_t count = 1;
    switch (family) {
    case Family::direct: count = 1 + rnd.below(2); break;
    case Family::fixed: count = 2 + rnd.below(2); break;
    case Family::chain:
    case Family::given:
    case Family::linked: count = 2 + rnd.below(dims == 3 ? 2 : 3); break;
    case Family::causes: count = 2 + rnd.below(3); break;
    }
    grp.objects.resize(count);
    for (std::size_t o = 0; o < count; ++o) {
        grp.add_surfaces(rnd, o, tn, 3, 55);
        Group::Obj& obj = grp.objects[o];
        int vars = 0;
        const std::size_t kind = rnd.below(100);
        if ((family == Family::fixed && o > 0) || (family != Family::direct && family != Family::fixed && kind < 20)) {
            obj.trans.push_back(all_variables(tn, vars));
            obj.rot.push_back(all_variables(rn, vars));
        } else if (kind < 40) {  // pinned: turns only
            obj.trans.push_back(all_variables(tn, vars));
            if (rnd.chance(30)) obj.rot.push_back(pattern(rnd, rn, 50, vars));
        } else if (kind < 60) {  // does not turn, some translations constrained
            obj.rot.push_back(all_variables(rn, vars));
            for (std::size_t k = rnd.below(3); k > 0; --k) obj.trans.push_back(pattern(rnd, tn, 40, vars));
        } else {  // random patterns, possibly none
            for (std::size_t k = rnd.below(3); k > 0; --k) obj.trans.push_back(pattern(rnd, tn, 40, vars));
            for (std::size_t k = rnd.below(2); k > 0; --k) obj.rot.push_back(pattern(rnd, rn, 40, vars));
        }
    }
    auto force_target = [&]() -> std::size_t { return family == Family::fixed ? 0 : rnd.below(count); };
    for (std::size_t k = rnd.below(3); k > 0; --k) grp.scene_forces.push_back(random_force(rnd, force_target(), tn));
    grp.contacts.resize(situations);
    grp.forces.resize(situations);
    grp.motions.resize(situations);
    for (std::size_t k = 0; k < situations; ++k) {
        if (family != Family::direct)
            grp.add_contacts(rnd, k, family == Family::causes ? rnd.below(2) : 1 + rnd.below(4), 75,
                             [&](std::size_t a, std::size_t b) { return family != Family::fixed || a == 0 || b == 0; });
        if (family == Family::causes) {
            // Two forces of different shared causes on most objects, often opposite: the same
            // pairs of causes meet on several objects, in and out of contact.
            for (std::size_t o = 0; o < count; ++o) {
                if (!rnd.chance(75)) continue;
                Group::F f = random_force(rnd, o, tn), g = random_force(rnd, o, tn);
                if (rnd.chance(70)) g.dir = opposite(f.dir);
                f.cause = static_cast<int>(rnd.below(3));
                g.cause = static_cast<int>((static_cast<std::size_t>(f.cause) + 1 + rnd.below(2)) % 3);
                grp.forces[k].push_back(f);
                grp.forces[k].push_back(g);
            }
            continue;
        }
        for (std::size_t n = rnd.below(3); n > 0; --n) {
            Group::F f = random_force(rnd, force_target(), tn);
            grp.forces[k].push_back(f);
            // Now and then the opposite force of the same cause (Law 5), on the same or another object.
            if (rnd.chance(25)) {
                Group::F g = f;
                g.dir = opposite(f.dir);
                if (g.cause < 0) g.cause = 1;
                grp.forces[k].back().cause = g.cause;
                if (family != Family::fixed && rnd.chance(40)) g.object = rnd.below(count);
                grp.forces[k].push_back(g);
            }
        }
    }
    if (family == Family::linked) {
        const std::size_t a = rnd.below(count), b = (a + 1 + rnd.below(count - 1)) % count;
        grp.linkages.push_back({a, b});
    }
    return grp;
}

// Given motions: mostly one the object is free to make. `scene` is the group read on its own.
void add_given_motions(Random& rnd, Group& grp, const Scene& scene, const Oracle& oracle) {
    for (std::size_t k = 0; k < grp.motions.size(); ++k) {
        if (!rnd.chance(50)) continue;
        const force_oracle::SituationResult r = oracle.solve(scene.situations[k], 1);
        const std::size_t o = rnd.below(grp.objects.size());
        std::vector<Direction> ts, rs;
        for (std::size_t i = 0; i < oracle.translations().size(); ++i)
            if (!r.trans_constrained[o][i]) ts.push_back(direction(oracle.translations()[i]));
        for (std::size_t i = 0; i < oracle.rotations().size(); ++i)
            if (!r.rot_constrained[o][i]) rs.push_back(direction(oracle.rotations()[i]));
        grp.motions[k].push_back({o, ts[rnd.below(ts.size())], rs[rnd.below(rs.size())]});
    }
}

struct RunStats {
    std::size_t groups = 0, situations = 0, chains = 0, chains_driven = 0, differing = 0, situations_differing = 0;
    std::size_t forces = 0, transmitted = 0, pushed = 0, ambiguous = 0, replaced = 0;
    std::size_t selected = 0, consistent = 0, branched = 0, together = 0, packs = 0;
    std::string examples;
};

// Runs `packs` analyses of `per_pack` random groups of one family; compares every situation.
RunStats run_family(Family family, int dims, std::size_t packs, std::uint32_t seed_base) {
    // 3-D objects have 27 x 27 motions: a free one alone has 729 combinations.
    const std::size_t per_pack = 4, chain_limit = dims == 3 ? 1500 : 400;
    const Readings readings = readings_from_env();
    RunStats st;
    for (std::uint32_t p = 0; p < packs; ++p) {
        Random rnd(seed_base ^ (p * 2654435761u));
        const std::size_t sits = 1 + rnd.below(4);
        std::vector<Group> groups;
        std::vector<std::size_t> numbers;
        for (std::size_t g = 0; g < per_pack; ++g) {
            for (int attempt = 0; attempt < 10; ++attempt) {
                Group grp = random_group(rnd, family, dims, sits);
                if (family == Family::given) {
                    const Scene bare = read_ok(render(dims, {grp}, sits, {g}));
                    add_given_motions(rnd, grp, bare, Oracle(bare, readings));
                }
                const Scene alone = read_ok(render(dims, {grp}, sits, {g}));
                const Oracle oracle(alone, readings);
                bool over = false;
                for (const Situation& sit : alone.situations) over = over || oracle.solve(sit, chain_limit).over_limit;
                if (over) {
                    ++st.replaced;
                    continue;
                }
                groups.push_back(std::move(grp));
                numbers.push_back(g);
                break;
            }
        }
        const Scene scene = read_ok(render(dims, groups, sits, numbers));
        const Oracle oracle(scene, readings);
        Analysis a = analyse_ok(scene);
        REQUIRE(a.situations().size() == scene.situations.size());
        st.groups += groups.size();
        bool pack_differs = false;
        for (std::size_t k = 0; k < scene.situations.size(); ++k) {
            const force_oracle::SituationResult e = oracle.solve(scene.situations[k], chain_limit * per_pack);
            REQUIRE_FALSE(e.over_limit);
            const Verdict v = compare(oracle, scene, e, a.situations()[k]);
            st.situations += groups.size();
            st.chains += v.chains;
            st.chains_driven += v.chains_driven;
            st.branched += v.branched;
            st.together += v.together;
            st.differing += v.differing + (v.partition ? 1 : 0);
            st.situations_differing += v.differing > 0 || v.partition;
            pack_differs = pack_differs || v.differing > 0 || v.partition;
            for (const auto& f : e.forces) {
                ++st.forces;
                st.transmitted += f.kind == force_oracle::ForceOn::transmitted;
                st.pushed += f.kind == force_oracle::ForceOn::pushed;
            }
            for (const auto& d : e.drive)
                st.ambiguous += d.driven && (std::count(d.net_trans.begin(), d.net_trans.end(), amb) +
                                             std::count(d.net_rot.begin(), d.net_rot.end(), amb)) > 0;
            for (const auto& c : e.chains) {
                st.selected += c.selected.size();
                st.consistent += c.consistent.size();
            }
        }
        // Differences are shown on the groups analysed alone (small scenes to reproduce by hand).
        if (pack_differs && st.examples.size() < 12000) {
            for (std::size_t g = 0; g < groups.size(); ++g) {
                const std::string src = render(dims, {groups[g]}, sits, {numbers[g]});
                const Scene alone = read_ok(src);
                const Oracle alone_oracle(alone, readings);
                Analysis b = analyse_ok(alone);
                for (std::size_t k = 0; k < alone.situations.size(); ++k) {
                    const Verdict v = compare(alone_oracle, alone, alone_oracle.solve(alone.situations[k], chain_limit), b.situations()[k]);
                    if (!v.diff.empty())
                        st.examples += std::string(family_name(family)) + " pack " + std::to_string(p) + ", situation " +
                                       std::to_string(k + 1) + ":\n" + src + v.diff + "\n";
                }
            }
        }
    }
    return st;
}

// Runs a family (packs_for: release_packs in a Release build, debug_packs in the others), reports
// what it met and checks that the product agrees everywhere.
RunStats check_family(Family family, int dims, std::size_t release_packs, std::size_t debug_packs, std::uint32_t seed) {
    const std::size_t packs = packs_for(release_packs, debug_packs, "QM_FORCE_ORACLE_PACKS");
    RunStats st = run_family(family, dims, packs, seed);
    st.packs = packs;
    MESSAGE(std::string(family_name(family)) << " (" << dims << "-D): " << st.groups << " scenes in " << packs << " analyses, "
                                << st.situations << " situations, " << st.chains << " chains (" << st.chains_driven
                                << " driven, " << st.branched << " branching on comparisons of causes, " << st.together
                                << " of several kinematic chains sharing a compared cause), consistent combinations " << st.consistent
                                << ", selected " << st.selected
                                << "; forces " << st.forces << " (" << st.transmitted << " transmitted, " << st.pushed
                                << " pushed), driven objects with an ambiguous net force " << st.ambiguous
                                << "; groups replaced (a chain over the limit) " << st.replaced
                                << "; chains where the product differs: " << st.differing << " in "
                                << st.situations_differing << " situations\n"
                                << st.examples.substr(0, 6000));
    CHECK(st.differing == 0);
    return st;
}

// The oracle's selected motions of one object, as "(t) (r)" strings.
std::set<std::string> selected_of(const Oracle& o, const Scene& s, const force_oracle::SituationResult& r, const char* name) {
    std::set<std::string> out;
    const std::size_t x = id(s, name).value;
    for (const auto& c : r.chains)
        for (std::size_t i = 0; i < c.objects.size(); ++i)
            if (c.objects[i] == x)
                for (const auto& combo : c.selected)
                    out.insert(qtext(o.translations()[combo[i].first]) + " " + qtext(o.rotations()[combo[i].second]));
    return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// The oracle on its own, against the thesis' results.

TEST_CASE("analysis/force_oracle: Definition 38 ranks and the zero threshold") {
    const Scene s = read_ok("(Defscenario 2 one Individuals (a))");
    const Oracle o(s, Readings{});
    CHECK(o.rank({0, -1}, {0, -1}) == 0);
    CHECK(o.rank({1, -1}, {0, -1}) == 1);
    CHECK(o.rank({0, 0}, {0, -1}) == 2);
    CHECK(o.rank({1, 0}, {0, -1}) == 3);   // perpendicular: past the threshold
    CHECK(o.rank({1, 1}, {0, -1}) == 3);   // the opposite half plane: past it too, ranked alike (8.3.4)
    CHECK(o.rank({0, 1}, {0, -1}) == 3);   // -v
    CHECK(o.rank({-1}, {1}) == 3);
    CHECK(o.rank({0, 0}, {0, 0}) == 0);    // no net force: only standing still
    CHECK(o.rank({1, 0}, {0, 0}) == 3);
    // Def 38's order beyond the threshold, were it used.
    Readings on;
    on.ranks_stop_at_zero = false;
    const Oracle o_on(s, on);
    CHECK(o_on.rank({1, 1}, {0, -1}) == 4);  // the opposite half plane
    CHECK(o_on.rank({0, 1}, {0, -1}) == 5);  // -v: in that half plane too, but listed last
    CHECK(o_on.rank({1, 0}, {0, 0}) == 6);
    CHECK(o.rank({0, 1}, {0, amb}) == 0);  // (0 ?) resolves to (0 +), (0 0), (0 -)
    CHECK(o.rank({0, 0}, {0, amb}) == 0);
    CHECK(o.rank({1, 1}, {0, amb}) == 1);
    Readings no_zero;
    no_zero.ambiguous_includes_zero = false;
    CHECK(Oracle(s, no_zero).rank({0, 0}, {0, amb}) == 2);
}

// The thesis' scenes with forces need no check of the oracle's selections here: the product agrees
// with it exactly on them (below) and with the thesis (tests/scenarios/). What is checked here is
// the oracle's own account of Law 5.
TEST_CASE("analysis/force_oracle: force fed back (Figure 5.2) cancels by Law 5: A's push comes back with its cause") {
    const Readings r;
    const Scene s = read_file_ok("force_feedback.def");
    const Oracle o(s, r);
    const auto res = o.solve(s.situations[0], 100000);
    // A's push reaches B at S (to the left) and comes back to A at T, upward, with the same
    // cause: it cancels A's own push (A also presses B to the right at T, so B's net is zero).
    const std::size_t a = id(s, "a").value;
    CHECK(std::any_of(res.forces.begin(), res.forces.end(), [&](const force_oracle::ForceOn& f) {
        return f.object == a && f.kind == force_oracle::ForceOn::transmitted && f.dir == QVec{-1, 1};
    }));
    CHECK(res.drive[a].net_trans == QVec{0, 0});
    CHECK(selected_of(o, s, res, "a") == std::set<std::string>{"(0 0) (0)"});
    CHECK(selected_of(o, s, res, "b") == std::set<std::string>{"(0 0) (0)"});
    // Law 5 on its own: opposite forces cancel when they share a cause, else the sum is `?`.
    for (const bool shared : {true, false}) {
        const Scene s2 = read_ok(std::string("(Defscenario 2 law5 Individuals (a) Forces ((a (0 -) (0 0) up) (a (0 +) (0 0) ") +
                                 (shared ? "up" : "down") + ")))(Defstates ())");
        const Oracle o2(s2, r);
        const auto res2 = o2.solve(s2.situations[0], 100000);
        CHECK(res2.drive[0].net_trans == (shared ? QVec{0, 0} : QVec{0, amb}));
        CHECK(selected_of(o2, s2, res2, "a") ==
              (shared ? std::set<std::string>{"(0 0) (0)"} : std::set<std::string>{"(0 +) (0)", "(0 0) (0)", "(0 -) (0)"}));
    }
}

// ---------------------------------------------------------------------------------------------
// The product against the oracle.

TEST_CASE("analysis/force_oracle: the product agrees with the oracle on the thesis' force scenes") {
    for (const char* file : {"block.def", "arch.def", "lever.def", "wedge_ramp.def", "wedge_ramp_catch.def",
                             "force_feedback.def", "block_stack.def", "corner_contacts.def", "crate_shim.def"}) {
        const Scene s = read_file_ok(file);
        if (std::any_of(s.surfaces.begin(), s.surfaces.end(), [](const Surface& x) { return x.is_corner(); })) continue;
        const Oracle o(s, Readings{});
        Analysis a = analyse_ok(s);
        for (std::size_t k = 0; k < s.situations.size(); ++k) {
            INFO(file << " situation " << k + 1);
            const Verdict v = compare(o, s, o.solve(s.situations[k], 100000), a.situations()[k]);
            CHECK(v.diff == "");
        }
    }
}

TEST_CASE("analysis/force_oracle: direct forces on free objects (no contact)") {
    const RunStats st = check_family(Family::direct, 2, 150, 10, 0x51f0u);
    if (st.packs >= 100) {  // comparisons of causes, also joining separate objects that share them
        CHECK(st.branched > 0);
        CHECK(st.together > 0);
    }
    CHECK(st.groups == st.packs * 4);
}

TEST_CASE("analysis/force_oracle: opposing forces of shared causes on several objects (section 2.3)") {
    const RunStats st = check_family(Family::causes, 2, 150, 10, 0xca05u);
    if (st.packs >= 100) {
        CHECK(st.branched > 0);
        CHECK(st.together > 0);
    }
}

TEST_CASE("analysis/force_oracle: forces on one object among fixed ones") {
    check_family(Family::fixed, 2, 150, 10, 0xf1edu);
}

TEST_CASE("analysis/force_oracle: transmission and several driven objects") {
    const RunStats st = check_family(Family::chain, 2, 200, 10, 0xc4a1u);
    if (st.packs >= 100) CHECK(st.branched > 0);  // the family exercises the comparisons of causes
}

TEST_CASE("analysis/force_oracle: forces with given current motions") {
    check_family(Family::given, 2, 150, 10, 0x9173u);
}

// A disagreement this oracle found. A given motion pushes B (no force), B pushes C, which rests on
// the table under gravity (net force zero: its weight is blocked). Table 3.2: the pushed object
// must move away if it can; C can slide right. docs/LAWS.md ("Given current motion") exempts what a
// given motion pushes from its own forces' threshold "since being pushed, not a force, is what
// moves it", and C is moved by being pushed, through B.
TEST_CASE("analysis/force_oracle: a given motion pushes through an object with no force") {
    const Scene s = read_ok(R"((Defscenario 2 given-push-through-intermediary
  Individuals (a b c table)
  Surfaces ((a (a-r (+ 0) (- 0))) (b (b-l (- 0) (+ 0)) (b-r (+ 0) (- 0)))
            (c (c-l (- 0) (+ 0)) (c-b (0 -) (0 +))) (table (tb (0 +) (0 0))))
  Translational-Constraints ((b (?x1 +) (?x2 -)) (table (?x3 ?y3)))
  Rotational-Constraints ((a (?r1)) (b (?r2)) (c (?r3)) (table (?r4)))
  Forces ((c (0 -) (0 0))))
(Defstates ((Contact a-r b-l) (Contact b-r c-l) (Contact c-b tb) (Motion a (+ 0) (0)))))");
    const Oracle o(s, Readings{});
    const auto e = o.solve(s.situations[0], 100000);
    CHECK(selected_of(o, s, e, "c") == std::set<std::string>{"(+ +) (0)", "(+ 0) (0)"});
    Analysis a = analyse_ok(s);
    const Verdict v = compare(o, s, e, a.situations()[0]);
    INFO(v.diff);
    CHECK(v.diff == "");
    CHECK(a.situations()[0].combination_count() == 2);
}

TEST_CASE("analysis/force_oracle: linked objects share their forces") {
    check_family(Family::linked, 2, 150, 10, 0x1127u);
}

// A disagreement this oracle found. d, pinned and pushed down right of its pivot, turns clockwise
// into a's top, so a receives a pushed force (0 -); a is linked to b (Def 21), which a spring lifts.
// docs/LAWS.md: linked objects "share their forces (equal net force)", and a pushed force "counts in
// its net force"; section 8.3.1: forces propagate "either by linkage or by contact". So a and b both
// have net force (0 ?), and d turning clockwise with a and b going down is as near as going up.
TEST_CASE("analysis/force_oracle: a pushed force is shared over a linkage") {
    const Scene s = read_ok(R"((Defscenario 2 linked-pushed-force
  Individuals (d a b)
  Surfaces ((d (d-r (0 -) (- +))) (a (a-top (0 +) (0 -))) (b (b-side (+ 0) (- 0))))
  Translational-Constraints ((d (?x1 ?y1)) (a (+ ?y2) (- ?y3)) (b (+ ?y4) (- ?y5)))
  Rotational-Constraints ((a (?r1)) (b (?r2)))
  Linkages ((a b))
  Forces ((d (0 -) (- 0) hand) (b (0 +) (0 0) spring)))
(Defstates ((Contact d-r a-top))))");
    const Oracle o(s, Readings{});
    const auto e = o.solve(s.situations[0], 100000);
    CHECK(e.drive[id(s, "a").value].net_trans == QVec{0, amb});
    CHECK(e.drive[id(s, "b").value].net_trans == QVec{0, amb});
    CHECK(selected_of(o, s, e, "d").count("(0 0) (-)") == 1);
    CHECK(selected_of(o, s, e, "b").count("(0 -) (0)") == 1);
    Analysis a = analyse_ok(s);
    const Verdict v = compare(o, s, e, a.situations()[0]);
    INFO(v.diff);
    CHECK(v.diff == "");
}

TEST_CASE("analysis/force_oracle: 3-D forces on objects with no contact") {
    check_family(Family::direct, 3, 40, 4, 0x3d01u);
}

TEST_CASE("analysis/force_oracle: 3-D transmission and several driven objects") {
    check_family(Family::chain, 3, 40, 4, 0x3dc4u);
}

// Section 2.3's branching, in scenes built to need it. The oracle's answer is checked against the
// count the reading implies, and the product against the oracle.
TEST_CASE("analysis/force_oracle: opposing causes branch once for every object (section 2.3)") {
    auto agree = [](const Scene& s, std::size_t situation) {
        const Oracle o(s, Readings{});
        const auto e = o.solve(s.situations[situation], 100000);
        Analysis a = analyse_ok(s);
        const Verdict v = compare(o, s, e, a.situations()[situation]);
        INFO(v.diff);
        CHECK(v.diff == "");
        return std::make_pair(e, a.situations()[situation].combination_count());
    };
    SUBCASE("squeezed blocks move together: hand prevails, they balance, or wind prevails") {
        const Scene s = read_file_ok("squeeze.def");
        const auto [e, count] = agree(s, 0);
        CHECK(count == 3);
        CHECK(selected_of(Oracle(s, Readings{}), s, e, "a") == std::set<std::string>{"(+ 0) (0)", "(0 0) (0)", "(- 0) (0)"});
    }
    SUBCASE("a wedge pushed under a block against its weight") {
        const Scene s = read_file_ok("wedge_push.def");
        CHECK(agree(s, 0).second == 3);
        CHECK(agree(s, 1).second == 1);
    }
    SUBCASE("two blocks apart, each pushed by the same hand against the same wind: one answer for both") {
        const Scene s = read_ok(R"((Defscenario 2 apart
  Individuals (a b)
  Forces ((a (+ 0) (0 0) hand) (a (- 0) (0 0) wind) (b (0 +) (0 0) hand) (b (0 -) (0 0) wind)))
(Defstates ()))");
        const auto [e, count] = agree(s, 0);
        CHECK(count == 3);  // not 3 x 3: the answer is the same for a and b
        REQUIRE(e.chains.size() == 1);
        CHECK(e.chains[0].kinematic_chains == 2);
        CHECK(e.chains[0].branches == 3);
    }
    SUBCASE("three causes compared pairwise on three objects: only the 13 orders of three magnitudes") {
        const Scene s = read_ok(R"((Defscenario 2 triangle
  Individuals (a b c)
  Forces ((a (+ 0) (0 0) x) (a (- 0) (0 0) y) (b (+ 0) (0 0) y) (b (- 0) (0 0) z) (c (+ 0) (0 0) x) (c (- 0) (0 0) z)))
(Defstates ()))");
        const auto [e, count] = agree(s, 0);
        CHECK(e.chains[0].branches == 13);
        CHECK(count == 13);  // each order moves a, b and c its own way (27 without transitivity)
        Readings r;
        r.compare_causes = false;  // the sums left ambiguous: every pair of directions near
        CHECK(Oracle(s, r).solve(s.situations[0], 100000).chains.size() == 3);
    }
    SUBCASE("three causes along one axis: ? stays (no comparison is asked)") {
        const Scene s = read_ok(R"((Defscenario 2 three
  Individuals (a)
  Forces ((a (+ 0) (0 0) hand) (a (+ 0) (0 0) spring) (a (- 0) (0 0) wind)))
(Defstates ()))");
        const auto [e, count] = agree(s, 0);
        CHECK(e.chains[0].branches == 1);
        CHECK(count == 3);
    }
}
