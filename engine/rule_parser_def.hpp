// engine/rule_parser_def.hpp
// Provides:   the Spirit X3 grammar of the rule language (docs/RULES.md is its reference): words,
//             terms, atoms, builtin tests, conditions, consequents and the seven top-level items.
//             Include only from rule_parser.cpp: X3's compile cost is paid in one translation unit.
// Ownership:  rules are constants; per-parse state (text start, builtin registry, nesting depth, the
//             recorded failure) comes in through x3::with<state_tag> (rule_parser_error_handler.hpp).
// Invariants: every rule whose attribute is position_tagged stores its start offset on success; after
//             an item's first word, every step is an expectation (`>`), so a syntax error is reported
//             where it is, named by the rule that was expected; only item_entry and atom_entry handle
//             errors, so an expectation failure always aborts the whole item.
// Layout:     the one layout rule of the language is here: a top-level item starts with its keyword in
//             column 1 (bol), and such a keyword ends whatever is open before it (term lists,
//             consequent lists), so an unclosed parenthesis is reported at the next item at the latest.
#pragma once
#include "qm/x3_ascii.hpp"
#include "engine/rule_parser.hpp"
#include "engine/rule_parser_ast.hpp"
#include "engine/rule_parser_error_handler.hpp"
#include <boost/fusion/include/adapt_struct.hpp>
#include <boost/spirit/home/x3.hpp>

BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Name, text)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Symbol, text)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Variable, name)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Integer, value)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Direction, signs)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Call, function, args)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Set, elements)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Atom, predicate, args)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Test, name, args)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Binder, variable, set, tests)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Negation, atom)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::ForAllCondition, binder, atoms)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::ExistsCondition, binder, atoms)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Aggregate, value, atom, function, start, result)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Assume, atom)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::ForAllConsequent, binder, atom)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::ExactlyOne, binder, atom)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::FileName, text)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Include, file)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Fact, atom)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Assumption, atom)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Rule, name, conditions, consequents)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Input, atom)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Output, atom)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Cite, text)
BOOST_FUSION_ADAPT_STRUCT(qm::engine::ast::Prefer, choice, rank, up_to)

namespace qm::engine::parser {

// --- custom primitives -------------------------------------------------------------------------

// Succeeds, consuming only blanks, where the next token starts a line (column 1).
struct bol_parser : x3::parser<bol_parser> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx& ctx, RCtx&, Attr&) const {
        It it = first;
        x3::skip_over(it, last, ctx);
        if (it != x3::get<state_tag>(ctx).begin && *(it - 1) != '\n') return false;
        first = it;
        return true;
    }
};
inline const bol_parser bol{};

// Succeeds, consuming nothing, where the next word names a builtin test of the registry.
struct test_ahead_parser : x3::parser<test_ahead_parser> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx& ctx, RCtx&, Attr&) const {
        It it = first;
        x3::skip_over(it, last, ctx);
        It end = it;
        while (end != last && is_word_char(*end)) ++end;
        auto id = x3::get<state_tag>(ctx).builtins->find(std::string_view(&*it, static_cast<std::size_t>(end - it)));
        return end != it && id && x3::get<state_tag>(ctx).builtins->get(*id).kind == BuiltinKind::test;
    }
};
inline const test_ahead_parser test_ahead{};

// Opening a call or a set: one level deeper, or an expectation failure at the opening bracket past
// max_term_nesting (so a pathological input cannot exhaust the stack). Used only where the bracket
// is next and the rule commits to it, so that every `deeper` is matched by a `shallower` or the item
// is abandoned (the depth is reset for each item).
struct deeper_parser : x3::parser<deeper_parser> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It& first, const It& last, const Ctx& ctx, RCtx&, Attr&) const {
        ParseState& st = x3::get<state_tag>(ctx);
        if (st.depth >= max_term_nesting) {
            It it = first;
            x3::skip_over(it, last, ctx);
            throw x3::expectation_failure<It>(it, "a term nested at most " + std::to_string(max_term_nesting) +
                                                      " calls or sets deep");
        }
        ++st.depth;
        return true;
    }
};
struct shallower_parser : x3::parser<shallower_parser> {
    using attribute_type = x3::unused_type;
    static const bool has_attribute = false;
    template <class It, class Ctx, class RCtx, class Attr>
    bool parse(It&, const It&, const Ctx& ctx, RCtx&, Attr&) const {
        --x3::get<state_tag>(ctx).depth;
        return true;
    }
};
inline const deeper_parser deeper{};
inline const shallower_parser shallower{};

