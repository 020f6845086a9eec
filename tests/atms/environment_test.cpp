// tests/atms/environment_test.cpp: Environment's set operations against std::set on random sets.
#include "atms/environment.hpp"

#include <doctest/doctest.h>
#include <random>
#include <set>

using namespace qm::atms;

namespace {
std::set<std::uint32_t> random_set(std::mt19937& rng, std::uint32_t universe) {
    std::set<std::uint32_t> s;
    const auto n = std::uniform_int_distribution<std::uint32_t>(0, 6)(rng);
    for (std::uint32_t i = 0; i < n; ++i) s.insert(std::uniform_int_distribution<std::uint32_t>(0, universe - 1)(rng));
    return s;
}
Environment env_of(const std::set<std::uint32_t>& s) {
    std::vector<AssumptionId> as;
    for (auto v : s) as.push_back(AssumptionId{v});
    return Environment::of(as);
}
}  // namespace

TEST_CASE("atms/environment: the empty environment") {
    const Environment e;
    CHECK(e.empty());
    CHECK(e.size() == 0);
    CHECK(e.words().empty());
    CHECK(e.subset_of(Environment::of(std::vector{AssumptionId{3}})));
    CHECK_THROWS_AS((void)e.first(), qm::InternalError);
}

TEST_CASE("atms/environment: operations agree with std::set on random sets (several words)") {
    std::mt19937 rng(7);
    for (int round = 0; round < 2000; ++round) {
        const std::uint32_t universe = round % 2 == 0 ? 10 : 200;  // one word, and several
        const auto x = random_set(rng, universe);
        const auto y = random_set(rng, universe);
        const Environment ex = env_of(x), ey = env_of(y);
        CHECK(ex.size() == x.size());
        CHECK((ex == ey) == (x == y));
        CHECK((ex.hash() == ey.hash()) >= (x == y));
        const bool subset = std::includes(y.begin(), y.end(), x.begin(), x.end());
        CHECK(ex.subset_of(ey) == subset);
        CHECK(words_subset(ex.words(), ey.words()) == subset);
        std::set<std::uint32_t> u = x;
        u.insert(y.begin(), y.end());
        CHECK(join(ex, ey) == env_of(u));
        std::vector<AssumptionId> listed = ex.assumptions();
        std::vector<AssumptionId> expected;
        for (auto v : x) expected.push_back(AssumptionId{v});
        CHECK(listed == expected);
        if (!x.empty()) CHECK(ex.first() == AssumptionId{*x.begin()});
        for (std::uint32_t v = 0; v < universe; v += 7) CHECK(ex.contains(AssumptionId{v}) == (x.count(v) == 1));
        const AssumptionId extra{static_cast<std::uint32_t>(round % universe)};
        std::set<std::uint32_t> w = x;
        w.insert(extra.value);
        CHECK(ex.with(extra) == env_of(w));
    }
}

TEST_CASE("atms/environment: no trailing zero words, so equal sets compare equal") {
    std::vector<std::uint64_t> words{5, 0, 0};
    const Environment a = Environment::from_words(words);
    CHECK(a.words().size() == 1);
    CHECK(a == Environment::of(std::vector{AssumptionId{0}, AssumptionId{2}}));
    CHECK(Environment::from_words(std::vector<std::uint64_t>{0, 0}) == Environment{});
    // Duplicates collapse.
    CHECK(Environment::of(std::vector{AssumptionId{70}, AssumptionId{70}}).size() == 1);
}

TEST_CASE("atms/environment: windows of words: from_words with an offset, first_word, windowed subset") {
    std::mt19937 rng(29);
    for (int round = 0; round < 2000; ++round) {
        const auto x = random_set(rng, 400);
        const auto y = random_set(rng, 400);
        const Environment ex = env_of(x), ey = env_of(y);
        CHECK(ex.first_word() == (x.empty() ? 0 : *x.begin() / 64));
        // y as a window starting at its first word rebuilds y.
        const std::size_t first = ey.first_word();
        const auto all = ey.words();
        const std::span<const std::uint64_t> window = all.subspan(std::min(first, all.size()));
        CHECK(Environment::from_words(window, first) == ey);
        const bool subset = std::includes(y.begin(), y.end(), x.begin(), x.end());
        CHECK(words_subset(ex.words(), window, first) == subset);
        // A window with extra zero words on either side answers the same.
        if (first > 0) {
            std::vector<std::uint64_t> wider(all.begin() + static_cast<std::ptrdiff_t>(first - 1), all.end());
            wider.push_back(0);
            CHECK(words_subset(ex.words(), wider, first - 1) == subset);
            CHECK(Environment::from_words(wider, first - 1) == ey);
        }
    }
    CHECK(Environment{}.first_word() == 0);
    CHECK(Environment::from_words(std::vector<std::uint64_t>{0, 0}, 5) == Environment{});
}
