// tests/envision/envision_checker.hpp: an independent envisioner, written from the thesis and the
// readings of docs/LAWS.md ("Clock: ...") WITHOUT the rule files of rules/clock/, to check the
// envisioner's states and transitions on every bundled mechanism:
//   - states by brute force: every place vector times every combination of motions, kept when no
//     pair's place blocks the pair's motion (Law 2 from the normals, Defs 29-30, and the metric
//     diagram's constrained adjacency, 8.1.3), linked parts move alike (Def 21), fixed parts stay,
//     and a force on a part has one sign at the places of all pairs holding it (Def 34);
//   - transitions recomputed: forces by place (8.2.1) passed through contacts along the reverse
//     normal and over shafts to a fixed point, summed per cause with Law 5 then over causes (Def 11);
//     Table 5.1; next places from the adjacency (8.1.3, 8.3.2); the order of Laws 3-4; arrivals and
//     collisions (5.3.3), at stops too; the chain made consistent by nearness (Def 38
//     with 8.3.4's threshold, Pareto over objects).
// Plain C++ over the geometry's values; no engine, no rule.
#pragma once
#include "bridge/place_correlation.hpp"
#include "bridge/place_facts.hpp"
#include "envision/chain.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/qualitative_sign.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <vector>

namespace qm::envision::checker {
namespace g = qm::geometry;

using Motions = std::vector<std::int8_t>;
struct Key {
    std::vector<std::uint32_t> places;
    Motions motions;
    friend auto operator<=>(const Key&, const Key&) = default;
};
struct Edge {
    Key to;
    bool instant = false;
    std::uint8_t causes = 0;  // 1 kinematic, 2 dynamic, 4 collision
    friend auto operator<=>(const Edge&, const Edge&) = default;
};
constexpr std::int8_t ambiguous = 2;

inline bool neg_dot(g::QualDirection n, g::QualDirection v) { return g::qdot(n, v) == g::QualSign::neg; }

class Checker {
public:
    Checker(const g::Mechanism& m, std::span<const bridge::PairPlaces> all, const Chain& chain) : m_(m), chain_(chain) {
        for (const std::size_t k : chain.pairs) {
            pairs_.push_back(&all[k]);
            ends_.emplace_back(chain.object_index(all[k].spec.a), chain.object_index(all[k].spec.b));
            request_.push_back(g::place_request(m, all[k].spec));
        }
        // Def 34: places of two pairs that hold one part's coordinate and cover disjoint values of
        // it (the geometry's comparison of lines and joins, bridge/place_correlation.hpp).
        for (std::size_t i = 0; i < pairs_.size(); ++i)
            for (std::size_t j = i + 1; j < pairs_.size(); ++j) {
                const g::PartId pi[2] = {pairs_[i]->spec.a, pairs_[i]->spec.b}, pj[2] = {pairs_[j]->spec.a, pairs_[j]->spec.b};
                for (int x = 0; x < 2; ++x)
                    for (int y = 0; y < 2; ++y) {
                        if (!m.same_shaft(pi[x], pj[y]) || m.parts[pi[x]].fixed()) continue;
                        for (const auto& [a, b] : bridge::places_apart(pairs_[i]->vocabulary, x, request_[i].cspace.axes[static_cast<std::size_t>(x)],
                                                                       pairs_[j]->vocabulary, y, request_[j].cspace.axes[static_cast<std::size_t>(y)]))
                            apart_.insert({i, a.value, j, b.value});
                    }
            }
    }

    // ---- Law 2 at a place: the normals (Defs 29-30) and the metric diagram (8.1.3) ----
    bool blocked(std::size_t k, std::uint32_t place, g::QualDirection v) const {
        const g::Place& p = pairs_[k]->vocabulary.places[place];
        bool by_normals = false;
        if (p.kind == g::PlaceKind::join && p.concave == false && !p.normals.empty()) {
            by_normals = std::all_of(p.normals.begin(), p.normals.end(), [&](auto n) { return neg_dot(n, v); });
        } else if (p.kind == g::PlaceKind::cseg || p.kind == g::PlaceKind::join || p.kind == g::PlaceKind::stop || p.gap) {
            by_normals = std::any_of(p.normals.begin(), p.normals.end(), [&](auto n) { return neg_dot(n, v); });
        }
        if (by_normals) return true;
        for (const auto& a : pairs_[k]->vocabulary.adjacency)
            if (a.from.value == place && a.motion == v && a.constrained) return true;
        return false;
    }

    g::QualDirection pair_motion(std::size_t k, const Motions& m) const {
        return g::QualDirection{{m[ends_[k].first], m[ends_[k].second]}};
    }

    // ---- states, by brute force over the product ----
    std::set<Key> states() const {
        std::set<Key> out;
        Key key{std::vector<std::uint32_t>(pairs_.size()), Motions(chain_.objects.size())};
        enumerate_places(0, key, out);
        return out;
    }

    bool consistent(const Key& s) const {
        for (std::size_t o = 0; o < chain_.objects.size(); ++o) {
            if (m_.parts[chain_.objects[o]].fixed() && s.motions[o] != 0) return false;
            for (std::size_t q = 0; q < chain_.objects.size(); ++q)
                if (m_.same_shaft(chain_.objects[o], chain_.objects[q]) && s.motions[o] != s.motions[q]) return false;
        }
        for (std::size_t k = 0; k < pairs_.size(); ++k)
            if (blocked(k, s.places[k], pair_motion(k, s.motions))) return false;
        for (std::size_t i = 0; i < pairs_.size(); ++i)
            for (std::size_t j = i + 1; j < pairs_.size(); ++j)
                if (apart_.count({i, s.places[i], j, s.places[j]})) return false;
        // Def 34: a force has one sign where two pairs hold its part.
        std::map<std::pair<std::uint32_t, std::string>, int> sign;
        for (std::size_t k = 0; k < pairs_.size(); ++k)
            for (const auto& f : pairs_[k]->forces.by_place[s.places[k]]) {
                auto [it, fresh] = sign.try_emplace({f.part.value, f.cause}, f.sign);
                if (!fresh && it->second != f.sign) return false;
            }
        return true;
    }

