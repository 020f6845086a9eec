// tests/atms/nogood_database_test.cpp: subsumption queries against a brute-force scan.
#include "atms/nogood_database.hpp"
#include "sparse_words.hpp"

#include <algorithm>
#include <doctest/doctest.h>
#include <random>

using namespace qm::atms;
using qm::atms::test::sparse;
using qm::atms::test::without;

namespace {
Environment random_env(std::mt19937& rng, int max_size, std::uint32_t universe) {
    std::vector<AssumptionId> as;
    const int k = std::uniform_int_distribution<int>(1, max_size)(rng);
    for (int i = 0; i < k; ++i) as.push_back(AssumptionId{std::uniform_int_distribution<std::uint32_t>(0, universe - 1)(rng)});
    return Environment::of(as);
}
}  // namespace

TEST_CASE("atms/nogood_database: subsumes, excludes and minimal agree with brute force") {
    std::mt19937 rng(5);
    for (int round = 0; round < 200; ++round) {
        const std::uint32_t universe = round % 2 == 0 ? 8 : 130;
        NogoodDatabase db;
        std::vector<Environment> added;  // every nogood ever added
        for (int i = 0; i < 15; ++i) {
            const Environment n = random_env(rng, 3, universe);
            auto subsumed_by = [&](const Environment& e) {
                return std::any_of(added.begin(), added.end(), [&](const Environment& g) { return g.subset_of(e); });
            };
            REQUIRE(db.subsumes(n) == subsumed_by(n));
            if (db.subsumes(n)) continue;
            db.add(EnvId{static_cast<std::uint32_t>(added.size())}, n);
            added.push_back(n);
            // Live nogoods: exactly the added ones with no proper subset among the added.
            std::vector<EnvId> expected;
            for (std::uint32_t k = 0; k < added.size(); ++k)
                if (std::none_of(added.begin(), added.end(),
                                 [&](const Environment& g) { return !(g == added[k]) && g.subset_of(added[k]); }))
                    expected.push_back(EnvId{k});
            REQUIRE(db.minimal() == expected);
            CHECK(db.size() == expected.size());
            for (int q = 0; q < 10; ++q) {
                const Environment e = random_env(rng, 5, universe);
                CHECK(db.subsumes(e) == subsumed_by(e));
                // The same question on its listed words, zero words listed or not (as weave asks it).
                std::vector<std::uint64_t> sw;
                std::vector<std::uint64_t> si;
                CHECK(db.subsumes_sparse(sparse(e, q % 2 == 0, sw, si)) == subsumed_by(e));
                // Contract of excludes: e minus a is consistent; then it answers subsumes(e).
                const AssumptionId a = e.first();
                if (!subsumed_by(without(e, a))) CHECK(db.excludes(without(e, a), a) == subsumed_by(e));
            }
        }
    }
}

TEST_CASE("atms/nogood_database: the empty nogood makes everything inconsistent") {
    NogoodDatabase db;
    db.add(EnvId{0}, Environment::of(std::vector{AssumptionId{1}}));
    db.add(EnvId{1}, Environment{});
    CHECK(db.empty_env_is_nogood());
    CHECK(db.subsumes(Environment{}));
    CHECK(db.minimal() == std::vector<EnvId>{EnvId{1}});
}

TEST_CASE("atms/nogood_database: adding a subsumed nogood is a clear error") {
    NogoodDatabase db;
    db.add(EnvId{0}, Environment::of(std::vector{AssumptionId{1}}));
    CHECK_THROWS_AS(db.add(EnvId{1}, Environment::of(std::vector{AssumptionId{1}, AssumptionId{2}})),
                    qm::InternalError);
}

TEST_CASE("atms/nogood_database: with at-most-one constraints, every query agrees with brute force") {
    std::mt19937 rng(23);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    for (int round = 0; round < 120; ++round) {
        CAPTURE(round);
        const std::uint32_t universe = round % 3 == 0 ? 10 : round % 3 == 1 ? 130 : 700;
        NogoodDatabase db;
        std::vector<Environment> added;       // stated nogoods, in order (index = EnvId)
        std::vector<Environment> constraints;  // member sets
        auto two_of_one = [&](const Environment& e) {
            return std::any_of(constraints.begin(), constraints.end(), [&](const Environment& c) {
                std::uint32_t n = 0;
                for (AssumptionId a : c.assumptions()) n += e.contains(a) ? 1 : 0;
                return n >= 2;
            });
        };
        auto inconsistent = [&](const Environment& e) {
            return two_of_one(e) ||
                   std::any_of(added.begin(), added.end(), [&](const Environment& g) { return g.subset_of(e); });
        };
        for (int step = 0; step < 20; ++step) {
            if (pick(0, 3) == 0) {
                const Environment members = random_env(rng, 9, universe);
                const auto c = db.add_at_most_one(members.assumptions());
                REQUIRE(c.has_value() == (members.size() >= 2));
                if (c) constraints.push_back(members);
            } else {
                const Environment n = random_env(rng, 3, universe);
                REQUIRE(db.subsumes(n) == inconsistent(n));
                if (db.subsumes(n)) continue;
                db.add(EnvId{static_cast<std::uint32_t>(added.size())}, n);
                added.push_back(n);
            }
            // Live stated nogoods: added ones with no proper subset among the added and not
            // holding two members of one constraint.
            std::vector<EnvId> live;
            for (std::uint32_t k = 0; k < added.size(); ++k)
                if (!two_of_one(added[k]) && std::none_of(added.begin(), added.end(), [&](const Environment& g) {
                        return !(g == added[k]) && g.subset_of(added[k]);
                    }))
                    live.push_back(EnvId{k});
            REQUIRE(db.minimal() == live);
            for (int q = 0; q < 12; ++q) {
                const Environment e = random_env(rng, 6, universe);
                const bool bad = inconsistent(e);
                CHECK(db.subsumes(e) == bad);
                std::vector<EnvId> inside;
                for (EnvId id : live)
                    if (added[id.value].subset_of(e)) inside.push_back(id);
                CHECK(db.within(e) == inside);
                // excludes under its precondition: e minus a consistent.
                for (AssumptionId a : e.assumptions()) {
                    const Environment rest = without(e, a);
                    if (inconsistent(rest)) continue;
                    CHECK(db.excludes(rest, a) == bad);
                }
            }
        }
    }
}
