// tests/atms/environment_test.cpp: Environment's set operations against std::set on random sets.
#include "atms/environment.hpp"

#include <doctest/doctest.h>
#include <random>
#include <algorithm>
#include <iterator>
#include <set>

using namespace qm::atms;

namespace {
std::set<std::uint32_t> random_id_set(std::mt19937& rng, std::uint32_t universe) {
    std::set<std::uint32_t> s;
    const auto n = std::uniform_int_distribution<std::uint32_t>(0, 6)(rng);
    for (std::uint32_t i = 0; i < n; ++i) s.insert(std::uniform_int_distribution<std::uint32_t>(0, universe - 1)(rng));
    return s;
}
// The set as a raw bitset from word 0.
std::vector<std::uint64_t> dense(const Environment& e) {
    std::vector<std::uint64_t> w(e.end_word(), 0);
    const auto window = e.window();
    std::copy(window.begin(), window.end(), w.begin() + static_cast<std::ptrdiff_t>(e.first_word()));
    return w;
}
Environment of_words(const std::vector<std::uint64_t>& words, std::size_t first = 0) {
    Environment e;
    e.assign_words(words, first);
    return e;
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
        const auto x = random_id_set(rng, universe);
        const auto y = random_id_set(rng, universe);
        const Environment ex = env_of(x), ey = env_of(y);
        CHECK(ex.size() == x.size());
        CHECK((ex == ey) == (x == y));
        CHECK((ex.hash() == ey.hash()) >= (x == y));
        const bool subset = std::includes(y.begin(), y.end(), x.begin(), x.end());
        CHECK(ex.subset_of(ey) == subset);
        CHECK(words_subset(dense(ex), dense(ey)) == subset);
        std::set<std::uint32_t> common;
        std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::inserter(common, common.end()));
        // The stored form: listed non-zero words only, word indices increasing.
        for (std::size_t i = 0; i < ex.words().size(); ++i) {
            CHECK(ex.words()[i] != 0);
            if (i > 0) CHECK(ex.index()[i - 1] < ex.index()[i]);
        }
        CHECK(sparse_subset(ex.sparse(), ey.sparse()) == subset);
        CHECK(sparse_subset(ex.sparse(), dense(ey)) == subset);
        CHECK(sparse_subset(ex.sparse(), ey.window(), ey.first_word()) == subset);
        CHECK(sparse_intersects(ex.sparse(), ey.sparse()) == !common.empty());
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
        std::set<std::uint32_t> v = x;
        v.erase(extra.value);
        Environment in_place = ex;
        in_place.insert(extra);
        CHECK(in_place == env_of(w));
        in_place.erase(extra);
        CHECK(in_place == env_of(v));
        Environment grown;  // inserting in falling order grows the window downwards
        for (auto it = x.rbegin(); it != x.rend(); ++it) grown.insert(AssumptionId{*it});
        CHECK(grown == ex);
        // The stored window is tight: from the lowest to the highest assumption's word.
        if (!x.empty()) {
            CHECK(ex.first_word() == *x.begin() / 64);
            CHECK(ex.end_word() == *x.rbegin() / 64 + 1);
        } else {
            CHECK(ex.first_word() == 0);
            CHECK(ex.words().empty());
        }
        CHECK(of_words(dense(ex)) == ex);
    }
}

TEST_CASE("atms/environment: no zero words at either end, so equal sets compare equal") {
    const Environment high = of_words({0, 0, 5, 0});
    CHECK(high.words().size() == 1);
    CHECK(high.first_word() == 2);
    CHECK(high == Environment::of(std::vector{AssumptionId{128}, AssumptionId{130}}));
    CHECK(Environment{}.first_word() == 0);
    const Environment a = of_words({5, 0, 0});
    CHECK(a.words().size() == 1);
    CHECK(a == Environment::of(std::vector{AssumptionId{0}, AssumptionId{2}}));
    CHECK(of_words({0, 0}) == Environment{});
    // Duplicates collapse.
    CHECK(Environment::of(std::vector{AssumptionId{70}, AssumptionId{70}}).size() == 1);
}