    // ---- forces (8.2.1, 8.3.1, Law 5, Def 11) ----
    std::vector<std::int8_t> net_force(const Key& s) const {
        std::set<std::tuple<std::size_t, int, std::string>> forces;  // object, sign, cause
        auto object_of = [&](g::PartId p) -> std::optional<std::size_t> {
            for (std::size_t o = 0; o < chain_.objects.size(); ++o)
                if (chain_.objects[o] == p) return o;
            return std::nullopt;
        };
        for (const auto& f : bridge::constant_forces(m_))
            if (auto o = object_of(f.part)) forces.insert({*o, f.sign, f.cause});
        for (std::size_t k = 0; k < pairs_.size(); ++k)
            for (const auto& f : pairs_[k]->forces.by_place[s.places[k]])
                if (auto o = object_of(f.part); o && f.sign != 0) forces.insert({*o, f.sign, f.cause});
        for (bool grew = true; grew;) {
            grew = false;
            const auto now = forces;
            for (const auto& [o, sign, cause] : now) {
                for (std::size_t q = 0; q < chain_.objects.size(); ++q)
                    if (q != o && m_.same_shaft(chain_.objects[o], chain_.objects[q])) grew |= forces.insert({q, sign, cause}).second;
                for (std::size_t k = 0; k < pairs_.size(); ++k) {
                    const g::Place& p = pairs_[k]->vocabulary.places[s.places[k]];
                    if (p.normals.empty() || p.kind == g::PlaceKind::stop) continue;  // no force passes to the frame
                    for (int side = 0; side < 2; ++side) {
                        const std::size_t from = side == 0 ? ends_[k].first : ends_[k].second;
                        const std::size_t to = side == 0 ? ends_[k].second : ends_[k].first;
                        if (from != o) continue;
                        g::QualDirection f{};
                        f.s[static_cast<std::size_t>(side)] = static_cast<std::int8_t>(sign);
                        const bool convex = p.kind == g::PlaceKind::join && p.concave == false;
                        const bool all_in = std::all_of(p.normals.begin(), p.normals.end(), [&](auto n) { return neg_dot(n, f); });
                        for (const auto n : p.normals) {
                            if (convex ? !all_in : !neg_dot(n, f)) continue;
                            const int got = n.s[static_cast<std::size_t>(1 - side)];
                            if (got != 0) grew |= forces.insert({to, got, cause}).second;
                        }
                    }
                }
            }
        }
        std::vector<std::int8_t> net(chain_.objects.size(), 0);
        std::map<std::pair<std::size_t, std::string>, std::pair<bool, bool>> per_cause;
        for (const auto& [o, sign, cause] : forces) (sign > 0 ? per_cause[{o, cause}].first : per_cause[{o, cause}].second) = true;
        for (const auto& [oc, signs] : per_cause) {
            const auto [plus, minus] = signs;
            if (plus == minus) continue;  // Law 5: opposite signs of one cause cancel (or none)
            const std::int8_t s = plus ? 1 : -1;
            std::int8_t& n = net[oc.first];
            n = n == 0 ? s : n == s ? s : ambiguous;
        }
        return net;
    }

    // ---- Table 5.1 as docs/LAWS.md reads it: (next, how) with how 0 persist, 1 instant, 2 interval ----
    static std::vector<std::pair<std::int8_t, int>> table_5_1(std::int8_t m, std::int8_t f) {
        if (m == 0) {
            if (f == 0) return {{0, 0}};
            if (f == ambiguous) return {{1, 1}, {-1, 1}, {0, 0}};
            return {{f, 1}};
        }
        if (f == m || f == 0) return {{m, 0}};
        return {{m, 0}, {0, 2}};  // against the force, or ambiguous: may go on, may stop
    }

    // ---- transitions out of s ----
    std::set<Edge> successors(const Key& s, const std::set<Key>& all) const;

private:
    void enumerate_places(std::size_t k, Key& key, std::set<Key>& out) const {
        if (k == pairs_.size()) return enumerate_motions(0, key, out);
        for (std::uint32_t p = 0; p < pairs_[k]->vocabulary.places.size(); ++p) {
            key.places[k] = p;
            enumerate_places(k + 1, key, out);
        }
    }
    void enumerate_motions(std::size_t o, Key& key, std::set<Key>& out) const {
        if (o == key.motions.size()) {
            if (consistent(key)) out.insert(key);
            return;
        }
        for (std::int8_t m = -1; m <= 1; ++m) {
            key.motions[o] = m;
            enumerate_motions(o + 1, key, out);
        }
    }

    const g::Mechanism& m_;
    const Chain& chain_;
    std::vector<const bridge::PairPlaces*> pairs_;
    std::vector<std::pair<std::size_t, std::size_t>> ends_;
    std::vector<g::PlaceRequest> request_;
    std::set<std::tuple<std::size_t, std::uint32_t, std::size_t, std::uint32_t>> apart_;
};

}  // namespace qm::envision::checker

#include "envision_checker-inl.hpp"
