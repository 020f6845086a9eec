// tests/atms/choice_set_groups_test.cpp: group_by_shared_nogoods against brute force on seeded random
// Horn theories (random_theory.hpp): the groups are the connected parts of the relation the header
// defines, computed here from the brute-force oracle's labels and minimal nogoods (not the ATMS's)
// by transitive closure; and index_choice_sets.
#include "atms/choice_set_groups.hpp"

#include "qm/assert.hpp"
#include "random_theory.hpp"
#include <algorithm>
#include <doctest/doctest.h>
#include <random>

using namespace qm::atms;
using qm::atms::test::Oracle;
using qm::atms::test::RandomTheory;
using qm::atms::test::TheoryShape;

namespace {

// The expected groups, from the oracle: members 0..m-1 and sets m.. tied as the header says.
std::vector<ChoiceSetGroup> expected_groups(const Oracle& oracle,
                                            const std::vector<std::uint32_t>& set_masks, std::uint32_t base,
                                            const std::vector<std::vector<NodeId>>& members) {
    const std::size_t m = members.size(), n = m + set_masks.size();
    std::uint32_t in_sets = 0;
    for (std::uint32_t s : set_masks) in_sets |= s;
    // The sets an environment needs beyond base, if all its other assumptions are in sets.
    auto beyond = [&](std::uint32_t env) {
        std::vector<std::size_t> out;
        const std::uint32_t rest = env & ~base;
        if ((rest & ~in_sets) != 0) return out;
        for (std::size_t s = 0; s < set_masks.size(); ++s)
            if (rest & set_masks[s]) out.push_back(s);
        return out;
    };
    std::vector<std::vector<bool>> tied(n, std::vector<bool>(n, false));
    for (std::size_t i = 0; i < n; ++i) tied[i][i] = true;
    for (std::size_t c = 0; c < m; ++c)
        for (NodeId node : members[c])
            for (std::uint32_t l : oracle.label(node))
                for (std::size_t s : beyond(l)) tied[c][m + s] = tied[m + s][c] = true;
    for (std::uint32_t ng : oracle.nogoods()) {
        const auto part = beyond(ng);
        for (std::size_t a : part)
            for (std::size_t b : part) tied[m + a][m + b] = true;
    }
    for (std::size_t k = 0; k < n; ++k)  // transitive closure (Warshall)
        for (std::size_t i = 0; i < n; ++i)
            if (tied[i][k])
                for (std::size_t j = 0; j < n; ++j)
                    if (tied[k][j]) tied[i][j] = true;
    std::vector<ChoiceSetGroup> out;
    std::vector<bool> placed(m, false);
    for (std::size_t c = 0; c < m; ++c) {
        if (placed[c]) continue;
        ChoiceSetGroup g;
        for (std::size_t d = c; d < m; ++d)
            if (tied[c][d]) {
                g.members.push_back(d);
                placed[d] = true;
            }
        for (std::size_t s = 0; s < set_masks.size(); ++s)
            if (tied[c][m + s]) g.sets.push_back(static_cast<std::uint32_t>(s));
        out.push_back(std::move(g));
    }
    return out;
}

}  // namespace