TEST_CASE("atms/environment: windows of words: assign_words with an offset, subsets of shifted windows") {
    std::mt19937 rng(29);
    for (int round = 0; round < 2000; ++round) {
        const auto x = random_id_set(rng, 400);
        const auto y = random_id_set(rng, 400);
        const Environment ex = env_of(x), ey = env_of(y);
        // y's window, padded with zero words on both sides and shifted, rebuilds y.
        const std::size_t pad = static_cast<std::size_t>(round % 3);
        std::vector<std::uint64_t> padded(pad, 0);
        const auto wy = ey.window();
        padded.insert(padded.end(), wy.begin(), wy.end());
        padded.push_back(0);
        const std::size_t at = ey.first_word() >= pad ? ey.first_word() - pad : 0;
        if (ey.first_word() >= pad) {
            CHECK(of_words(padded, at) == ey);
            const bool subset = std::includes(y.begin(), y.end(), x.begin(), x.end());
            CHECK(sparse_subset(ex.sparse(), padded, at) == subset);
        }
    }
    CHECK(of_words({0, 0}, 5) == Environment{});
    CHECK(of_words({0, 4, 0}, 5) == Environment::of(std::vector{AssumptionId{6 * 64 + 2}}));
    // An id far beyond any word yet seen is one word, not thousands.
    CHECK(Environment::of(std::vector{AssumptionId{100000}}).words().size() == 1);
}

namespace {
// y as SparseWords over its non-zero words plus some zero words listed too (weave lists the words
// of every env it involves, so a row may have listed zero words), in increasing order.
struct Sparse {
    std::vector<std::uint64_t> words;
    std::vector<std::uint64_t> index;
    [[nodiscard]] SparseWords view() const { return {words, index}; }
};
Sparse sparse_of(const std::set<std::uint32_t>& s, std::mt19937& rng, std::uint32_t universe) {
    std::set<std::uint32_t> listed;
    for (auto v : s) listed.insert(v / 64);
    const auto extra = std::uniform_int_distribution<std::uint32_t>(0, 3)(rng);
    for (std::uint32_t i = 0; i < extra; ++i) listed.insert(std::uniform_int_distribution<std::uint32_t>(0, universe / 64)(rng));
    Sparse out;
    for (auto w : listed) {
        out.index.push_back(w);
        out.words.push_back(0);
    }
    for (auto v : s) {
        const auto at = std::lower_bound(out.index.begin(), out.index.end(), v / 64) - out.index.begin();
        out.words[static_cast<std::size_t>(at)] |= std::uint64_t{1} << (v % 64);
    }
    return out;
}
}  // namespace

TEST_CASE("atms/environment: SparseWords (listed words only) agree with std::set on random sets") {
    std::mt19937 rng(11);
    for (int round = 0; round < 4000; ++round) {
        const std::uint32_t universe = round % 3 == 0 ? 10 : round % 3 == 1 ? 300 : 5000;
        const auto x = random_id_set(rng, universe);
        const auto y = random_id_set(rng, universe);
        const Environment ex = env_of(x);
        const Sparse sy = sparse_of(y, rng, universe);
        CHECK(Environment::from_sparse(sy.view()) == env_of(y));
        CHECK(sparse_subset(ex.sparse(), sy.view()) == std::includes(y.begin(), y.end(), x.begin(), x.end()));
        std::set<std::uint32_t> common;
        std::set_intersection(x.begin(), x.end(), y.begin(), y.end(), std::inserter(common, common.end()));
        CHECK(sparse_intersects(ex.sparse(), sy.view()) == !common.empty());
    }
    CHECK(Environment::from_sparse({}) == Environment{});
    const std::vector<std::uint64_t> zeros{0, 0};
    const std::vector<std::uint64_t> at{3, 90};
    CHECK(Environment::from_sparse({zeros, at}) == Environment{});
}
