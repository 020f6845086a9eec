// tests/atms/preferred_interpretations_test.cpp: the preferred interpretations against their
// definition on seeded random theories (choice sets, random nogoods, a random base, random ranks):
// every interpretation whose ranked picks no other interpretation's ranked picks dominate, found by
// brute force over the product of the sets; and the count of feasible ranked assignments.
#include "atms/preferred_interpretations.hpp"

#include "atms/atms.hpp"
#include <algorithm>
#include <doctest/doctest.h>
#include <random>
#include <set>

using namespace qm::atms;

namespace {

struct RankedTheory {
    Atms atms;
    std::vector<RankedChoiceSet> ranked;
    std::vector<std::vector<AssumptionId>> free;
    std::vector<std::vector<NodeId>> nogoods;
    EnvId base{};
};

void random_ranked_theory(std::uint32_t seed, RankedTheory& t) {
    std::mt19937 rng(seed);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    std::vector<NodeId> nodes;
    auto make_set = [&]() {
        std::vector<AssumptionId> set;
        for (int i = pick(1, 3); i > 0; --i) {
            const NodeId n = t.atms.add_assumption(DatumId{0});
            nodes.push_back(n);
            set.push_back(*t.atms.assumption_of(n));
        }
        return set;
    };
    for (int i = pick(0, 3); i > 0; --i) {
        RankedChoiceSet s{make_set(), {}};
        for (std::size_t k = 0; k < s.members.size(); ++k) s.ranks.push_back(pick(0, 3));
        t.ranked.push_back(std::move(s));
    }
    for (int i = pick(0, 3); i > 0; --i) t.free.push_back(make_set());
    for (int i = nodes.empty() ? 0 : pick(0, 5); i > 0; --i) {
        std::vector<NodeId> ng;
        for (int k = pick(1, 3); k > 0; --k) ng.push_back(nodes[static_cast<std::size_t>(pick(0, static_cast<int>(nodes.size()) - 1))]);
        t.atms.add_nogood(InformantId{0}, ng);
    }
    // A base of at most one assumption, maybe one of a set's members.
    std::vector<AssumptionId> base;
    if (!nodes.empty() && pick(0, 2) == 0) base.push_back(*t.atms.assumption_of(nodes[static_cast<std::size_t>(pick(0, static_cast<int>(nodes.size()) - 1))]));
    t.base = t.atms.environment(base);
}

bool ranks_dominate(const std::vector<std::int64_t>& x, const std::vector<std::int64_t>& y) {
    bool better = false;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i] > y[i]) return false;
        better = better || x[i] < y[i];
    }
    return better;
}

}  // namespace

TEST_CASE("atms/preferred_interpretations: agrees with the definition on random theories") {
    for (std::uint32_t seed = 0; seed < 400; ++seed) {
        RankedTheory t;
        random_ranked_theory(seed, t);
        CAPTURE(seed);
        // Brute force: every interpretation of all the sets, its ranked picks' ranks.
        std::vector<std::vector<AssumptionId>> all;
        for (const RankedChoiceSet& s : t.ranked) all.push_back(s.members);
        for (const auto& s : t.free) all.push_back(s);
        std::vector<std::vector<AssumptionId>> interpretations;
        std::vector<std::vector<std::int64_t>> ranks;
        t.atms.for_each_interpretation(all, t.base, [&](const Environment& e) {
            std::vector<std::int64_t> r;
            for (const RankedChoiceSet& s : t.ranked)
                for (std::size_t k = 0; k < s.members.size(); ++k)
                    if (e.contains(s.members[k])) r.push_back(s.ranks[k]);
            interpretations.push_back(e.assumptions());
            ranks.push_back(std::move(r));
            return true;
        });
        std::set<std::vector<AssumptionId>> expected;
        for (std::size_t i = 0; i < interpretations.size(); ++i) {
            bool dominated = false;
            for (std::size_t j = 0; j < interpretations.size() && !dominated; ++j) dominated = ranks_dominate(ranks[j], ranks[i]);
            if (!dominated) expected.insert(interpretations[i]);
        }
        std::set<std::vector<AssumptionId>> found;
        std::size_t visits = 0;
        const std::size_t count = for_each_preferred_interpretation(t.atms, t.ranked, t.free, t.base, [&](const Environment& e) {
            ++visits;
            found.insert(e.assumptions());
            return true;
        });
        CHECK(found == expected);
        CHECK(visits == expected.size());  // each once
        // Feasible assignments of the ranked sets: the distinct ranked picks of the interpretations.
        std::set<std::vector<AssumptionId>> picks;
        for (const auto& i : interpretations) {
            std::vector<AssumptionId> p;
            for (const RankedChoiceSet& s : t.ranked)
                for (AssumptionId a : s.members)
                    if (std::find(i.begin(), i.end(), a) != i.end()) p.push_back(a);
            picks.insert(p);
        }
        CHECK(count == picks.size());
    }
}

TEST_CASE("atms/preferred_interpretations: a visitor that refuses stops the current pick's completions") {
    Atms atms;
    std::vector<AssumptionId> r, f;
    for (int i = 0; i < 2; ++i) r.push_back(*atms.assumption_of(atms.add_assumption(DatumId{0})));
    for (int i = 0; i < 3; ++i) f.push_back(*atms.assumption_of(atms.add_assumption(DatumId{0})));
    const std::vector<RankedChoiceSet> ranked{{r, {0, 0}}};  // a tie: both picks preferred
    const std::vector<std::vector<AssumptionId>> free{f};
    std::size_t visits = 0;
    const std::size_t count = for_each_preferred_interpretation(atms, ranked, free, atms.environment(std::vector<AssumptionId>{}), [&](const Environment&) {
        ++visits;
        return false;
    });
    CHECK(count == 2);
    CHECK(visits == 2);  // one completion of each preferred pick
}