// --- lexical pieces ----------------------------------------------------------------------------
// ASCII classes (qm/x3_ascii.hpp) rather than x3::space/x3::alpha, which follow the C library's
// classification and abort on bytes >= 0x80 in a debug build.
using x3_ascii::blank;
using x3_ascii::digit;
using x3_ascii::letter;
inline const auto skipper = blank | (x3::lit('#') >> *(x3::char_ - x3::lit('\n')));
inline const auto word_char = ~x3::char_("()[]{}:#\" \t\n\r\v\f");
inline const auto sign_char = x3::char_('+') | x3::char_('0') | x3::char_('-') | x3::char_('?');
inline const auto integer_ahead = x3::lexeme[-x3::lit('-') >> +digit >> !word_char];

// A keyword is a whole word: `not` but not `nothing`.
inline auto kw(const char* word) { return x3::lexeme[x3::lit(word) >> !word_char]; }
inline const auto top_keyword =
    bol >> (kw("rule") | kw("fact") | kw("assume") | kw("include") | kw("input") | kw("output") | kw("cite") | kw("prefer"));
// A rule's consequents end at the end of the text or at a line whose first token (in column 1)
// cannot continue them: only `(`, `[` and `false` can, so `assume` in column 1 is a top-level item,
// and a misspelt top-level keyword costs only its own item, not the rule before it.
inline const auto consequents_end = x3::eoi | (bol >> !(x3::lit('(') | x3::lit('[') | kw("false")));

// Named pieces used after `>`: the name is what "expected ..." says.
template <class ID>
auto named(const char* name, auto subject) {
    return x3::rule<ID>{name} = subject;
}
inline const auto when_kw = named<struct when_kw_id>("'when'", kw("when"));
inline const auto then_kw = named<struct then_kw_id>("'then'", kw("then"));
inline const auto all_kw = named<struct all_kw_id>("'all'", kw("all"));
inline const auto in_kw = named<struct in_kw_id>("'in'", kw("in"));
inline const auto one_kw = named<struct one_kw_id>("'one'", kw("one"));
inline const auto over_kw = named<struct over_kw_id>("'over'", kw("over"));
inline const auto with_kw = named<struct with_kw_id>("'with'", kw("with"));
inline const auto start_kw = named<struct start_kw_id>("'start'", kw("start"));
inline const auto as_kw = named<struct as_kw_id>("'as'", kw("as"));
inline const auto by_kw = named<struct by_kw_id>("'by'", kw("by"));
inline const auto to_kw = named<struct to_kw_id>("'to'", kw("to"));
inline const auto assume_kw = named<struct assume_kw_id>("'assume'", kw("assume"));
inline const auto colon = named<struct colon_id>("':'", x3::lit(':'));
inline const auto close_bracket = named<struct close_bracket_id>("']'", x3::lit(']'));
inline const auto close_paren = named<struct close_paren_id>("a term or ')'", x3::lit(')'));
inline const auto close_brace = named<struct close_brace_id>("a term or '}'", x3::lit('}'));
inline const auto end_of_input = named<struct end_of_input_id>("the end of the text", x3::eoi);

