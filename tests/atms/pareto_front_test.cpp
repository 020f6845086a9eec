// tests/atms/pareto_front_test.cpp: the Pareto front against its definition, on seeded random
// rank vectors: every kept candidate is dominated by none; every dropped one is dominated by a kept
// one (a dominating chain ends in the front, since domination is a strict order).
#include "atms/pareto_front.hpp"
#include "qm/assert.hpp"
#include <doctest/doctest.h>
#include <random>

using qm::atms::pareto_front;

namespace {
bool dominates(const std::vector<int>& x, const std::vector<int>& y) {
    bool strictly = false;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i] > y[i]) return false;
        if (x[i] < y[i]) strictly = true;
    }
    return strictly;
}
}  // namespace

TEST_CASE("atms/pareto_front: small cases") {
    CHECK(pareto_front(std::vector<std::vector<int>>{}).empty());
    const std::vector<std::vector<int>> one{{3, 1}};
    CHECK(pareto_front(one) == std::vector<std::size_t>{0});
    const std::vector<std::vector<int>> chain{{2, 2}, {1, 1}, {0, 3}, {1, 1}};
    CHECK(pareto_front(chain) == std::vector<std::size_t>{1, 2, 3});  // equal vectors both kept
    const std::vector<std::vector<int>> empty_ranks{{}, {}};
    CHECK(pareto_front(empty_ranks) == std::vector<std::size_t>{0, 1});
    const std::vector<std::vector<int>> uneven{{1}, {1, 2}};
    CHECK_THROWS_AS((void)pareto_front(uneven), qm::InternalError);
}

TEST_CASE("atms/pareto_front: agrees with the definition on random rank vectors") {
    std::mt19937 rng(5);
    for (int round = 0; round < 300; ++round) {
        const std::size_t n = std::uniform_int_distribution<std::size_t>(1, 12)(rng);
        const std::size_t k = std::uniform_int_distribution<std::size_t>(0, 4)(rng);
        std::vector<std::vector<int>> ranks(n, std::vector<int>(k));
        for (auto& r : ranks)
            for (int& x : r) x = std::uniform_int_distribution<int>(0, 3)(rng);
        const auto front = pareto_front(ranks);
        std::vector<bool> kept(n, false);
        for (std::size_t i : front) kept[i] = true;
        for (std::size_t i = 0; i < n; ++i) {
            bool dominated = false;
            for (std::size_t j = 0; j < n; ++j) dominated = dominated || dominates(ranks[j], ranks[i]);
            CHECK(kept[i] == !dominated);
        }
        CHECK(!front.empty());
    }
}
