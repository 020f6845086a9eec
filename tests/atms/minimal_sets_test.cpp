// tests/atms/minimal_sets_test.cpp: the scratch bitset pool and the minimal-elements filter behind
// weave (atms/detail/minimal_sets.hpp), against a brute-force filter over std::set on random pools
// with duplicates, the empty set, and rows several words wide.
#include "atms/detail/minimal_sets.hpp"

#include <algorithm>
#include <doctest/doctest.h>
#include <random>
#include <set>

using namespace qm::atms::detail;

namespace {
using Set = std::set<std::uint32_t>;

std::vector<std::uint64_t> words_of(const Set& s, std::size_t width) {
    std::vector<std::uint64_t> w(width, 0);
    for (auto b : s) w[b / 64] |= std::uint64_t{1} << (b % 64);
    return w;
}

Set set_of(std::span<const std::uint64_t> row) {
    Set s;
    for (std::size_t i = 0; i < row.size() * 64; ++i)
        if ((row[i / 64] >> (i % 64)) & 1U) s.insert(static_cast<std::uint32_t>(i));
    return s;
}
}  // namespace

TEST_CASE("atms/minimal_sets: BitsetPool rows are zero padded copies; pop and clear") {
    BitsetPool pool(3);
    const std::uint64_t one[] = {5};
    std::uint64_t* r = pool.push(one);
    CHECK(pool.size() == 1);
    CHECK(std::vector<std::uint64_t>(pool[0].begin(), pool[0].end()) == std::vector<std::uint64_t>{5, 0, 0});
    r[2] = 9;  // the returned row is the pool's own storage
    CHECK(pool[0][2] == 9);
    const std::uint64_t three[] = {1, 2, 3};
    pool.push(three);
    CHECK(pool[1][2] == 3);
    pool.pop();
    CHECK(pool.size() == 1);
    CHECK(pool[0][0] == 5);
    pool.clear();
    CHECK(pool.size() == 0);
    BitsetPool empty_rows(0);  // only empty sets: rows of no words still count
    empty_rows.push({});
    empty_rows.push({});
    CHECK(empty_rows.size() == 2);
}

TEST_CASE("atms/minimal_sets: keep_minimal equals the brute-force minimal elements, in size order") {
    std::mt19937 rng(23);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    MinimalFilter filter;  // reused across rounds, as weave does
    for (int round = 0; round < 3000; ++round) {
        CAPTURE(round);
        const std::size_t width = static_cast<std::size_t>(pick(1, 3));
        const int universe = round % 3 == 0 ? 6 : static_cast<int>(width) * 64;
        std::vector<Set> sets;
        BitsetPool in(width), out(width);
        for (int i = pick(0, 40); i > 0; --i) {
            Set s;
            // Small sets over a small universe give many duplicates and inclusions; rarely {}.
            for (int k = pick(round % 17 == 0 ? 0 : 1, 4); k > 0; --k) s.insert(static_cast<std::uint32_t>(pick(0, universe - 1)));
            sets.push_back(s);
            in.push(words_of(s, width));
        }
        filter.keep_minimal(in, out);
        std::set<Set> expected;
        for (const Set& s : sets)
            if (std::none_of(sets.begin(), sets.end(), [&](const Set& o) {
                    return o != s && std::includes(s.begin(), s.end(), o.begin(), o.end());
                }))
                expected.insert(s);
        std::set<Set> got;
        std::size_t previous_size = 0;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const Set s = set_of(out[i]);
            CHECK(s.size() >= previous_size);  // increasing size
            previous_size = s.size();
            CHECK(got.insert(s).second);       // no duplicates
        }
        REQUIRE(got == expected);
    }
}
