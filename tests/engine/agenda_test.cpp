// tests/engine/agenda_test.cpp: engine/agenda.hpp. Against a brute-force model over thousands of
// instances (enough for the seen-key table to grow several times): an instance is queued iff no
// instance with the same rule, binding (bound and unbound slots alike) and context was ever
// queued, by either push; instances come out urgent first, FIFO within each class, with their
// binding, antecedents and context intact; keys that differ only in an unbound slot, in the
// context (none vs 0) or in their length are different.
#include "engine/agenda.hpp"
#include <doctest/doctest.h>
#include <deque>
#include <random>
#include <set>
#include <tuple>

using namespace qm::engine;

namespace {
using ModelKey = std::tuple<std::uint32_t, std::optional<std::uint32_t>, Binding>;

RuleInstance instance(std::uint32_t rule, Binding b, std::optional<std::uint32_t> context, std::vector<FactId> ants = {}) {
    return RuleInstance{RuleId{rule}, std::move(b), std::move(ants), context};
}
}  // namespace

TEST_CASE("a key is queued once: rule, context and every slot, bound or not, count") {
    Agenda a;
    const Binding xy{ValueId{1}, ValueId{2}};
    const Binding x_{ValueId{1}, std::nullopt};
    const Binding x{ValueId{1}};
    CHECK(a.push(instance(0, xy, std::nullopt)));
    CHECK_FALSE(a.push(instance(0, xy, std::nullopt)));
    CHECK(a.push(instance(1, xy, std::nullopt)));       // another rule
    CHECK(a.push(instance(0, xy, 0u)));                 // context 0 is not "no context"
    CHECK_FALSE(a.push(RuleId{0}, xy, {}, 0u));         // the other push sees the same keys
    CHECK(a.push(instance(0, x_, std::nullopt)));       // an unbound slot
    CHECK(a.push(instance(0, x, std::nullopt)));        // a shorter binding
    CHECK(a.push(instance(0, Binding{ValueId{0xffffffffu}, std::nullopt}, std::nullopt)));
    CHECK(a.instances_ever() == 6);
}

TEST_CASE("urgent instances come out first, each class in the order queued, intact") {
    Agenda a;
    const FactId f1{7}, f2{9};
    const FactId ants[] = {f1, f2};
    CHECK(a.push(RuleId{3}, Binding{ValueId{5}}, ants, std::nullopt));
    CHECK(a.push(instance(4, Binding{ValueId{6}}, 2u, {f2}), /*urgent=*/true));
    CHECK(a.push(instance(5, Binding{}, std::nullopt)));
    CHECK(a.push(RuleId{6}, Binding{std::nullopt}, {}, 1u, /*urgent=*/true));
    RuleInstance r = a.pop();
    CHECK(r.rule == RuleId{4});
    CHECK(r.context == 2u);
    CHECK(r.antecedents == std::vector<FactId>{f2});
    CHECK(a.pop().rule == RuleId{6});
    r = a.pop();
    CHECK(r.rule == RuleId{3});
    CHECK(r.binding == Binding{ValueId{5}});
    CHECK(r.antecedents == std::vector<FactId>{f1, f2});
    CHECK_FALSE(r.context);
    CHECK(a.pop().rule == RuleId{5});
    CHECK(a.empty());
}

TEST_CASE("against a model: thousands of instances, many repeats, the table growing several times") {
    std::mt19937 random(16);
    Agenda a;
    std::set<ModelKey> seen;
    std::deque<ModelKey> queue, urgent;
    for (int i = 0; i < 20000; ++i) {
        const std::uint32_t rule = random() % 7;
        const std::optional<std::uint32_t> context = random() % 3 == 0 ? std::optional<std::uint32_t>(random() % 2) : std::nullopt;
        Binding b(random() % 4);
        for (auto& v : b)
            if (random() % 5 != 0) v = ValueId{static_cast<std::uint32_t>(random() % 12)};
        const bool is_urgent = rule == 6;
        const ModelKey key{rule, context, b};
        const bool fresh = seen.insert(key).second;
        if (fresh) (is_urgent ? urgent : queue).push_back(key);
        const bool pushed = i % 2 ? a.push(instance(rule, b, context), is_urgent) : a.push(RuleId{rule}, b, {}, context, is_urgent);
        REQUIRE(pushed == fresh);
        if (random() % 4 == 0 && !a.empty()) {  // pop some as we go
            const RuleInstance r = a.pop();
            auto& from = urgent.empty() ? queue : urgent;
            REQUIRE(ModelKey{r.rule.value, r.context, r.binding} == from.front());
            from.pop_front();
        }
    }
    CHECK(a.instances_ever() == seen.size());
    CHECK(seen.size() > 2000);  // the table grew past its first size several times
    while (!a.empty()) {
        const RuleInstance r = a.pop();
        auto& from = urgent.empty() ? queue : urgent;
        REQUIRE(ModelKey{r.rule.value, r.context, r.binding} == from.front());
        from.pop_front();
    }
    CHECK(queue.empty());
    CHECK(urgent.empty());
}