// --- rule ids ----------------------------------------------------------------------------------
struct name_id : annotate {};
struct predicate_id : annotate {};
struct function_name_id : annotate {};
struct rule_name_id : annotate {};
struct symbol_id : annotate {};
struct variable_id : annotate {};
struct variable_expected_id : annotate {};
struct integer_id : annotate {};
struct direction_id : annotate {};
struct call_id : annotate {};
struct set_id : annotate {};
struct term_id : annotate {};
struct args_id : annotate {};
struct atom_id : annotate {};
struct atom_expected_id : annotate {};
struct atoms_id : annotate {};
struct test_id : annotate {};
struct test_expected_id : annotate {};
struct where_clause_id : annotate {};
struct binder_id : annotate {};
struct negation_id : annotate {};
struct for_all_condition_id : annotate {};
struct exists_condition_id : annotate {};
struct aggregate_id : annotate {};
struct condition_id : annotate {};
struct conditions_id : annotate {};
struct falsity_id : annotate {};
struct assume_consequent_id : annotate {};
struct for_all_consequent_id : annotate {};
struct exactly_one_id : annotate {};
struct consequent_id : annotate {};
struct consequents_id : annotate {};
struct file_name_id : annotate {};
struct citation_text_id : annotate {};
struct include_item_id : annotate {};
struct fact_item_id : annotate {};
struct assume_item_id : annotate {};
struct rule_item_id : annotate {};
struct input_item_id : annotate {};
struct output_item_id : annotate {};
struct cite_item_id : annotate {};
struct prefer_item_id : annotate {};
struct threshold_id : annotate {};
struct top_item_id : annotate {};
struct item_entry_id : annotate, first_failure {};
struct atom_entry_id : annotate, first_failure {};

const x3::rule<name_id, ast::Name> name = "a name";
const x3::rule<predicate_id, ast::Name> predicate = "a predicate name";
const x3::rule<function_name_id, ast::Name> function_name = "a direction of signs or a builtin function name";
const x3::rule<rule_name_id, ast::Name> rule_name = "a rule name";
const x3::rule<symbol_id, ast::Symbol> symbol = "a symbol";
const x3::rule<variable_id, ast::Variable> variable = "a variable";
const x3::rule<variable_expected_id, ast::Variable> variable_expected = "a variable like ?x";
const x3::rule<integer_id, ast::Integer> integer = "an integer";
const x3::rule<direction_id, ast::Direction> direction = "a direction";
const x3::rule<call_id, ast::Call> call = "a function call";
const x3::rule<set_id, ast::Set> set = "a set";
const x3::rule<term_id, ast::Term> term = "a term (a symbol, integer, variable, direction, set or function call)";
const x3::rule<args_id, std::vector<ast::Term>> args = "terms";
const x3::rule<atom_id, ast::Atom> atom = "an atom";
const x3::rule<atom_expected_id, ast::Atom> atom_expected = "an atom like (p ?x)";
const x3::rule<atoms_id, std::vector<ast::Atom>> atoms = "an atom like (p ?x)";
const x3::rule<test_id, ast::Test> test = "a builtin test";
const x3::rule<test_expected_id, ast::Test> test_expected = "a builtin test like (= ?x ?y)";
const x3::rule<where_clause_id, std::vector<ast::Test>> where_clause = "'where' or ':'";
const x3::rule<binder_id, ast::Binder> binder = "a variable like ?x";
const x3::rule<negation_id, ast::Negation> negation = "a negation";
const x3::rule<for_all_condition_id, ast::ForAllCondition> for_all_condition = "'for all'";
const x3::rule<exists_condition_id, ast::ExistsCondition> exists_condition = "'exists'";
const x3::rule<aggregate_id, ast::Aggregate> aggregate = "'sum'";
const x3::rule<condition_id, ast::Condition> condition = "a condition or 'then'";
const x3::rule<conditions_id, std::vector<ast::Condition>> conditions = "conditions";
const x3::rule<falsity_id, ast::Falsity> falsity = "'false'";
const x3::rule<assume_consequent_id, ast::Assume> assume_consequent = "'assume'";
const x3::rule<for_all_consequent_id, ast::ForAllConsequent> for_all_consequent = "'for all'";
const x3::rule<exactly_one_id, ast::ExactlyOne> exactly_one = "'exactly one'";
const x3::rule<consequent_id, ast::Consequent> consequent =
    "a consequent (an atom, 'false', 'assume' or a bracketed quantifier)";
