// tests/engine/rule_parser_test.cpp: the Spirit X3 parser of the rule language (engine/rule_parser.hpp)
// through the reader: every form of docs/RULES.md parses to the documented spec (printed back with
// the printer) at the documented locations; the layout rule (top-level keywords in column 1); every
// syntax error names what was expected and what was found, with its source line; the nesting limit;
// and, on seeded random programs with one corrupted item, recovery: every other item is read
// unchanged.
#include "engine/rule_parser.hpp"
#include "engine/rule_printer.hpp"
#include "engine/rule_spec_reader.hpp"
#include <doctest/doctest.h>
#include <random>
#include <sstream>

using namespace qm::engine;

namespace {

ProgramSpec read(const std::string& text, qm::Diagnostics& d) {
    ProgramSpec spec;
    read_rule_text(text, "t.rules", spec, d);
    return spec;
}

std::string messages(const qm::Diagnostics& d) {
    std::ostringstream out;
    d.print(out);
    return out.str();
}

// Reads text that must be valid and prints it back.
std::string normal_form(const std::string& text) {
    qm::Diagnostics d;
    ProgramSpec spec = read(text, d);
    CAPTURE(messages(d));
    CHECK(!d.has_errors());
    return print_program(spec);
}

// The first diagnostic as "line:col: message".
std::string first_error(const std::string& text) {
    qm::Diagnostics d;
    (void)read(text, d);
    if (!d.has_errors()) return "no error";
    const auto e = d.sorted().front();
    return std::to_string(e.where.line) + ":" + std::to_string(e.where.column) + ": " + e.message;
}

std::string at(const qm::SourceLocation& w) { return std::to_string(w.line) + ":" + std::to_string(w.column); }

// Valid items of every kind, each starting in column 1 and ending with a newline.
const char* const items[] = {
    "fact (p a -3 (+ 0 -) {x (0) 7} b2)\n",
    "fact (edge a b)\n",
    "assume (mode m1 ok)\n",
    "assume (open b)\n",
    "rule r1\n  when (p ?x) (< ?x 3) not (q ?x)\n  then (s ?x)\n",
    "rule r2\n  when (edge ?x ?y) [for all ?d in (translations 2) where (open-half-plane ?d (+ 0)): (t ?x ?d)]\n"
    "  then [exactly one ?s in {ok faulty}: assume (mode ?x ?s)]\n",
    "rule r3   # a comment\n  when [exists ?e in {a b}: (u ?e) and (w ?e)]\n       [sum ?v over (val ?v) with + start 0 as ?t]\n"
    "  then (total ?t) false\n",
    "rule r4\n  when (p ?x)\n  then assume (a ?x) [for all ?k in (range 1 3) where (> ?k 1): (k ?x ?k)]\n",
    "rule r5 when (p ?x) (= ?y (neg (- 0))) then (q ?x ?y)\n",
};

}  // namespace

