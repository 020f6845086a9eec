// tests/atms/environment_table_test.cpp: interning, memoised unions, nogood flags, the index.
#include "atms/environment_table.hpp"

#include <doctest/doctest.h>
#include <random>

using namespace qm::atms;

namespace {
Environment env(std::initializer_list<std::uint32_t> ids) {
    std::vector<AssumptionId> as;
    for (auto i : ids) as.push_back(AssumptionId{i});
    return Environment::of(as);
}
}  // namespace

TEST_CASE("atms/environment_table: equal sets get the same id, different sets different ids") {
    NogoodDatabase nogoods;
    EnvironmentTable t;
    const EnvId a = t.intern(env({1, 2}), nogoods);
    CHECK(t.intern(env({2, 1}), nogoods) == a);
    const EnvId b = t.intern(env({1}), nogoods);
    CHECK(a != b);
    CHECK(t.size() == 2);
    CHECK(t[a] == env({1, 2}));
    CHECK(t.count(a) == 2);
    CHECK(t.subset(b, a));
    CHECK_FALSE(t.subset(a, b));
}

TEST_CASE("atms/environment_table: join is the interned union and is memoised") {
    NogoodDatabase nogoods;
    EnvironmentTable t;
    std::mt19937 rng(3);
    std::vector<EnvId> ids;
    for (int i = 0; i < 50; ++i) {
        std::vector<AssumptionId> as;
        for (int k = 0; k < 3; ++k) as.push_back(AssumptionId{std::uniform_int_distribution<std::uint32_t>(0, 9)(rng)});
        ids.push_back(t.intern(Environment::of(as), nogoods));
    }
    for (EnvId x : ids)
        for (EnvId y : ids) {
            const EnvId u = t.join(x, y, nogoods);
            CHECK(t[u] == join(t[x], t[y]));
            CHECK(t.join(y, x, nogoods) == u);
        }
}

TEST_CASE("atms/environment_table: new environments take their nogood flag from the database") {
    NogoodDatabase nogoods;
    EnvironmentTable t;
    const EnvId ab = t.intern(env({0, 1}), nogoods);
    nogoods.add(ab, t[ab]);
    t.mark_nogood(ab);
    CHECK(t.is_nogood(t.intern(env({0, 1, 5}), nogoods)));
    CHECK_FALSE(t.is_nogood(t.intern(env({0, 5}), nogoods)));
    CHECK(t.is_nogood(t.join(t.intern(env({0}), nogoods), t.intern(env({1}), nogoods), nogoods)));
}

TEST_CASE("atms/environment_table: containing() indexes every env by each of its assumptions") {
    NogoodDatabase nogoods;
    EnvironmentTable t;
    const EnvId a = t.intern(env({0, 3}), nogoods);
    const EnvId b = t.intern(env({3}), nogoods);
    t.intern(env({1}), nogoods);
    CHECK(t.containing(AssumptionId{3}) == std::vector<EnvId>{a, b});
    CHECK(t.containing(AssumptionId{0}) == std::vector<EnvId>{a});
    CHECK(t.containing(AssumptionId{99}).empty());
}

TEST_CASE("atms/environment_table: join of unknown ids is a clear error") {
    NogoodDatabase nogoods;
    EnvironmentTable t;
    const EnvId a = t.intern(env({0}), nogoods);
    CHECK_THROWS_AS((void)t.join(a, EnvId{42}, nogoods), qm::InternalError);
}

TEST_CASE("atms/environment_table: intern_consistent interns like intern, with a clear nogood flag") {
    NogoodDatabase nogoods;
    EnvironmentTable t;
    const EnvId a = t.intern(env({0, 1}), nogoods);
    CHECK(t.intern_consistent(env({1, 0}), nogoods) == a);
    const EnvId b = t.intern_consistent(env({2, 70}), nogoods);
    CHECK(t.intern(env({70, 2}), nogoods) == b);
    CHECK_FALSE(t.is_nogood(b));
    CHECK(t.containing(AssumptionId{70}) == std::vector<EnvId>{b});
}
