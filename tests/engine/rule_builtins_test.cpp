// tests/engine/rule_builtins_test.cpp: the qualitative builtins as a law file uses them, through the
// rule language (parser, compiler, engine), against the thesis' own tables and definitions:
//   - sign-sum and sign-product against Tables 2.2 and 2.3 (Forbus' qualitative arithmetic), as
//     transcribed below, with the `?` row and column of our extension;
//   - half-plane and open-half-plane against Definitions 12 and 13 computed here from the tables,
//     for every pair of 2-D and 3-D translational directions (Definition 1), with section 7.3's
//     reading: a dot product of ambiguous sign (`?`) satisfies neither test;
//   - rotate-90 against Definition 14 / Table 2.1 in 2-D (the quarter-turn matrix of Table 2.4);
//   - the direction sets of Definitions 1 and 4 and the zero tests of Definitions 3 and 6.
// Every table cell is derived by a rule firing, so a wrong entry would show as a wrong fact.
#include "run_rule_text.hpp"
#include <doctest/doctest.h>
#include <map>
#include <memory>
#include <set>

using namespace qm::engine;

namespace {

std::unique_ptr<Engine> run_builtins(const std::string& text) {
    return test::run_rule_text(text, "builtins.rules");
}

// Every fact of predicate, as its argument texts.
std::set<std::vector<std::string>> facts(Engine& e, const std::string& predicate) {
    std::set<std::vector<std::string>> out;
    for (FactId f : e.facts_of(e.values().symbol(predicate))) {
        std::vector<std::string> args;
        for (ValueId v : e.facts().fact(f).args) args.push_back(e.values().print(v));
        out.insert(args);
    }
    return out;
}

const std::string signs = "+0-";

// Tables 2.2 and 2.3 (rows X, columns Y, in the order + 0 -).
const char* const table_2_2[3] = {"++?", "+0-", "?--"};
const char* const table_2_3[3] = {"+0-", "000", "-0+"};

// Pre: x and y are definite signs.
char table(const char* const t[3], char x, char y) {
    const std::size_t i = signs.find(x), j = signs.find(y);
    REQUIRE(i < 3);
    REQUIRE(j < 3);
    return t[i][j];
}
// The `?` extension: ? + 0 = ?, ? + s = ?; ? * 0 = 0, ? * s = ?.
char sum(char x, char y) {
    if (x == '?' || y == '?') return x == '0' ? y : y == '0' ? x : '?';
    return table(table_2_2, x, y);
}
char product(char x, char y) {
    if (x == '0' || y == '0') return '0';
    if (x == '?' || y == '?') return '?';
    return table(table_2_3, x, y);
}
// Definitions 12 and 13 rest on the sign of the dot product, computed with the two tables.
char dot(const std::string& x, const std::string& y) {
    char s = '0';
    for (std::size_t i = 0; i < x.size(); ++i) s = sum(s, product(x[i], y[i]));
    return s;
}
std::string direction(const std::string& s) {
    std::string out = "(";
    for (std::size_t i = 0; i < s.size(); ++i) out += (i ? " " : "") + std::string(1, s[i]);
    return out + ")";
}
std::string signs_of(const std::string& printed) {  // "(+ 0)" -> "+0"
    std::string out;
    for (char c : printed)
        if (c != '(' && c != ')' && c != ' ') out += c;
    return out;
}

}  // namespace

TEST_CASE("engine/rule_builtins: sign-sum and sign-product reproduce Tables 2.2 and 2.3") {
    auto e = run_builtins("fact (sign (+))\nfact (sign (0))\nfact (sign (-))\nfact (sign (?))\n"
                 "rule tables\n  when (sign ?x) (sign ?y)\n"
                 "  then (sum ?x ?y (sign-sum ?x ?y)) (product ?x ?y (sign-product ?x ?y))\n");
    auto sums = facts(*e, "sum");
    auto products = facts(*e, "product");
    CHECK(sums.size() == 16);
    CHECK(products.size() == 16);
    for (char x : std::string("+0-?"))
        for (char y : std::string("+0-?")) {
            CAPTURE(x);
            CAPTURE(y);
            CHECK(sums.count({direction({x}), direction({y}), direction({sum(x, y)})}) == 1);
            CHECK(products.count({direction({x}), direction({y}), direction({product(x, y)})}) == 1);
        }
    // The thesis' cells themselves, spelled out: opposite signs sum to ?, equal signs multiply to +.
    CHECK(sums.count({"(+)", "(-)", "(?)"}) == 1);
    CHECK(sums.count({"(-)", "(0)", "(-)"}) == 1);
    CHECK(products.count({"(-)", "(-)", "(+)"}) == 1);
    CHECK(products.count({"(+)", "(-)", "(-)"}) == 1);
}