TEST_CASE("engine/rule_parser: every form of the language reads to its documented spec") {
    CHECK(normal_form("fact (p a -3 (+ 0 -) {x (0) 7} b2)") == "fact (p a -3 (+ 0 -) {x (0) 7} b2)\n");
    CHECK(normal_form("assume (m x)\n") == "assume (m x)\n");
    CHECK(normal_form("rule r\n"
                      "  when (p ?x) (< ?x 3) not (q ?x)\n"
                      "       [for all ?d in (translations 2) where (open-half-plane ?d (+ 0)) (nonzero? ?d): (s ?d) (t ?d)]\n"
                      "       [exists ?e in {a b}: (u ?e) and (w ?e)] [sum ?v over (val ?x ?v) with + start 0 as ?t]\n"
                      "  then (out ?x ?t) false assume (a ?x)\n"
                      "       [for all ?k in (range 1 3) where (> ?k 1): (k ?x ?k)]\n"
                      "       [exactly one ?s in {ok faulty}: assume (mode ?x ?s)]\n") ==
          "\nrule r\n  when (p ?x) (< ?x 3) not (q ?x) [for all ?d in (translations 2) where (open-half-plane ?d (+ 0)) "
          "and (nonzero? ?d): (s ?d) and (t ?d)] [exists ?e in {a b}: (u ?e) and (w ?e)] "
          "[sum ?v over (val ?x ?v) with + start 0 as ?t]\n"
          "  then (out ?x ?t) false assume (a ?x) [for all ?k in (range 1 3) where (> ?k 1): (k ?x ?k)] "
          "[exactly one ?s in {ok faulty}: assume (mode ?x ?s)]\n");
    // Blanks and comments are free between tokens; punctuation needs no blanks around it.
    CHECK(normal_form("rule r when(p ?x)not(q ?x)[for all ?d in{a b}:(s ?d)]then(t ?x)# c") ==
          normal_form("rule r\n  when (p ?x) not (q ?x) [for all ?d in {a b}: (s ?d)]\n  then (t ?x)\n"));
    CHECK(normal_form("fact (p a)\r\nrule r\r\n\twhen (p ?x)\r\n\tthen (q ?x)") ==
          "fact (p a)\n\nrule r\n  when (p ?x)\n  then (q ?x)\n");
    CHECK(normal_form("fact (p a#comment\n b)") == "fact (p a b)\n");  // '#' ends a word
    // A parenthesised list of lone signs is a direction; anything else in parentheses is a call.
    CHECK(normal_form("fact (p (- 0) (?) (- 0 1) (+0-))") == "fact (p (- 0) (?) (- 0 1) (+0-))\n");
    qm::Diagnostics d;
    ProgramSpec calls = read("fact (p (- 0) (- 0 1) (+0-))", d);
    REQUIRE(calls.facts.size() == 1);
    CHECK(calls.facts[0].args[0].kind == TermSpec::Kind::direction);
    CHECK(calls.facts[0].args[1].kind == TermSpec::Kind::call);
    CHECK(calls.facts[0].args[2].kind == TermSpec::Kind::call);  // one word "+0-": an (unknown) function
    // Names are any words but integers and variables; keywords are names where a name is expected.
    CHECK(normal_form("rule when\n  when (<=> a.b x-1? rule fact not then) (p zero?)\n  then (not a+b)\n") ==
          "\nrule when\n  when (<=> a.b x-1? rule fact not then) (p zero?)\n  then (not a+b)\n");
    CHECK(normal_form("fact (p -9223372036854775808 9223372036854775807 -0 007)") ==
          "fact (p -9223372036854775808 9223372036854775807 0 7)\n");
}

TEST_CASE("engine/rule_parser: a top-level `assume` starts in column 1, a consequent `assume` is indented") {
    qm::Diagnostics d;
    ProgramSpec spec = read("rule r\n  when (p ?x)\n  then (q ?x)\n  assume (m ?x)\nassume (n a)\n", d);
    REQUIRE(!d.has_errors());
    REQUIRE(spec.rules.size() == 1);
    REQUIRE(spec.rules[0].consequents.size() == 2);
    CHECK(spec.rules[0].consequents[1].kind == ConsequentSpec::Kind::assume);
    REQUIRE(spec.assumptions.size() == 1);
    CHECK(spec.assumptions[0].predicate == "n");
    // A column-1 keyword ends whatever is open: the unclosed atom is reported there, and the next
    // item is read.
    qm::Diagnostics e;
    ProgramSpec after = read("fact (p a\nfact (q b)\n", e);
    CHECK(messages(e) == "t.rules:2:1: error: expected a term or ')' to close the '(' at 1:6 but found 'fact'\n"
                         "  fact (q b)\n  ^\n");
    REQUIRE(after.facts.size() == 1);
    CHECK(after.facts[0].predicate == "q");
    // Indented, it is not an item; the word `rule` inside an atom on the same line is a symbol.
    CHECK(first_error("  fact (p)") ==
          "1:3: expected 'rule', 'fact', 'assume', 'include', 'input', 'output', 'cite' or 'prefer' at the start of a line but found 'fact' in column 3");
    CHECK(normal_form("fact (p rule)") == "fact (p rule)\n");
}

TEST_CASE("engine/rule_parser: every node is located where it starts") {
    qm::Diagnostics d;
    ProgramSpec spec = read("rule r\n  when (p ?x) not (q ?x) [for all ?d in {a}: (s ?d)]\n"
                            "  then false [exactly one ?s in {a}: assume (m ?s)]\n",
                            d);
    REQUIRE(!d.has_errors());
    const RuleSpec& r = spec.rules.at(0);
    CHECK(at(r.where) == "1:1");
    CHECK(r.where.file == "t.rules");
    CHECK(at(r.conditions.at(0).where) == "2:8");
    CHECK(at(r.conditions[0].atom.where) == "2:8");
    CHECK(at(r.conditions[0].atom.args.at(0).where) == "2:11");
    CHECK(at(r.conditions.at(1).where) == "2:15");  // `not`
    CHECK(at(r.conditions[1].atom.where) == "2:19");
    CHECK(at(r.conditions.at(2).where) == "2:26");  // '['
    CHECK(at(r.conditions[2].set.where) == "2:41");
    CHECK(at(r.conditions[2].atoms.at(0).where) == "2:46");
    CHECK(at(r.consequents.at(0).where) == "3:8");
    CHECK(at(r.consequents.at(1).where) == "3:14");
    CHECK(at(r.consequents[1].atom.where) == "3:45");
}

