// tests/envision/chain_test.cpp: kinematic chains (envision/chain.hpp, thesis 8.1.4, Def 22)
// against a union-find over the parts joined by pairs and shafts, on the bundled mechanisms and on
// seeded random mechanisms (parts, random pairs and shafts); and the order of pairs along a chain.
#include "envision/chain.hpp"
#include "envision_fixture.hpp"

#include <numeric>
#include <random>
#include <set>

using namespace qm;
using namespace qm::envision;
using namespace qm::envision::testing;
namespace g = qm::geometry;

namespace {

struct UnionFind {
    std::vector<std::size_t> up;
    explicit UnionFind(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0); }
    std::size_t find(std::size_t x) { return up[x] == x ? x : up[x] = find(up[x]); }
    void join(std::size_t a, std::size_t b) { up[find(a)] = find(b); }
};

void check_chains(const g::Mechanism& m, const std::vector<bridge::PairPlaces>& pairs) {
    const auto chains = kinematic_chains(m, pairs);
    UnionFind uf(m.parts.size());
    for (const auto& p : pairs) uf.join(p.spec.a.value, p.spec.b.value);
    for (const auto& l : m.linkages)
        for (const auto part : l.parts) uf.join(l.parts.front().value, part.value);
    // Every pair in exactly one chain; two pairs share a chain iff their parts are joined.
    std::vector<int> chain_of(pairs.size(), -1);
    for (std::size_t c = 0; c < chains.size(); ++c) {
        CHECK(chains[c].index == c);
        CHECK(!chains[c].pairs.empty());
        for (const auto k : chains[c].pairs) {
            CHECK(chain_of[k] == -1);
            chain_of[k] = static_cast<int>(c);
        }
        // Objects: exactly the parts of the component that are in a pair or on a shaft with one.
        std::set<std::uint32_t> expected;
        for (std::size_t k = 0; k < pairs.size(); ++k)
            if (uf.find(pairs[k].spec.a.value) == uf.find(pairs[chains[c].pairs.front()].spec.a.value))
                for (std::uint32_t q = 0; q < m.parts.size(); ++q)
                    if (m.same_shaft(g::PartId{q}, pairs[k].spec.a) || m.same_shaft(g::PartId{q}, pairs[k].spec.b)) expected.insert(q);
        std::set<std::uint32_t> got;
        for (const auto o : chains[c].objects) got.insert(o.value);
        CHECK(got == expected);
        CHECK(got.size() == chains[c].objects.size());
        // 8.2.3: each pair after the first shares a part or a shaft with an earlier one.
        for (std::size_t i = 1; i < chains[c].pairs.size(); ++i) {
            const auto& y = pairs[chains[c].pairs[i]].spec;
            bool linked = false;
            for (std::size_t j = 0; j < i; ++j) {
                const auto& x = pairs[chains[c].pairs[j]].spec;
                linked = linked || m.same_shaft(x.a, y.a) || m.same_shaft(x.a, y.b) || m.same_shaft(x.b, y.a) || m.same_shaft(x.b, y.b);
            }
            CHECK(linked);
        }
    }
    for (std::size_t a = 0; a < pairs.size(); ++a) {
        REQUIRE(chain_of[a] >= 0);
        for (std::size_t b = 0; b < pairs.size(); ++b)
            CHECK((chain_of[a] == chain_of[b]) == (uf.find(pairs[a].spec.a.value) == uf.find(pairs[b].spec.a.value)));
    }
}

}  // namespace

TEST_CASE("envision/chain: the bundled mechanisms' chains are the components of pairs and shafts") {
    for (const auto& file : bundled()) {
        CAPTURE(file);
        const auto m = mechanism(file);
        check_chains(m, pairs_of(m));
    }
    const auto two = mechanism("tests/envision/scenes/two_chains.def");
    CHECK(kinematic_chains(two, pairs_of(two)).size() == 2);
    const auto train = mechanism("scenarios/metric/gear_train.def");
    const auto chains = kinematic_chains(train, pairs_of(train));
    REQUIRE(chains.size() == 1);  // gear-2 and pinion-2 share a shaft: one chain
    CHECK(chains[0].objects.size() == 4);
}

TEST_CASE("envision/chain: random mechanisms' chains agree with a union-find") {
    std::mt19937 rng(7);
    for (int round = 0; round < 200; ++round) {
        g::Mechanism m;
        const std::uint32_t n = std::uniform_int_distribution<std::uint32_t>(2, 12)(rng);
        for (std::uint32_t i = 0; i < n; ++i) {
            g::Part part;
            part.name = "p" + std::to_string(i);
            m.parts.push_back(part);
            m.part_where.push_back({});
        }
        // Shafts: disjoint groups of parts.
        std::vector<bool> on_shaft(n, false);
        for (int s = std::uniform_int_distribution<int>(0, 3)(rng); s > 0; --s) {
            g::Linkage l;
            for (std::uint32_t i = 0; i < n; ++i)
                if (!on_shaft[i] && std::uniform_int_distribution<int>(0, 3)(rng) == 0) l.parts.push_back(g::PartId{i});
            if (l.parts.size() < 2) continue;
            for (const auto p : l.parts) on_shaft[p.value] = true;
            m.linkages.push_back(l);
        }
        std::vector<bridge::PairPlaces> pairs;
        for (int k = std::uniform_int_distribution<int>(1, 10)(rng); k > 0; --k) {
            const std::uint32_t a = std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng);
            const std::uint32_t b = std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng);
            if (m.same_shaft(g::PartId{a}, g::PartId{b})) continue;
            bridge::PairPlaces p;
            p.spec.a = g::PartId{a};
            p.spec.b = g::PartId{b};
            pairs.push_back(p);
        }
        if (pairs.empty()) continue;
        CAPTURE(round);
        check_chains(m, pairs);
    }
}