const x3::rule<consequents_id, std::vector<ast::Consequent>> consequents =
    "a consequent (an atom, 'false', 'assume' or a bracketed quantifier)";
const x3::rule<file_name_id, ast::FileName> file_name = "a file name in double quotes";
const x3::rule<citation_text_id, ast::FileName> citation_text = "a citation in double quotes";
const x3::rule<include_item_id, ast::Include> include_item = "'include'";
const x3::rule<fact_item_id, ast::Fact> fact_item = "'fact'";
const x3::rule<assume_item_id, ast::Assumption> assume_item = "'assume'";
const x3::rule<rule_item_id, ast::Rule> rule_item = "'rule'";
const x3::rule<input_item_id, ast::Input> input_item = "'input'";
const x3::rule<output_item_id, ast::Output> output_item = "'output'";
const x3::rule<cite_item_id, ast::Cite> cite_item = "'cite'";
const x3::rule<prefer_item_id, ast::Prefer> prefer_item = "'prefer'";
const x3::rule<threshold_id, ast::Integer> threshold = "an integer (the threshold)";
const x3::rule<top_item_id, ast::Item> top_item = top_item_name;
const x3::rule<item_entry_id, ast::Item> item_entry = "a top-level item";
const x3::rule<atom_entry_id, ast::Atom> atom_entry = "an atom";

// --- words and terms ---------------------------------------------------------------------------
// A name is a word that is neither an integer nor a variable: `contact`, `trans-motion`, `<=`, `+`;
// a top-level keyword in column 1 is never a name (it starts the next item).
// raw[]: the word is copied into the attribute once, not appended a character at a time.
const auto name_def = !top_keyword >> x3::lexeme[!integer_ahead >> !x3::lit('?') >> x3::raw[+word_char]];
const auto predicate_def = name;
const auto function_name_def = name;
const auto rule_name_def = name;
const auto symbol_def = x3::lexeme[x3::raw[letter >> *word_char]];
const auto variable_def = x3::lexeme[x3::lit('?') >> x3::raw[+word_char]];
const auto variable_expected_def = variable;
// A word of digits with an optional '-'; `-` alone, `+5` and `12a` are not integers. One that does
// not fit in 64 bits is an error (long_long fails on overflow).
const auto integer_def = x3::lexeme[&integer_ahead >> x3::long_long >> !word_char];
const auto integer_overflow =
    &integer_ahead > named<struct integer_overflow_id>("an integer from -9223372036854775808 to 9223372036854775807", !x3::eps);
// `(+ 0 -)`: a parenthesised list of lone signs is always a direction, never a call.
const auto direction_def = x3::lit('(') >> +x3::lexeme[sign_char >> !word_char] >> x3::lit(')');
const auto call_def = (((&x3::lit('(') >> deeper >> x3::lit('(')) > function_name > args > close_paren) >> shallower);
const auto set_def = (((&x3::lit('{') >> deeper >> x3::lit('{')) > args > close_brace) >> shallower);
const auto term_def = variable | integer | integer_overflow | symbol | direction | call | set;
const auto args_def = *(!top_keyword >> term);

// --- atoms and tests ---------------------------------------------------------------------------
const auto atom_def = x3::lit('(') > predicate > args > close_paren;
const auto atom_expected_def = atom;
const auto atoms_def = atom_expected > *((kw("and") > atom_expected) | atom);
const auto test_def = (x3::lit('(') >> test_ahead >> name) > args > close_paren;
const auto test_expected_def = test;
const auto where_clause_def = (kw("where") > test_expected > *((kw("and") > test_expected) | test)) |
                              x3::attr(std::vector<ast::Test>{});
const auto binder_def = variable_expected > in_kw > term > where_clause > colon;

