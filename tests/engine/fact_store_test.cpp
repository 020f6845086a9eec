// tests/engine/fact_store_test.cpp: engine/fact_store.hpp. Against a brute-force model over
// thousands of facts (enough for every table to grow several times): equal (predicate, args) give
// one id and only new ones are reported new; find sees exactly the interned facts; the predicate
// and argument lists, all and active, hold exactly the matching facts in creation (resp.
// activation) order; activating twice is refused; facts of other arities and of no arguments
// are kept apart.
#include "engine/fact_store.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <map>
#include <vector>

using namespace qm::engine;

namespace {
std::vector<ValueId> ids(std::initializer_list<std::uint32_t> xs) {
    std::vector<ValueId> out;
    for (auto x : xs) out.push_back(ValueId{x});
    return out;
}
std::vector<FactId> list(std::span<const FactId> s) { return {s.begin(), s.end()}; }
}  // namespace

TEST_CASE("interning gives equal facts one id; find sees exactly the interned facts") {
    FactStore store;
    const auto [a, new_a] = store.intern(ValueId{1}, ids({2, 3}));
    const auto [b, new_b] = store.intern(ValueId{1}, ids({3, 2}));
    const auto [c, new_c] = store.intern(ValueId{1}, ids({2, 3}));
    const auto [d, new_d] = store.intern(ValueId{1}, ids({2}));
    const auto [e, new_e] = store.intern(ValueId{1}, {});
    CHECK(new_a);
    CHECK(new_b);
    CHECK_FALSE(new_c);
    CHECK(new_d);
    CHECK(new_e);
    CHECK(c == a);
    CHECK(a != b);
    CHECK(store.size() == 4);
    CHECK(store.find(ValueId{1}, ids({2, 3})) == a);
    CHECK(store.find(ValueId{1}, {}) == e);
    CHECK_FALSE(store.find(ValueId{1}, ids({2, 3, 4})).has_value());
    CHECK_FALSE(store.find(ValueId{2}, ids({2, 3})).has_value());
    CHECK(store.fact(b).args == ids({3, 2}));
    CHECK(list(store.with_predicate(ValueId{1})) == std::vector<FactId>{a, b, d, e});
    CHECK(list(store.with_argument(ValueId{1}, 0, ValueId{2})) == std::vector<FactId>{a, d});
    CHECK(store.with_argument(ValueId{1}, 2, ValueId{2}).empty());
    CHECK(store.with_predicate(ValueId{9}).empty());
    CHECK(FactStore{}.find(ValueId{1}, {}) == std::nullopt);
}

TEST_CASE("thousands of facts: every list is the model's, in order, through the tables' growth") {
    FactStore store;
    using Key = std::vector<std::uint32_t>;  // predicate, then args
    std::map<Key, FactId> model;
    std::vector<Key> order;  // by id
    std::uint32_t seed = 12345;
    auto next = [&](std::uint32_t n) {
        seed = seed * 1103515245u + 12345u;
        return (seed >> 8) % n;
    };
    for (int i = 0; i < 6000; ++i) {
        const std::uint32_t predicate = 1 + next(7), arity = next(4);
        Key k{predicate};
        for (std::uint32_t j = 0; j < arity; ++j) k.push_back(next(30));
        std::vector<ValueId> args;
        for (std::size_t j = 1; j < k.size(); ++j) args.push_back(ValueId{k[j]});
        const auto [f, fresh] = store.intern(ValueId{predicate}, args);
        const auto it = model.find(k);
        REQUIRE(fresh == (it == model.end()));
        if (fresh) {
            REQUIRE(f.value == order.size());
            model.emplace(k, f);
            order.push_back(k);
        } else {
            REQUIRE(f == it->second);
        }
    }
    REQUIRE(store.size() == order.size());
    REQUIRE(order.size() > 1000);
    // Activate every third fact, in an order other than creation.
    std::vector<FactId> activated;
    for (std::uint32_t i = 0; i < order.size(); ++i) {
        const FactId f{static_cast<std::uint32_t>((i * 7919u) % order.size())};
        if (f.value % 3 != 0) continue;
        CHECK(store.activate(f));
        activated.push_back(f);
    }
    CHECK_FALSE(store.activate(activated.front()));
    for (std::uint32_t f = 0; f < order.size(); ++f) CHECK(store.is_active(FactId{f}) == (f % 3 == 0));
    for (std::uint32_t p = 1; p <= 8; ++p) {
        std::vector<FactId> all, active;
        for (std::uint32_t f = 0; f < order.size(); ++f)
            if (order[f][0] == p) all.push_back(FactId{f});
        for (FactId f : activated)
            if (order[f.value][0] == p) active.push_back(f);
        CHECK(list(store.with_predicate(ValueId{p})) == all);
        CHECK(list(store.active_with_predicate(ValueId{p})) == active);
        for (std::uint32_t position = 0; position < 3; ++position)
            for (std::uint32_t v = 0; v < 30; ++v) {
                auto holds = [&](FactId f) { return order[f.value].size() > position + 1 && order[f.value][position + 1] == v; };
                std::vector<FactId> all_v, active_v;
                std::copy_if(all.begin(), all.end(), std::back_inserter(all_v), holds);
                std::copy_if(active.begin(), active.end(), std::back_inserter(active_v), holds);
                CHECK(list(store.with_argument(ValueId{p}, position, ValueId{v})) == all_v);
                CHECK(list(store.active_with_argument(ValueId{p}, position, ValueId{v})) == active_v);
            }
    }
    for (const auto& [k, f] : model) {
        std::vector<ValueId> args;
        for (std::size_t j = 1; j < k.size(); ++j) args.push_back(ValueId{k[j]});
        CHECK(store.find(ValueId{k[0]}, args) == f);
        CHECK(store.fact(f).predicate == ValueId{k[0]});
        CHECK(store.fact(f).args == args);
    }
}