TEST_CASE("atms/choice_set_groups: groups equal the connected parts of the oracle's ties on random theories") {
    std::size_t with_sets = 0, joined = 0;
    for (std::uint32_t seed = 0; seed < 600; ++seed) {
        CAPTURE(seed);
        std::mt19937 rng(seed * 7919U + 3U);
        auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
        TheoryShape shape;
        shape.assumptions = pick(3, 9);
        shape.derived = pick(3, 10);
        shape.clauses = pick(5, 25);
        shape.max_padding = seed % 2 == 0 ? 0 : 40;
        RandomTheory t(seed, shape);
        while (t.add_next()) {
        }
        const Oracle oracle(t);
        // Each tracked assumption goes to the base, to one of the sets, or nowhere.
        std::vector<std::vector<AssumptionId>> sets(static_cast<std::size_t>(pick(0, 4)));
        std::vector<std::uint32_t> set_masks(sets.size(), 0);
        std::uint32_t base = 0;
        for (std::size_t i = 0; i < t.tracked().size(); ++i) {
            const int where = pick(0, 4);
            if (where == 0) base |= 1U << i;
            else if (where > 1 && !sets.empty()) {
                const auto s = static_cast<std::size_t>(pick(0, static_cast<int>(sets.size()) - 1));
                sets[s].push_back(t.tracked()[i]);
                set_masks[s] |= 1U << i;
            }
        }
        // Members: lists of 0-3 nodes of any kind.
        std::vector<NodeId> any = t.derived;
        any.insert(any.end(), t.assumptions.begin(), t.assumptions.end());
        any.insert(any.end(), t.premises.begin(), t.premises.end());
        std::vector<std::vector<NodeId>> members(static_cast<std::size_t>(pick(0, 5)));
        for (auto& nodes : members)
            for (int k = pick(0, 3); k > 0; --k) nodes.push_back(any[static_cast<std::size_t>(pick(0, static_cast<int>(any.size()) - 1))]);
        const ChoiceSetIndex index = index_choice_sets(sets);
        const std::vector<ChoiceSetGroup> got = group_by_shared_nogoods(t.atms, index, t.env_of_mask(base), members);
        const std::vector<ChoiceSetGroup> want = expected_groups(oracle, set_masks, base, members);
        REQUIRE(got.size() == want.size());
        for (std::size_t g = 0; g < got.size(); ++g) {
            CAPTURE(g);
            CHECK(got[g].members == want[g].members);
            CHECK(got[g].sets == want[g].sets);
            if (!got[g].sets.empty()) ++with_sets;
            if (got[g].members.size() > 1 || got[g].sets.size() > 1) ++joined;
        }
    }
    MESSAGE("groups with sets ", with_sets, ", groups of several members or sets ", joined);
    CHECK(with_sets > 100);
    CHECK(joined > 50);
}

TEST_CASE("atms/choice_set_groups: two sets coupled by a nogood join the members they reach") {
    Atms atms;
    auto assume = [&]() { return *atms.assumption_of(atms.add_assumption(DatumId{0})); };
    const AssumptionId b = assume(), x1 = assume(), x2 = assume(), y1 = assume(), y2 = assume(), z1 = assume();
    const NodeId p = atms.add_node(DatumId{1}), q = atms.add_node(DatumId{1}), r = atms.add_node(DatumId{1});
    atms.justify(InformantId{0}, {atms.node_of(b), atms.node_of(x1)}, p);  // p needs set X
    atms.justify(InformantId{0}, {atms.node_of(y2)}, q);                   // q needs set Y
    atms.justify(InformantId{0}, {atms.node_of(b)}, r);                    // r needs only the base
    const ChoiceSetIndex index = index_choice_sets({{x1, x2}, {y1, y2}, {z1}});
    const EnvId base = atms.environment({b});
    const std::vector<std::vector<NodeId>> members{{p}, {q}, {r}};
    auto groups = group_by_shared_nogoods(atms, index, base, members);
    REQUIRE(groups.size() == 3);
    CHECK(groups[0].members == std::vector<std::size_t>{0});
    CHECK(groups[0].sets == std::vector<std::uint32_t>{0});
    CHECK(groups[1].sets == std::vector<std::uint32_t>{1});
    CHECK(groups[2].sets.empty());  // and set Z, tied to nothing, is in no group
    atms.add_nogood(InformantId{0}, {atms.node_of(x2), atms.node_of(y1), atms.node_of(b)});
    groups = group_by_shared_nogoods(atms, index, base, members);
    REQUIRE(groups.size() == 2);
    CHECK(groups[0].members == std::vector<std::size_t>{0, 1});
    CHECK(groups[0].sets == std::vector<std::uint32_t>{0, 1});
    CHECK(groups[1].members == std::vector<std::size_t>{2});
    CHECK(index_choice_sets({}).empty());
    CHECK_THROWS_AS((void)index_choice_sets({{x1, x2}, {x2}}), qm::InternalError);
    CHECK(index.of(y2) == std::optional<std::uint32_t>{1});
    CHECK_FALSE(index.of(b).has_value());
    CHECK_FALSE(index.of(AssumptionId{1000}).has_value());
}