// --- conditions --------------------------------------------------------------------------------
// A bracketed quantifier or aggregate is recognised by the word after '[' (so its node starts at
// the '['); any other word there is reported by the bad_bracket alternatives.
const auto negation_def = kw("not") > atom_expected;
const auto for_all_condition_def = (x3::lit('[') >> kw("for")) > all_kw > binder > atoms > close_bracket;
const auto exists_condition_def = (x3::lit('[') >> kw("exists")) > binder > atoms > close_bracket;
const auto aggregate_def = (x3::lit('[') >> kw("sum")) > variable_expected > over_kw > atom_expected > with_kw >
                           function_name > start_kw > term > as_kw > variable_expected > close_bracket;
const auto bad_bracket_condition = x3::lit('[') > named<struct bracket_condition_id>("'for all', 'exists' or 'sum'", !x3::eps);
const auto condition_def = negation | test | atom | for_all_condition | exists_condition | aggregate | bad_bracket_condition;
const auto conditions_def = *((!kw("then")) > condition);

// --- consequents -------------------------------------------------------------------------------
const auto falsity_def = kw("false") >> x3::attr(ast::Falsity{});
const auto assume_consequent_def = kw("assume") > atom_expected;
const auto for_all_consequent_def = (x3::lit('[') >> kw("for")) > all_kw > binder > atom_expected > close_bracket;
const auto exactly_one_def =
    (x3::lit('[') >> kw("exactly")) > one_kw > binder > assume_kw > atom_expected > close_bracket;
const auto bad_bracket_consequent = x3::lit('[') > named<struct bracket_consequent_id>("'for all' or 'exactly one'", !x3::eps);
const auto consequent_def = falsity | assume_consequent | atom | for_all_consequent | exactly_one | bad_bracket_consequent;
// One or more, up to the next top-level item: a consequent `assume` is indented, a top-level one is not.
const auto consequents_def = +((!consequents_end) > consequent);

// --- top-level items ---------------------------------------------------------------------------
const auto closing_quote = named<struct closing_quote_id>(closing_quote_name, x3::lit('"'));
const auto file_name_def = x3::lexeme[x3::lit('"') > *(x3::char_ - x3::char_("\"\n")) > closing_quote];
const auto include_item_def = kw("include") > file_name;
const auto fact_item_def = kw("fact") > atom_expected;
const auto assume_item_def = kw("assume") > atom_expected;
const auto rule_item_def = kw("rule") > rule_name > when_kw > conditions > then_kw > consequents;
const auto input_item_def = kw("input") > atom_expected;
const auto output_item_def = kw("output") > atom_expected;
const auto citation_text_def = file_name_def;
const auto cite_item_def = kw("cite") > citation_text;
// `up to N` is optional; a misspelt word after the rank atom is the next item's error (it must
// start a line), like a consequent after a rule.
const auto threshold_def = integer;
const auto prefer_item_def = kw("prefer") > atom_expected > by_kw > atom_expected > -(kw("up") > to_kw > threshold);
const auto top_item_def =
    bol >> (include_item | fact_item | assume_item | rule_item | input_item | output_item | cite_item | prefer_item);
const auto item_entry_def = x3::eps > top_item;
const auto atom_entry_def = x3::eps > atom_expected > end_of_input;

BOOST_SPIRIT_DEFINE(name, predicate, function_name, rule_name, symbol, variable, variable_expected, integer,
                    direction, call, set, term, args)
BOOST_SPIRIT_DEFINE(atom, atom_expected, atoms, test, test_expected, where_clause, binder)
BOOST_SPIRIT_DEFINE(negation, for_all_condition, exists_condition, aggregate, condition, conditions)
BOOST_SPIRIT_DEFINE(falsity, assume_consequent, for_all_consequent, exactly_one, consequent, consequents)
BOOST_SPIRIT_DEFINE(file_name, citation_text, include_item, fact_item, assume_item, rule_item, input_item, output_item, cite_item, prefer_item, threshold,
                    top_item, item_entry, atom_entry)

}  // namespace qm::engine::parser
