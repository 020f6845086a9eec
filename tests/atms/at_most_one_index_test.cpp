// tests/atms/at_most_one_index_test.cpp: AtMostOneIndex's question against counting members,
// on random constraints (overlapping, of 2 to 40 members) over assumptions spread across many words.
#include "atms/at_most_one_index.hpp"
#include "sparse_words.hpp"

#include <algorithm>
#include <doctest/doctest.h>
#include <random>

using namespace qm::atms;
using qm::atms::test::sparse;
using qm::atms::test::without;

namespace {
Environment random_set(std::mt19937& rng, int max_size, std::uint32_t universe) {
    std::vector<AssumptionId> as;
    const int k = std::uniform_int_distribution<int>(0, max_size)(rng);
    for (int i = 0; i < k; ++i) as.push_back(AssumptionId{std::uniform_int_distribution<std::uint32_t>(0, universe - 1)(rng)});
    return Environment::of(as);
}
std::uint32_t shared(const Environment& x, const Environment& y) {
    std::uint32_t n = 0;
    for (AssumptionId a : x.assumptions()) n += y.contains(a) ? 1 : 0;
    return n;
}
}  // namespace

TEST_CASE("atms/at_most_one_index: other_member agrees with counting members") {
    std::mt19937 rng(31);
    for (int round = 0; round < 300; ++round) {
        CAPTURE(round);
        const std::uint32_t universe = round % 2 == 0 ? 60 : 2000;
        AtMostOneIndex index;
        std::vector<Environment> sets;
        for (int c = std::uniform_int_distribution<int>(0, 6)(rng); c > 0; --c) {
            const Environment s = random_set(rng, 40, universe);
            const auto added = index.add(s.assumptions());
            REQUIRE(added.has_value() == (s.size() >= 2));
            if (!added) continue;
            CHECK(*added == sets.size());
            CHECK(index.members(*added) == s);
            sets.push_back(s);
        }
        CHECK(index.size() == sets.size());
        for (int q = 0; q < 40; ++q) {
            const Environment e = random_set(rng, 12, universe);
            const bool two = std::any_of(sets.begin(), sets.end(), [&](const Environment& s) { return shared(s, e) >= 2; });
            bool found = false;  // two members of one constraint, found from either
            for (AssumptionId a : e.assumptions()) {
                const auto of = index.of(a);
                CHECK(static_cast<std::size_t>(std::count_if(sets.begin(), sets.end(), [&](const Environment& s) { return s.contains(a); })) == of.size());
                const bool other = std::any_of(of.begin(), of.end(), [&](std::uint32_t c) { return shared(sets[c], without(e, a)) >= 1; });
                std::vector<std::uint64_t> sw;
                std::vector<std::uint64_t> si;
                CHECK(index.other_member(a, sparse(e, q % 2 == 0, sw, si)) == other);
                CHECK(index.other_member(a, without(e, a).sparse()) == other);
                found = found || other;
            }
            CHECK(found == two);
        }
    }
}

TEST_CASE("atms/at_most_one_index: a set of fewer than two distinct members is not stored") {
    AtMostOneIndex index;
    CHECK_FALSE(index.add(std::vector<AssumptionId>{}).has_value());
    CHECK_FALSE(index.add(std::vector{AssumptionId{3}, AssumptionId{3}}).has_value());
    CHECK(index.empty());
    CHECK(index.add(std::vector{AssumptionId{3}, AssumptionId{900}}) == 0U);
    CHECK_THROWS((void)index.members(1));
}