TEST_CASE("engine/rule_parser: syntax errors say what was expected and what was found") {
    const std::pair<const char*, const char*> cases[] = {
        {"rule", "1:5: expected a rule name but found the end of the file"},
        {"rule r\n", "1:7: expected 'when' but found the end of the file"},
        {"rule r when", "1:12: expected a condition or 'then' but found the end of the file"},
        {"rule r when (p) :", "1:17: expected a condition or 'then' but found ':'"},
        {"rule r when (p) then",
         "1:21: expected a consequent (an atom, 'false', 'assume' or a bracketed quantifier) but found the end of the file"},
        {"rule r when (p) then (q) junk",
         "1:26: expected a consequent (an atom, 'false', 'assume' or a bracketed quantifier) but found 'junk'"},
        {"fact p", "1:6: expected an atom like (p ?x) but found 'p'"},
        {"fact (p", "1:8: expected a term or ')' but found the end of the file"},
        {"fact (p \"s\")", "1:9: expected a term or ')' but found '\"s\"'"},
        {"fact (?x)", "1:7: expected a predicate name but found '?x'"},
        {"fact (p {a b)", "1:13: expected a term or '}' but found ')'"},
        {"fact (p ())", "1:10: expected a direction of signs or a builtin function name but found ')'"},
        {"fact (p 99999999999999999999)",
         "1:9: expected an integer from -9223372036854775808 to 9223372036854775807 but found '99999999999999999999'"},
        {"include x", "1:9: expected a file name in double quotes but found 'x'"},
        {"include \"a\nfact (p)", "1:11: expected a closing '\"' on the same line but found the end of the line"},
        {"junk", "1:1: expected 'rule', 'fact', 'assume', 'include', 'input', 'output', 'cite' or 'prefer' at the start of a line but found 'junk'"},
        {"rule r when [for all x in {a}: (p x)] then false", "1:22: expected a variable like ?x but found 'x'"},
        {"rule r when [for all ?x of {a}: (p ?x)] then false", "1:25: expected 'in' but found 'of'"},
        {"rule r when [for all ?x in {a} (p ?x)] then false", "1:32: expected ':' but found '(p'"},
        {"rule r when [for all ?x in {a} where (p ?x): (p ?x)] then false",
         "1:38: expected a builtin test like (= ?x ?y) but found '(p'"},
        {"rule r when [for all ?x in {a}: (p ?x) and] then false", "1:43: expected an atom like (p ?x) but found ']'"},
        {"rule r when [for every ?x in {a}: (p ?x)] then false", "1:18: expected 'all' but found 'every'"},
        {"rule r when [sum ?v over (p ?v) with + start 0] then false", "1:47: expected 'as' but found ']'"},
        {"rule r when [sum 3 over (p ?v) with + start 0 as ?t] then false", "1:18: expected a variable like ?x but found '3'"},
        {"rule r when (p ?x) [bogus] then false", "1:21: expected 'for all', 'exists' or 'sum' but found 'bogus'"},
        {"rule r when (p ?x) then [bogus]", "1:26: expected 'for all' or 'exactly one' but found 'bogus'"},
        {"rule r when (p) then [exactly one ?s in {a}: (m ?s)]", "1:46: expected 'assume' but found '(m'"},
        {"rule r when (p) then [exactly two ?s in {a}: assume (m ?s)]", "1:31: expected 'one' but found 'two'"},
        {"rule r when (p) then [for all ?s in {a}: (m ?s)", "1:48: expected ']' but found the end of the file"},
        {"fact (p \x01\xfe)", "1:9: expected a term or ')' but found '\\x01\\xfe'"},
    };
    for (const auto& [text, expected] : cases) {
        CAPTURE(text);
        CHECK(first_error(text) == expected);
    }
    // The diagnostic carries its source line, so that it prints with a caret under the token.
    qm::Diagnostics d;
    (void)read("fact (p a)\nrule r\n  when [for all ?x of {a}: (p ?x)]\n  then false\n", d);
    CHECK(messages(d) == "t.rules:3:20: error: expected 'in' but found 'of'\n"
                         "    when [for all ?x of {a}: (p ?x)]\n"
                         "                     ^\n");
}

