// bench/atms/base_queries.hpp: interpretations on a base environment, the query an envisioner
// makes thousands of times (choice sets {place of each pair} x {motion of each object}
// under nogoods, often on top of the facts of a state). Public ATMS API only, so the same workload
// runs against any version of the library. Shared by atms_bench.
//
// The theory (seeded): `pairs` choice sets of 10 places and `objects` choice sets of 9 motions,
// and 40 situational assumptions outside every set; a nogood for each pair of members of two
// different sets with probability 1/12, for each situational assumption and member with probability
// 1/20, and 100 nogoods of three members of three sets. A query's base holds 1-3 situational
// assumptions and the places of 0-2 pairs; its interpretations are streamed (nothing interned) up
// to a cap.
#pragma once
#include "atms/atms.hpp"
#include <cstdint>
#include <random>
#include <vector>

namespace qm::atms::bench {

struct BaseQueries {
    Atms atms;
    std::vector<std::vector<AssumptionId>> sets;
    std::vector<EnvId> bases;

    BaseQueries(std::uint32_t seed, int pairs, int objects, int queries) {
        std::mt19937 rng(seed);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        std::vector<std::vector<NodeId>> nodes;
        for (int s = 0; s < pairs + objects; ++s) {
            sets.emplace_back();
            nodes.emplace_back();
            for (int m = 0; m < (s < pairs ? 10 : 9); ++m) {
                nodes.back().push_back(atms.add_assumption(DatumId{0}));
                sets.back().push_back(*atms.assumption_of(nodes.back().back()));
            }
        }
        std::vector<NodeId> situational;
        for (int i = 0; i < 40; ++i) situational.push_back(atms.add_assumption(DatumId{1}));
        for (std::size_t s = 0; s < nodes.size(); ++s)
            for (std::size_t t = s + 1; t < nodes.size(); ++t)
                for (NodeId a : nodes[s])
                    for (NodeId b : nodes[t])
                        if (pick(1, 12) == 1) atms.add_nogood(InformantId{0}, {a, b});
        for (NodeId x : situational)
            for (const auto& set : nodes)
                for (NodeId a : set)
                    if (pick(1, 20) == 1) atms.add_nogood(InformantId{0}, {x, a});
        const int count = static_cast<int>(nodes.size());
        for (int i = 0; i < 100; ++i) {
            const int s = pick(0, count - 3), t = pick(s + 1, count - 2), u = pick(t + 1, count - 1);
            auto member = [&](int set) {
                const auto& v = nodes[static_cast<std::size_t>(set)];
                return v[static_cast<std::size_t>(pick(0, static_cast<int>(v.size()) - 1))];
            };
            atms.add_nogood(InformantId{0}, {member(s), member(t), member(u)});
        }
        for (int q = 0; q < queries; ++q) {
            std::vector<AssumptionId> base;
            for (int i = pick(1, 3); i > 0; --i) base.push_back(*atms.assumption_of(situational[static_cast<std::size_t>(pick(0, 39))]));
            for (int i = pick(0, 2); i > 0; --i) {
                const auto& set = sets[static_cast<std::size_t>(pick(0, pairs - 1))];
                base.push_back(set[static_cast<std::size_t>(pick(0, 9))]);
            }
            bases.push_back(atms.environment(base));
        }
    }

    // Streams the interpretations of every query up to `cap` each; returns how many were visited.
    std::size_t run(std::size_t cap) const {
        std::size_t visited = 0;
        for (EnvId base : bases) {
            std::size_t here = 0;
            visited += atms.for_each_interpretation(sets, base, [&](const Environment&) { return ++here < cap; });
        }
        return visited;
    }
};

}  // namespace qm::atms::bench
