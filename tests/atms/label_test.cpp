// tests/atms/label_test.cpp: minimal-label maintenance against a brute-force minimal filter.
#include "atms/label.hpp"

#include <algorithm>
#include <doctest/doctest.h>
#include <random>

using namespace qm::atms;

TEST_CASE("atms/label: adding envs keeps the label equal to the minimal elements added so far") {
    std::mt19937 rng(11);
    for (int round = 0; round < 300; ++round) {
        NogoodDatabase nogoods;
        EnvironmentTable t;
        Label label;
        std::vector<EnvId> all;
        for (int i = 0; i < 12; ++i) {
            std::vector<AssumptionId> as;
            const int k = std::uniform_int_distribution<int>(0, 3)(rng);
            for (int j = 0; j < k; ++j) as.push_back(AssumptionId{std::uniform_int_distribution<std::uint32_t>(0, 5)(rng)});
            const EnvId e = t.intern(Environment::of(as), nogoods);
            const bool subsumed = label_subsumes(label, e, t);
            CHECK(label_add_minimal(label, e, t) == !subsumed);
            all.push_back(e);
            REQUIRE(label_is_minimal(label, t));
            std::vector<EnvId> expected;
            for (EnvId x : all)
                if (std::none_of(all.begin(), all.end(), [&](EnvId y) { return y != x && t.subset(y, x); }))
                    expected.push_back(x);
            std::sort(expected.begin(), expected.end());
            expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
            REQUIRE(label == expected);
        }
    }
}

TEST_CASE("atms/label: label_is_minimal rejects unsorted and non-minimal labels") {
    NogoodDatabase nogoods;
    EnvironmentTable t;
    const EnvId a = t.intern(Environment::of(std::vector{AssumptionId{0}}), nogoods);
    const EnvId ab = t.intern(Environment::of(std::vector{AssumptionId{0}, AssumptionId{1}}), nogoods);
    const EnvId c = t.intern(Environment::of(std::vector{AssumptionId{2}}), nogoods);
    CHECK(label_is_minimal({a, c}, t));
    CHECK_FALSE(label_is_minimal({c, a}, t));
    CHECK_FALSE(label_is_minimal({a, ab}, t));
    CHECK_FALSE(label_is_minimal({a, a}, t));
}
