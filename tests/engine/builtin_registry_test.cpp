// tests/engine/builtin_registry_test.cpp: the registry's contract and the comparison and integer
// builtins, checked against C++ arithmetic on seeded random integers.
#include "engine/builtin_registry.hpp"
#include <doctest/doctest.h>
#include <random>

using namespace qm::engine;

namespace {
BuiltinResult apply_registered(ValueTable& v, const char* name, std::vector<ValueId> args) {
    const auto& b = default_builtins();
    auto id = b.find(name);
    REQUIRE(id.has_value());
    return b.apply(*id, v, args);
}
}  // namespace

TEST_CASE("engine/builtin_registry: names are unique and arity is a precondition") {
    BuiltinRegistry r;
    auto fn = [](ValueTable&, std::span<const ValueId>) { return BuiltinResult::truth(true); };
    BuiltinId t = r.add("t", BuiltinKind::test, 1, 2, fn);
    CHECK(r.find("t") == t);
    CHECK(!r.find("u").has_value());
    CHECK_THROWS_AS(r.add("t", BuiltinKind::test, 1, 1, fn), qm::InternalError);
    CHECK_THROWS_AS(r.add("bad", BuiltinKind::test, 2, 1, fn), qm::InternalError);
    ValueTable v;
    CHECK_THROWS_AS((void)r.apply(t, v, {}), qm::InternalError);
    CHECK(r.apply(t, v, std::vector<ValueId>{v.integer(1)}).holds);
}

TEST_CASE("engine/builtin_registry: integer arithmetic and comparisons agree with C++ on random integers") {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> d(-50, 50);
    ValueTable v;
    for (int i = 0; i < 500; ++i) {
        int x = d(rng), y = d(rng);
        ValueId a = v.integer(x), b = v.integer(y);
        CHECK(apply_registered(v, "+", {a, b}).value == v.integer(x + y));
        CHECK(apply_registered(v, "-", {a, b}).value == v.integer(x - y));
        CHECK(apply_registered(v, "-", {a}).value == v.integer(-x));
        CHECK(apply_registered(v, "*", {a, b}).value == v.integer(x * y));
        CHECK(apply_registered(v, "abs", {a}).value == v.integer(x < 0 ? -x : x));
        CHECK(apply_registered(v, "min", {a, b}).value == v.integer(std::min(x, y)));
        CHECK(apply_registered(v, "max", {a, b}).value == v.integer(std::max(x, y)));
        CHECK(apply_registered(v, "<", {a, b}).holds == (x < y));
        CHECK(apply_registered(v, "<=", {a, b}).holds == (x <= y));
        CHECK(apply_registered(v, ">", {a, b}).holds == (x > y));
        CHECK(apply_registered(v, ">=", {a, b}).holds == (x >= y));
        CHECK(apply_registered(v, "=", {a, b}).holds == (x == y));
        CHECK(apply_registered(v, "!=", {a, b}).holds == (x != y));
    }
}

TEST_CASE("engine/builtin_registry: range generates a set; errors are reported, not thrown") {
    ValueTable v;
    auto r = apply_registered(v, "range", {v.integer(1), v.integer(4)});
    REQUIRE(r.value.has_value());
    CHECK(v.print(*r.value) == "{1 2 3 4}");
    CHECK(v.print(*apply_registered(v, "range", {v.integer(3), v.integer(1)}).value) == "{}");
    CHECK(!apply_registered(v, "range", {v.integer(0), v.integer(1000000)}).error.empty());
    CHECK(!apply_registered(v, "+", {v.symbol("a"), v.integer(1)}).error.empty());
    CHECK(!apply_registered(v, "*", {v.integer(INT64_MAX), v.integer(2)}).error.empty());
    CHECK(!apply_registered(v, "abs", {v.integer(INT64_MIN)}).error.empty());
    // Comparison of different kinds follows the table's total order: integers before symbols.
    CHECK(apply_registered(v, "<", {v.integer(9), v.symbol("a")}).holds);
}

TEST_CASE("engine/builtin_registry: range is exact at both ends of the 64-bit integers, and capped") {
    ValueTable v;
    // Stepping up to INT64_MAX must not overflow ++i (undefined; in practice an endless loop).
    auto top = apply_registered(v, "range", {v.integer(INT64_MAX - 2), v.integer(INT64_MAX)});
    REQUIRE(top.value.has_value());
    CHECK(v.print(*top.value) == "{9223372036854775805 9223372036854775806 9223372036854775807}");
    auto one = apply_registered(v, "range", {v.integer(INT64_MAX), v.integer(INT64_MAX)});
    REQUIRE(one.value.has_value());
    CHECK(v.value(*one.value).elements.size() == 1);
    auto bottom = apply_registered(v, "range", {v.integer(INT64_MIN), v.integer(INT64_MIN + 1)});
    REQUIRE(bottom.value.has_value());
    CHECK(v.value(*bottom.value).elements.size() == 2);
    // hi - lo does not fit in 64 bits: refused, not wrapped.
    CHECK(apply_registered(v, "range", {v.integer(INT64_MIN), v.integer(INT64_MAX)}).error ==
          "'range' would have more than 100000 elements");
    CHECK(!apply_registered(v, "range", {v.integer(-1), v.integer(INT64_MAX)}).error.empty());
    CHECK(v.print(*apply_registered(v, "range", {v.integer(INT64_MAX), v.integer(INT64_MIN)}).value) == "{}");
    // The cap is exact: 100000 elements are fine, 100001 are not.
    auto cap = apply_registered(v, "range", {v.integer(INT64_MAX - 99999), v.integer(INT64_MAX)});
    REQUIRE(cap.value.has_value());
    CHECK(v.value(*cap.value).elements.size() == 100000);
    CHECK(!apply_registered(v, "range", {v.integer(INT64_MAX - 100000), v.integer(INT64_MAX)}).error.empty());
}

TEST_CASE("engine/builtin_registry: a result longer than max_value_text is an error, not a runaway") {
    // (set-add ?s ?s) doubles the printed text at each application (a rule doing so would fill
    // the memory).
    ValueTable v;
    auto start = apply_registered(v, "range", {v.integer(1), v.integer(1000)});
    REQUIRE(start.value.has_value());
    ValueId s = *start.value;
    std::string error;
    int doublings = 0;
    for (; doublings < 40; ++doublings) {
        const std::size_t before = v.print(s).size();
        auto r = apply_registered(v, "set-add", {s, s});
        if (!r.error.empty()) {
            error = r.error;
            // Refused only when the result would indeed have been too long (it holds s whole).
            CHECK(before + 2 > BuiltinRegistry::max_value_text / 2);
            break;
        }
        REQUIRE(r.value.has_value());
        CHECK(v.print(*r.value).size() <= BuiltinRegistry::max_value_text);
        CHECK(v.print(*r.value).size() > before);
        s = *r.value;
    }
    CHECK(doublings < 40);
    CHECK(error.rfind("'set-add' would make a value of ", 0) == 0);
    CHECK(error.find("characters, more than the " + std::to_string(BuiltinRegistry::max_value_text) +
                     " a value may have") != std::string::npos);
}
