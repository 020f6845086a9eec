// tests/scene/kinematic_chains_test.cpp: scene/kinematic_chains.hpp (Definition 22). On seeded
// random graphs the chains are those of a union-find over the links, each in ascending order and
// ordered by their first object; objects in no link are chains of their own; ids out of range are
// refused.
#include "scene/kinematic_chains.hpp"
#include "scene/fwd.hpp"
#include "qm/assert.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <numeric>
#include <random>

using namespace qm;

namespace {

struct UnionFind {
    std::vector<std::uint32_t> up;
    explicit UnionFind(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0u); }
    std::uint32_t find(std::uint32_t x) { return up[x] == x ? x : up[x] = find(up[x]); }
    void join(std::uint32_t a, std::uint32_t b) { up[find(a)] = find(b); }
};

}  // namespace

TEST_CASE("scene/kinematic_chains: two pairs sharing an object are one chain; an object in none is its own") {
    using scene::ObjectId;
    const std::vector<std::pair<ObjectId, ObjectId>> pairs{{ObjectId{3}, ObjectId{1}}, {ObjectId{1}, ObjectId{4}}};
    const auto chains = scene::kinematic_chains(5, pairs);
    CHECK(chains == std::vector<std::vector<ObjectId>>{{ObjectId{0}}, {ObjectId{1}, ObjectId{3}, ObjectId{4}}, {ObjectId{2}}});
    CHECK(scene::kinematic_chains(0, std::vector<std::pair<ObjectId, ObjectId>>{}).empty());
}

TEST_CASE("scene/kinematic_chains: the connected components of random links, in canonical order") {
    std::mt19937 rng(22);
    for (int round = 0; round < 200; ++round) {
        const std::uint32_t n = std::uniform_int_distribution<std::uint32_t>(1, 12)(rng);
        std::vector<std::pair<std::uint32_t, std::uint32_t>> links;
        UnionFind uf(n);
        for (int k = std::uniform_int_distribution<int>(0, 10)(rng); k > 0; --k) {
            const std::uint32_t a = std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng);
            const std::uint32_t b = std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng);
            links.emplace_back(a, b);
            uf.join(a, b);
        }
        CAPTURE(round);
        const auto chains = scene::kinematic_chains(n, links);
        std::vector<int> seen(n, 0);
        for (std::size_t c = 0; c < chains.size(); ++c) {
            REQUIRE(!chains[c].empty());
            CHECK(std::is_sorted(chains[c].begin(), chains[c].end()));
            if (c > 0) CHECK(chains[c - 1].front() < chains[c].front());
            for (const std::uint32_t v : chains[c]) {
                ++seen[v];
                CHECK(uf.find(v) == uf.find(chains[c].front()));
            }
        }
        CHECK(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));  // a partition
        // One chain per component.
        std::vector<std::uint32_t> roots;
        for (std::uint32_t v = 0; v < n; ++v) roots.push_back(uf.find(v));
        std::sort(roots.begin(), roots.end());
        CHECK(chains.size() == static_cast<std::size_t>(std::unique(roots.begin(), roots.end()) - roots.begin()));
    }
}

TEST_CASE("scene/kinematic_chains: Pre: every id is below the count") {
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> links{{0, 3}};
    CHECK_THROWS_AS((void)scene::kinematic_chains(3, links), InternalError);
}
