// tests/engine/value_table_test.cpp: engine/value_table.hpp. Interning gives equal values one id;
// after share(), a copy finds the shared values under the same ids and text, adds its own values
// from the shared size on without the original or another copy seeing them, and orders and prints
// shared and own values alike; sharing again keeps every id; remembered applications of the
// shared table are seen by its copies.
#include "engine/value_table.hpp"
#include <doctest/doctest.h>

using namespace qm::engine;

TEST_CASE("interning: equal values, one id") {
    ValueTable v;
    const ValueId a = v.symbol("a"), one = v.integer(1), d = v.direction("+-");
    CHECK(v.symbol("a") == a);
    CHECK(v.integer(1) == one);
    CHECK(v.direction("+-") == d);
    CHECK(v.set({one, a, one}) == v.set({a, one}));
    CHECK(v.print(d) == "(+ -)");
    CHECK(v.size() == 4);
}

TEST_CASE("share: copies keep the shared ids and add their own apart") {
    ValueTable base;
    const ValueId a = base.symbol("a"), two = base.integer(2), s = base.set({a, two});
    base.share();
    CHECK(base.size() == 3);
    CHECK(base.symbol("a") == a);
    CHECK(base.print(s) == "{2 a}");

    ValueTable x = base, y = base;
    const ValueId bx = x.symbol("b");
    const ValueId cy = y.symbol("c");
    CHECK(bx.value == 3);
    CHECK(cy.value == 3);  // each copy numbers its own values from the shared size on
    CHECK(x.print(bx) == "b");
    CHECK(y.print(cy) == "c");
    CHECK(base.size() == 3);
    CHECK(x.symbol("a") == a);        // a shared value is found, not added again
    CHECK(x.integer(2) == two);
    CHECK(x.size() == 4);
    // A set of shared and own values: sorted by the one order, printed through both.
    const ValueId mixed = x.set({bx, two, a});
    CHECK(x.print(mixed) == "{2 a b}");
    CHECK(x.less(two, bx));
    CHECK(x.less(a, bx));
    CHECK_FALSE(x.less(bx, a));
    CHECK(x.value(bx).text == "b");
    CHECK(x.value(a).text == "a");

    // Sharing a copy again keeps every id it gave.
    x.share();
    CHECK(x.symbol("b") == bx);
    CHECK(x.set({a, two, bx}) == mixed);
    ValueTable z = x;
    CHECK(z.print(mixed) == "{2 a b}");
    CHECK(z.symbol("d").value == x.size());
}

TEST_CASE("share: remembered applications are seen by copies, and copies remember their own") {
    ValueTable base;
    const ValueId a = base.symbol("a");
    const ValueId args[] = {a};
    base.remember(1, args, {a, true, ""});
    base.share();
    ValueTable x = base;
    REQUIRE(x.remembered(1, args) != nullptr);
    CHECK(x.remembered(1, args)->value == a);
    CHECK(x.remembered(2, args) == nullptr);
    x.remember(2, args, {std::nullopt, false, "no"});
    REQUIRE(x.remembered(2, args) != nullptr);
    CHECK(x.remembered(2, args)->error == "no");
    CHECK(base.remembered(2, args) == nullptr);
}
