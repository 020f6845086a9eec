// engine/rule_printer.cpp: ProgramSpec -> text in the syntax of docs/RULES.md.
#include "engine/rule_printer.hpp"
#include "qm/assert.hpp"

namespace qm::engine {
namespace {

std::string join_terms(const std::vector<TermSpec>& terms) {
    std::string out;
    for (const TermSpec& t : terms) out += " " + print_term(t);
    return out;
}

std::string print_test(const TestSpec& test) { return "(" + test.name + join_terms(test.args) + ")"; }

// `?v in SET where T1 and T2:` shared by quantified conditions and consequents.
std::string binder(const std::string& variable, const TermSpec& set, const std::vector<TestSpec>& tests) {
    std::string out = "?" + variable + " in " + print_term(set);
    for (std::size_t i = 0; i < tests.size(); ++i) out += (i == 0 ? " where " : " and ") + print_test(tests[i]);
    return out + ":";
}

std::string print_condition(const ConditionSpec& c) {
    switch (c.kind) {
        case ConditionSpec::Kind::atom: return print_atom(c.atom);
        case ConditionSpec::Kind::test: return print_test(c.test);
        case ConditionSpec::Kind::negation: return "not " + print_atom(c.atom);
        case ConditionSpec::Kind::for_all:
        case ConditionSpec::Kind::exists: {
            std::string out = c.kind == ConditionSpec::Kind::for_all ? "[for all " : "[exists ";
            out += binder(c.variable, c.set, c.tests);
            for (std::size_t i = 0; i < c.atoms.size(); ++i) out += (i == 0 ? " " : " and ") + print_atom(c.atoms[i]);
            return out + "]";
        }
        case ConditionSpec::Kind::aggregate:
            return "[sum " + print_term(c.value) + " over " + print_atom(c.atom) + " with " + c.function + " start " +
                   print_term(c.start) + " as ?" + c.variable + "]";
    }
    QM_REQUIRE(false, "unknown kind");
    return {};
}

std::string print_consequent(const ConsequentSpec& c) {
    switch (c.kind) {
        case ConsequentSpec::Kind::atom: return print_atom(c.atom);
        case ConsequentSpec::Kind::falsity: return "false";
        case ConsequentSpec::Kind::assume: return "assume " + print_atom(c.atom);
        case ConsequentSpec::Kind::for_all: return "[for all " + binder(c.variable, c.set, c.tests) + " " + print_atom(c.atom) + "]";
        case ConsequentSpec::Kind::exactly_one:
            return "[exactly one " + binder(c.variable, c.set, c.tests) + " assume " + print_atom(c.atom) + "]";
    }
    QM_REQUIRE(false, "unknown kind");
    return {};
}

}  // namespace

std::string print_term(const TermSpec& term) {
    switch (term.kind) {
        case TermSpec::Kind::symbol: return term.text;
        case TermSpec::Kind::integer: return std::to_string(term.integer);
        case TermSpec::Kind::variable: return "?" + term.text;
        case TermSpec::Kind::direction: {
            std::string out = "(";
            for (std::size_t i = 0; i < term.text.size(); ++i) {
                if (i > 0) out += ' ';
                out += term.text[i];
            }
            return out + ")";
        }
        case TermSpec::Kind::call: return "(" + term.text + join_terms(term.args) + ")";
        case TermSpec::Kind::set: {
            std::string inner = join_terms(term.args);
            return "{" + (inner.empty() ? inner : inner.substr(1)) + "}";
        }
    }
    QM_REQUIRE(false, "unknown kind");
    return {};
}

std::string print_atom(const AtomSpec& atom) { return "(" + atom.predicate + join_terms(atom.args) + ")"; }

std::string print_program(const ProgramSpec& spec) {
    std::string out;
    for (const CitationSpec& c : spec.citations) out += "cite \"" + c.text + "\"\n";
    for (const AtomSpec& i : spec.inputs) out += "input " + print_atom(i) + "\n";
    for (const AtomSpec& o : spec.outputs) out += "output " + print_atom(o) + "\n";
    for (const AtomSpec& f : spec.facts) out += "fact " + print_atom(f) + "\n";
    for (const AtomSpec& a : spec.assumptions) out += "assume " + print_atom(a) + "\n";
    for (const PreferenceSpec& p : spec.preferences)
        out += "prefer " + print_atom(p.choice) + " by " + print_atom(p.rank) +
               (p.up_to ? " up to " + std::to_string(*p.up_to) : std::string()) + "\n";
    for (const RuleSpec& r : spec.rules) {
        out += "\nrule " + r.name + "\n  when";
        for (const ConditionSpec& c : r.conditions) out += " " + print_condition(c);
        out += "\n  then";
        for (const ConsequentSpec& c : r.consequents) out += " " + print_consequent(c);
        out += "\n";
    }
    return out;
}

}  // namespace qm::engine
