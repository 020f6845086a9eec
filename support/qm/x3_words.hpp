// support/qm/x3_words.hpp
// Provides:   readable words for what an X3 expectation failure names when the parser after `>` is
//             not a rule or a literal. X3 describes a parser through get_info<Parser>, whose default
//             is typeid(Parser).name(): an expectation on `+name` said
//             `expected N5boost6spirit2x34plusINS1_4ruleIN2qm8geometry7mparser10name_class...`
//             Here every composite parser is described by its parts, down to the rules
//             (their names) and literals (quoted):
//               +p, *p, -p, p % sep, p - q, &p, p[action], lexeme[p], raw[p], ... -> what(p)
//               a >> b                                                        -> what(a)
//               a | b                                                         -> what(a) or what(b)
//               !p                                                            -> something other than what(p)
//             so the message stays `expected a name but found ')'`.
// Contract:   included (through qm/x3_parse.hpp and qm/x3_ascii.hpp) before any grammar is
//             defined, so that every translation unit instantiating a reader sees the same
//             specialisations.
#pragma once
#include <boost/spirit/home/x3.hpp>
#include <string>

namespace boost::spirit::x3 {

// A parser described by its subject.
template <class Subject>
struct get_info<plus<Subject>> {
    using result_type = std::string;
    std::string operator()(const plus<Subject>& p) const { return what(p.subject); }
};
template <class Subject>
struct get_info<kleene<Subject>> {
    using result_type = std::string;
    std::string operator()(const kleene<Subject>& p) const { return what(p.subject); }
};
template <class Subject>
struct get_info<optional<Subject>> {
    using result_type = std::string;
    std::string operator()(const optional<Subject>& p) const { return what(p.subject); }
};
template <class Subject>
struct get_info<and_predicate<Subject>> {
    using result_type = std::string;
    std::string operator()(const and_predicate<Subject>& p) const { return what(p.subject); }
};
template <class Subject>
struct get_info<not_predicate<Subject>> {
    using result_type = std::string;
    std::string operator()(const not_predicate<Subject>& p) const { return "something other than " + what(p.subject); }
};
template <class Subject>
struct get_info<lexeme_directive<Subject>> {
    using result_type = std::string;
    std::string operator()(const lexeme_directive<Subject>& p) const { return what(p.subject); }
};
template <class Subject>
struct get_info<raw_directive<Subject>> {
    using result_type = std::string;
    std::string operator()(const raw_directive<Subject>& p) const { return what(p.subject); }
};
template <class Subject>
struct get_info<omit_directive<Subject>> {
    using result_type = std::string;
    std::string operator()(const omit_directive<Subject>& p) const { return what(p.subject); }
};
template <class Subject>
struct get_info<no_case_directive<Subject>> {
    using result_type = std::string;
    std::string operator()(const no_case_directive<Subject>& p) const { return what(p.subject); }
};
template <class Subject>
struct get_info<expect_directive<Subject>> {
    using result_type = std::string;
    std::string operator()(const expect_directive<Subject>& p) const { return what(p.subject); }
};
template <class Subject, class Action>
struct get_info<action<Subject, Action>> {
    using result_type = std::string;
    std::string operator()(const action<Subject, Action>& p) const { return what(p.subject); }
};

// A binary parser described by what it must start with.
template <class Left, class Right>
struct get_info<sequence<Left, Right>> {
    using result_type = std::string;
    std::string operator()(const sequence<Left, Right>& p) const { return what(p.left); }
};
template <class Left, class Right>
struct get_info<list<Left, Right>> {
    using result_type = std::string;
    std::string operator()(const list<Left, Right>& p) const { return what(p.left); }
};
template <class Left, class Right>
struct get_info<difference<Left, Right>> {
    using result_type = std::string;
    std::string operator()(const difference<Left, Right>& p) const { return what(p.left); }
};
template <class Left, class Right>
struct get_info<alternative<Left, Right>> {
    using result_type = std::string;
    std::string operator()(const alternative<Left, Right>& p) const { return what(p.left) + " or " + what(p.right); }
};

}  // namespace boost::spirit::x3
