// tests/engine/ground_atom_text_test.cpp: reading ground atoms; printing what was read gives the
// same text back (ValueTable printing is the language's notation).
#include "engine/ground_atom_text.hpp"
#include <doctest/doctest.h>

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
}

TEST_CASE("engine/ground_atom_text: bad text is an error with a column, never an exception") {
    CHECK(round_trip("queen 1 2") == "error at 1: expected '(' to start a fact");
    CHECK(round_trip("(queen 1 2") == "error at 11: expected ')' to end the fact");
    CHECK(round_trip("(queen (1 2))") == "error at 8: expected a direction of signs like (+ 0 -)");
    CHECK(round_trip("(queen 1) x") == "error at 11: unexpected text after the fact");
    CHECK(round_trip("(queen 99999999999999999999)") == "error at 8: integer out of range");
    CHECK(round_trip("(1 2)") == "error at 2: expected a predicate name");
    CHECK(round_trip("(q {1 2") == "error at 8: expected '}'");
    CHECK(round_trip("(p 0x)") == "error at 4: expected a value");  // a symbol starts with a letter
}
