// tests/engine/ground_atom_text_test.cpp: reading ground atoms with the rule grammar. Printing what
// was read gives the same text back (ValueTable printing is the language's notation), for hand-picked
// atoms and for seeded random atoms over every value kind (including the extreme 64-bit integers);
// bad text is an error with a column, never an exception.
#include "engine/ground_atom_text.hpp"
#include <doctest/doctest.h>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>

using namespace qm::engine;

namespace {
std::string round_trip(const std::string& text) {
    ValueTable v;
    auto p = parse_ground_atom(text, v);
    if (!p.atom) return "error at " + std::to_string(p.column) + ": " + p.error;
    std::string out = "(" + v.print(p.atom->predicate);
    for (auto a : p.atom->args) out += " " + v.print(a);
    return out + ")";
}
}  // namespace

TEST_CASE("engine/ground_atom_text: atoms of every value kind read back as written") {
    CHECK(round_trip("(queen 1 2)") == "(queen 1 2)");
    CHECK(round_trip("  ( queen  -3   2 ) ") == "(queen -3 2)");
    CHECK(round_trip("(trans-motion block (+ 0))") == "(trans-motion block (+ 0))");
    CHECK(round_trip("(m (- ?) (0))") == "(m (- ?) (0))");
    CHECK(round_trip("(s {(0 +) (+ 0) (0 +)})") == "(s {(+ 0) (0 +)})");  // sets are sorted and distinct
    CHECK(round_trip("(flag)") == "(flag)");
    CHECK(round_trip("(p a-b_c.d x0)") == "(p a-b_c.d x0)");
    CHECK(round_trip("(p -9223372036854775808 9223372036854775807)") == "(p -9223372036854775808 9223372036854775807)");
    CHECK(round_trip("(p {} {{1} a})") == round_trip("(p {} {a {1}})"));  // set order is not significant
}

TEST_CASE("engine/ground_atom_text: random ground atoms read back to the same values") {
    std::mt19937_64 rng(88);
    auto pick = [&](int n) { return static_cast<int>(std::uniform_int_distribution<int>(0, n - 1)(rng)); };
    ValueTable v;
    std::function<ValueId(int)> value = [&](int depth) -> ValueId {
        switch (pick(depth > 0 ? 4 : 3)) {
            case 0: return v.symbol(std::string(1, "abcXYZ"[pick(6)]) + std::to_string(pick(100)) + "-x?");
            case 1: {
                const std::int64_t extremes[] = {std::numeric_limits<std::int64_t>::min(),
                                                 std::numeric_limits<std::int64_t>::max(), 0, -1};
                return pick(4) == 0 ? v.integer(extremes[pick(4)]) : v.integer(static_cast<std::int64_t>(rng()));
            }
            case 2: {
                std::string signs;
                for (int i = 0, n = 1 + pick(3); i < n; ++i) signs += "+0-?"[pick(4)];
                return v.direction(signs);
            }
            default: {
                std::vector<ValueId> elements;
                for (int i = 0, n = pick(4); i < n; ++i) elements.push_back(value(depth - 1));
                return v.set(std::move(elements));
            }
        }
    };
    for (int i = 0; i < 500; ++i) {
        ValueId predicate = v.symbol("p" + std::to_string(pick(5)));
        std::vector<ValueId> args;
        std::string text = "(" + v.print(predicate);
        for (int k = 0, n = pick(5); k < n; ++k) {
            args.push_back(value(2));
            text += " " + v.print(args.back());
        }
        text += ")";
        CAPTURE(text);
        auto p = parse_ground_atom(text, v);
        REQUIRE(p.atom.has_value());
        CHECK(p.atom->predicate == predicate);
        CHECK(p.atom->args == args);  // interned: equal values have equal ids
    }
}

TEST_CASE("engine/ground_atom_text: bad text is an error with a column, never an exception") {
    CHECK(round_trip("queen 1 2") == "error at 1: expected an atom like (p ?x) but found 'queen'");
    CHECK(round_trip("(queen 1 2") == "error at 11: expected a term or ')' but found the end of the text");
    CHECK(round_trip("(queen (1 2))") == "error at 9: expected a direction of signs or a builtin function name but found '1'");
    CHECK(round_trip("(queen 1) x") == "error at 11: expected the end of the text but found 'x'");
    CHECK(round_trip("(queen 99999999999999999999)") ==
          "error at 8: expected an integer from -9223372036854775808 to 9223372036854775807 but found "
          "'99999999999999999999'");
    CHECK(round_trip("(1 2)") == "error at 2: expected a predicate name but found '1'");
    CHECK(round_trip("(q {1 2") == "error at 8: expected a term or '}' but found the end of the text");
    CHECK(round_trip("(p 0x)") == "error at 4: expected a term or ')' but found '0x'");  // a symbol starts with a letter
    CHECK(round_trip("(p ?x)") == "error at 4: expected a constant but found the variable ?x (a fact is ground)");
    CHECK(round_trip("(p {a (neg (+))})") == "error at 7: expected a constant but found a call of 'neg' (a fact is ground)");
    CHECK(round_trip("") == "error at 1: expected an atom like (p ?x) but found the end of the text");
    CHECK(round_trip(std::string("(p \xff)")) == "error at 4: expected a term or ')' but found '\\xff'");
}