TEST_CASE("engine/rule_builtins: half planes follow Definitions 12-13; an ambiguous dot product is false (7.3)") {
    auto e = run_builtins("fact (dimension 2)\nfact (dimension 3)\n"
                 "rule directions\n  when (dimension ?n)\n  then [for all ?d in (translations ?n): (dir ?n ?d)]\n"
                 "rule half-planes\n  when (dir ?n ?x) (dir ?n ?y)\n  then (pair ?x ?y (dot-sign ?x ?y))\n"
                 "rule closed\n  when (dir ?n ?x) (dir ?n ?y) (half-plane ?x ?y)\n  then (hp ?x ?y)\n"
                 "rule open\n  when (dir ?n ?x) (dir ?n ?y) (open-half-plane ?x ?y)\n  then (ohp ?x ?y)\n");
    auto dirs = facts(*e, "dir");
    CHECK(dirs.size() == 9 + 27);  // Definition 1: {+,0,-}^n
    auto pairs = facts(*e, "pair");
    auto hp = facts(*e, "hp");
    auto ohp = facts(*e, "ohp");
    REQUIRE(pairs.size() == 81 + 729);
    std::size_t ambiguous = 0;
    for (const auto& p : pairs) {
        const std::string x = signs_of(p[0]), y = signs_of(p[1]);
        const char d = dot(x, y);
        CAPTURE(p[0]);
        CAPTURE(p[1]);
        CHECK(p[2] == direction({d}));
        CHECK(hp.count({p[0], p[1]}) == (d == '+' || d == '0' ? 1u : 0u));  // Definition 12
        CHECK(ohp.count({p[0], p[1]}) == (d == '+' ? 1u : 0u));              // Definition 13
        ambiguous += d == '?';
    }
    CHECK(ambiguous > 0);  // e.g. (+ -) against (+ +): neither test holds
    CHECK(ohp.count({"(+ -)", "(+ +)"}) == 0);
    CHECK(hp.count({"(+ -)", "(+ +)"}) == 0);
    CHECK(ohp.count({"(+ -)", "(+ 0)"}) == 1);
}

TEST_CASE("engine/rule_builtins: rotate-90 is the quarter turn of Definition 14 and Table 2.4 in 2-D") {
    auto e = run_builtins("fact (dimension 2)\n"
                 "rule directions\n  when (dimension ?n)\n  then [for all ?d in (translations ?n): (dir ?d)]\n"
                 "rule turns\n  when (dir ?x)\n"
                 "  then (turn ?x (+) (rotate-90 ?x (+))) (turn ?x (-) (rotate-90 ?x (-)))\n"
                 "       (back ?x (rotate-90 (rotate-90 ?x (+)) (-)))\n"
                 "       (full ?x (rotate-90 (rotate-90 (rotate-90 (rotate-90 ?x (+)) (+)) (+)) (+)))\n");
    auto turns = facts(*e, "turn");
    REQUIRE(turns.size() == 18);
    for (const auto& t : turns) {
        const std::string x = signs_of(t[0]);
        // Table 2.4 with theta = +-90 degrees: (x, y) -> (-y, x) counter-clockwise, (y, -x) clockwise.
        auto neg = [](char c) { return c == '+' ? '-' : c == '-' ? '+' : c; };
        const std::string expected = t[1] == "(+)" ? std::string{neg(x[1]), x[0]} : std::string{x[1], neg(x[0])};
        CAPTURE(t[0]);
        CAPTURE(t[1]);
        CHECK(signs_of(t[2]) == expected);
        // Perpendicular: a definite dot product of 0 wherever the signs allow one (axis directions).
        if (x.find('0') != std::string::npos) CHECK(dot(x, expected) == '0');
        // Table 2.1 in the plane: positive rotation turns x towards y.
        if (x == "+0" && t[1] == "(+)") CHECK(expected == "0+");
    }
    for (const auto& b : facts(*e, "back")) CHECK(b[0] == b[1]);
    for (const auto& f : facts(*e, "full")) CHECK(f[0] == f[1]);
}

TEST_CASE("engine/rule_builtins: rotate-90 per axis in 3-D follows Table 2.1") {
    // Table 2.1: a positive rotation about x turns y to z, about y turns z to x, about z turns x to y.
    auto e = run_builtins("fact (v (+ 0 0) (0 0 +))\nfact (v (0 + 0) (+ 0 0))\nfact (v (0 0 +) (0 + 0))\n"
                 "rule turn\n  when (v ?x ?r)\n  then (turned ?x ?r (rotate-90 ?x ?r))\n");
    auto turned = facts(*e, "turned");
    CHECK(turned.count({"(+ 0 0)", "(0 0 +)", "(0 + 0)"}) == 1);
    CHECK(turned.count({"(0 + 0)", "(+ 0 0)", "(0 0 +)"}) == 1);
    CHECK(turned.count({"(0 0 +)", "(0 + 0)", "(+ 0 0)"}) == 1);
}

TEST_CASE("engine/rule_builtins: direction sets (Definitions 1, 4) and zero tests (Definitions 3, 6)") {
    auto e = run_builtins("fact (dimension 2)\nfact (dimension 3)\n"
                 "rule sets\n  when (dimension ?n)\n"
                 "  then [for all ?t in (translations ?n) where (zero? ?t): (zero-t ?n ?t)]\n"
                 "       [for all ?r in (rotations ?n): (rot ?n ?r)]\n"
                 "       [for all ?t in (translations ?n) where (nonzero? ?t): (moving ?n ?t)]\n"
                 "       (zeros ?n (zero-translation ?n) (zero-rotation ?n))\n");
    CHECK(facts(*e, "zero-t") == std::set<std::vector<std::string>>{{"2", "(0 0)"}, {"3", "(0 0 0)"}});
    CHECK(facts(*e, "zeros") ==
          std::set<std::vector<std::string>>{{"2", "(0 0)", "(0)"}, {"3", "(0 0 0)", "(0 0 0)"}});
    std::map<std::string, int> rotations, moving;
    for (const auto& r : facts(*e, "rot")) ++rotations[r[0]];
    for (const auto& m : facts(*e, "moving")) ++moving[m[0]];
    CHECK(rotations["2"] == 3);  // in the plane a rotation is a 1-tuple (Definition 4, section 2.1.2)
    CHECK(rotations["3"] == 27);
    CHECK(moving["2"] == 8);
    CHECK(moving["3"] == 26);
}