TEST_CASE("engine/rule_parser: calls and sets nest at most max_term_nesting deep") {
    auto nested = [](int depth) {
        return "fact (p " + std::string(static_cast<std::size_t>(depth), '{') +
               std::string(static_cast<std::size_t>(depth), '}') + ")";
    };
    CHECK(first_error(nested(max_term_nesting)) == "no error");
    CHECK(first_error(nested(max_term_nesting + 1)) ==
          "1:" + std::to_string(9 + max_term_nesting) + ": expected a term nested at most 64 calls or sets deep but found '{'");
    std::string calls = "fact (p ";
    for (int i = 0; i <= max_term_nesting; ++i) calls += "(neg ";
    calls += "(+)" + std::string(static_cast<std::size_t>(max_term_nesting) + 1, ')') + ")";
    CHECK(first_error(calls).find("expected a term nested at most 64") != std::string::npos);
    // Deep input far beyond the limit is an error, not a stack overflow.
    CHECK(first_error(nested(200000)).find("expected a term nested at most 64") != std::string::npos);
}

TEST_CASE("engine/rule_parser: a corrupted item affects no other item") {
    // Reading is compositional over items: with one item corrupted (any character but its first
    // and its line ends), the file reads to exactly what its items read to one by one, with as many
    // errors, so recovery never loses or changes a neighbour.
    std::mt19937 rng(2026);
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    const std::string alphabet = "()[]{}:\"#?+-0 abwx;";
    int with_errors = 0;
    for (int round = 0; round < 2000; ++round) {
        std::vector<std::string> chosen;
        for (std::size_t i = 0, n = 2 + pick(6); i < n; ++i) chosen.push_back(items[pick(std::size(items))]);
        std::string& bad = chosen[pick(chosen.size())];
        std::size_t k = 1 + pick(bad.size() - 1);
        while (bad[k] == '\n') k = 1 + pick(bad.size() - 1);
        bad[k] = alphabet[pick(alphabet.size())];
        std::string text;
        ProgramSpec one_by_one;
        std::size_t errors = 0;
        for (const std::string& item : chosen) {
            text += item;
            qm::Diagnostics d;
            ProgramSpec alone = read(item, d);
            errors += d.size();
            for (auto& f : alone.facts) one_by_one.facts.push_back(f);
            for (auto& a : alone.assumptions) one_by_one.assumptions.push_back(a);
            for (auto& r : alone.rules) one_by_one.rules.push_back(r);
        }
        CAPTURE(text);
        qm::Diagnostics d;
        ProgramSpec spec;
        CHECK_NOTHROW(spec = read(text, d));
        for (const auto& x : d.items()) CHECK(!x.source_line.empty());
        CHECK(d.size() == errors);
        CHECK(print_program(spec) == print_program(one_by_one));
        with_errors += d.has_errors();
    }
    CHECK(with_errors > 700);  // most corruptions are errors, so recovery is what is being tested
}

TEST_CASE("engine/rule_parser: a misspelt keyword in column 1 ends the rule before it") {
    qm::Diagnostics d;
    ProgramSpec spec = read("rule r\n  when (p ?x)\n  then (q ?x)\nrul s\n  when (q ?x)\n  then (s ?x)\nfact (p a)\n", d);
    CHECK(messages(d) == "t.rules:4:1: error: expected 'rule', 'fact', 'assume', 'include', 'input', 'output', 'cite' or 'prefer' at the start of a line but "
                         "found 'rul'\n  rul s\n  ^\n");
    CHECK(spec.rules.size() == 1);
    CHECK(spec.facts.size() == 1);
    // `(`, `[` and `false` in column 1 continue the consequents.
    CHECK(normal_form("rule r\nwhen (p ?x)\nthen (q ?x)\n(r ?x)\n[for all ?y in {a}: (s ?y)]\nfalse\n") ==
          "\nrule r\n  when (p ?x)\n  then (q ?x) (r ?x) [for all ?y in {a}: (s ?y)] false\n");
}
