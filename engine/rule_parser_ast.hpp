// engine/rule_parser_ast.hpp
// Provides:   the AST of a rule file as the Spirit X3 grammar (rule_parser_def.hpp) produces it:
//             one Item per top-level `include`, `fact`, `assume`, `rule`, `input`, `output`, `cite` or `prefer`, with every condition,
//             consequent and term as written. rule_parser_to_spec.hpp turns it into a ProgramSpec.
// Ownership:  plain values. Every node derives from x3::position_tagged; the parser stores in
//             id_first the byte offset where the node starts (after blanks and comments), so a
//             SourceText (rule_parser_source.hpp) of the same text locates it. id_last is unused.
// Invariants: a Test's name is a builtin test of the registry the text was parsed with; an Atom's
//             predicate, a Call's function and a Rule's name are words that are neither integers
//             nor variables; a Direction holds at least one of the signs + 0 - ?.
// Knows nothing of the ATMS, of ValueIds or of the compiled program.
#pragma once
#include <boost/optional.hpp>
#include <boost/spirit/home/x3/support/ast/position_tagged.hpp>
#include <boost/spirit/home/x3/support/ast/variant.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace qm::engine::ast {
namespace x3 = boost::spirit::x3;

struct Name : x3::position_tagged { std::string text; };      // predicate, rule or function name
struct Symbol : x3::position_tagged { std::string text; };    // starts with a letter
struct Variable : x3::position_tagged { std::string name; };  // without the '?'
struct Integer : x3::position_tagged { std::int64_t value = 0; };
struct Direction : x3::position_tagged { std::string signs; };  // "+0-"
struct Call;
struct Set;

struct Term : x3::variant<Symbol, Integer, Variable, Direction, x3::forward_ast<Call>, x3::forward_ast<Set>> {
    using base_type::base_type;
    using base_type::operator=;
};

struct Call : x3::position_tagged {
    Name function;
    std::vector<Term> args;
};
struct Set : x3::position_tagged { std::vector<Term> elements; };

struct Atom : x3::position_tagged {
    Name predicate;
    std::vector<Term> args;
};
struct Test : x3::position_tagged {
    Name name;
    std::vector<Term> args;
};

// `?v in SET where TEST and TEST:`, shared by the quantifiers.
struct Binder : x3::position_tagged {
    Variable variable;
    Term set;
    std::vector<Test> tests;
};

struct Negation : x3::position_tagged { Atom atom; };
struct ForAllCondition : x3::position_tagged {
    Binder binder;
    std::vector<Atom> atoms;
};
struct ExistsCondition : x3::position_tagged {
    Binder binder;
    std::vector<Atom> atoms;
};
struct Aggregate : x3::position_tagged {  // [sum ?value over ATOM with FUNCTION start TERM as ?result]
    Variable value;
    Atom atom;
    Name function;
    Term start;
    Variable result;
};
struct Condition : x3::variant<Atom, Test, Negation, ForAllCondition, ExistsCondition, Aggregate> {
    using base_type::base_type;
    using base_type::operator=;
};

struct Falsity : x3::position_tagged {};
struct Assume : x3::position_tagged { Atom atom; };
struct ForAllConsequent : x3::position_tagged {
    Binder binder;
    Atom atom;
};
struct ExactlyOne : x3::position_tagged {
    Binder binder;
    Atom atom;
};
struct Consequent : x3::variant<Atom, Falsity, Assume, ForAllConsequent, ExactlyOne> {
    using base_type::base_type;
    using base_type::operator=;
};

struct FileName : x3::position_tagged { std::string text; };  // between the double quotes
struct Include : x3::position_tagged { FileName file; };
struct Fact : x3::position_tagged { Atom atom; };
struct Assumption : x3::position_tagged { Atom atom; };
struct Rule : x3::position_tagged {
    Name name;
    std::vector<Condition> conditions;
    std::vector<Consequent> consequents;
};
struct Input : x3::position_tagged { Atom atom; };     // `input (p ?x)`: a driver asserts p
struct Output : x3::position_tagged { Atom atom; };    // `output (p ?x)`: a driver reads p back
struct Cite : x3::position_tagged { FileName text; };  // `cite "section 3.1, Table 3.1"`
// `prefer (c ?x ?y) by (r ?x ?y ?k) up to 3`: prefer interpretations whose picks of c rank lower by r.
struct Prefer : x3::position_tagged {
    Atom choice;
    Atom rank;
    boost::optional<Integer> up_to;
};
struct Item : x3::variant<Include, Fact, Assumption, Rule, Input, Output, Cite, Prefer> {
    using base_type::base_type;
    using base_type::operator=;
};

}  // namespace qm::engine::ast
