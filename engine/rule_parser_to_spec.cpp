// engine/rule_parser_to_spec.cpp: AST -> ProgramSpec, node by node.
#include "engine/rule_parser_to_spec.hpp"
#include "qm/assert.hpp"
#include <boost/variant/apply_visitor.hpp>

namespace qm::engine {
namespace {
namespace x3 = boost::spirit::x3;

SourceLocation at(const x3::position_tagged& node, const SourceText& src) {
    return src.locate(node.id_first < 0 ? 0 : static_cast<std::size_t>(node.id_first));
}

std::vector<TermSpec> terms(const std::vector<ast::Term>& ts, const SourceText& src) {
    std::vector<TermSpec> out;
    out.reserve(ts.size());
    for (const auto& t : ts) out.push_back(to_term_spec(t, src));
    return out;
}

struct TermVisitor {
    const SourceText& src;
    using result_type = TermSpec;
    TermSpec make(TermSpec::Kind kind, const x3::position_tagged& node) const {
        TermSpec t;
        t.kind = kind;
        t.where = at(node, src);
        return t;
    }
    TermSpec operator()(const ast::Symbol& s) const {
        TermSpec t = make(TermSpec::Kind::symbol, s);
        t.text = s.text;
        return t;
    }
    TermSpec operator()(const ast::Integer& i) const {
        TermSpec t = make(TermSpec::Kind::integer, i);
        t.integer = i.value;
        return t;
    }
    TermSpec operator()(const ast::Variable& v) const {
        TermSpec t = make(TermSpec::Kind::variable, v);
        t.text = v.name;
        return t;
    }
    TermSpec operator()(const ast::Direction& d) const {
        TermSpec t = make(TermSpec::Kind::direction, d);
        t.text = d.signs;
        return t;
    }
    TermSpec operator()(const ast::Call& c) const {
        TermSpec t = make(TermSpec::Kind::call, c);
        t.text = c.function.text;
        t.args = terms(c.args, src);
        return t;
    }
    TermSpec operator()(const ast::Set& s) const {
        TermSpec t = make(TermSpec::Kind::set, s);
        t.args = terms(s.elements, src);
        return t;
    }
};

TestSpec to_test_spec(const ast::Test& test, const SourceText& src) {
    return TestSpec{test.name.text, terms(test.args, src), at(test, src)};
}

std::vector<TestSpec> tests(const std::vector<ast::Test>& ts, const SourceText& src) {
    std::vector<TestSpec> out;
    for (const auto& t : ts) out.push_back(to_test_spec(t, src));
    return out;
}

struct ConditionVisitor {
    const SourceText& src;
    using result_type = ConditionSpec;
    ConditionSpec make(ConditionSpec::Kind kind, const x3::position_tagged& node) const {
        ConditionSpec c;
        c.kind = kind;
        c.where = at(node, src);
        return c;
    }
    ConditionSpec operator()(const ast::Atom& a) const {
        ConditionSpec c = make(ConditionSpec::Kind::atom, a);
        c.atom = to_atom_spec(a, src);
        return c;
    }
    ConditionSpec operator()(const ast::Test& t) const {
        ConditionSpec c = make(ConditionSpec::Kind::test, t);
        c.test = to_test_spec(t, src);
        return c;
    }
    ConditionSpec operator()(const ast::Negation& n) const {
        ConditionSpec c = make(ConditionSpec::Kind::negation, n);
        c.atom = to_atom_spec(n.atom, src);
        return c;
    }
    ConditionSpec quantified(ConditionSpec::Kind kind, const x3::position_tagged& node, const ast::Binder& b,
                             const std::vector<ast::Atom>& atoms) const {
        ConditionSpec c = make(kind, node);
        c.variable = b.variable.name;
        c.set = to_term_spec(b.set, src);
        c.tests = tests(b.tests, src);
        for (const auto& a : atoms) c.atoms.push_back(to_atom_spec(a, src));
        return c;
    }
    ConditionSpec operator()(const ast::ForAllCondition& f) const {
        return quantified(ConditionSpec::Kind::for_all, f, f.binder, f.atoms);
    }
    ConditionSpec operator()(const ast::ExistsCondition& e) const {
        return quantified(ConditionSpec::Kind::exists, e, e.binder, e.atoms);
    }
    ConditionSpec operator()(const ast::Aggregate& g) const {
        ConditionSpec c = make(ConditionSpec::Kind::aggregate, g);
        c.value = TermVisitor{src}(g.value);
        c.atom = to_atom_spec(g.atom, src);
        c.function = g.function.text;
        c.start = to_term_spec(g.start, src);
        c.variable = g.result.name;
        return c;
    }
};

struct ConsequentVisitor {
    const SourceText& src;
    using result_type = ConsequentSpec;
    ConsequentSpec make(ConsequentSpec::Kind kind, const x3::position_tagged& node) const {
        ConsequentSpec c;
        c.kind = kind;
        c.where = at(node, src);
        return c;
    }
    ConsequentSpec operator()(const ast::Atom& a) const {
        ConsequentSpec c = make(ConsequentSpec::Kind::atom, a);
        c.atom = to_atom_spec(a, src);
        return c;
    }
    ConsequentSpec operator()(const ast::Falsity& f) const { return make(ConsequentSpec::Kind::falsity, f); }
    ConsequentSpec operator()(const ast::Assume& a) const {
        ConsequentSpec c = make(ConsequentSpec::Kind::assume, a);
        c.atom = to_atom_spec(a.atom, src);
        return c;
    }
    ConsequentSpec quantified(ConsequentSpec::Kind kind, const x3::position_tagged& node, const ast::Binder& b,
                              const ast::Atom& atom) const {
        ConsequentSpec c = make(kind, node);
        c.variable = b.variable.name;
        c.set = to_term_spec(b.set, src);
        c.tests = tests(b.tests, src);
        c.atom = to_atom_spec(atom, src);
        return c;
    }
    ConsequentSpec operator()(const ast::ForAllConsequent& f) const {
        return quantified(ConsequentSpec::Kind::for_all, f, f.binder, f.atom);
    }
    ConsequentSpec operator()(const ast::ExactlyOne& e) const {
        return quantified(ConsequentSpec::Kind::exactly_one, e, e.binder, e.atom);
    }
};

struct ItemVisitor {
    const SourceText& src;
    ProgramSpec& spec;
    using result_type = void;
    void operator()(const ast::Include&) const { QM_REQUIRE(false, "an include is followed by the reader"); }
    void operator()(const ast::Fact& f) const { spec.facts.push_back(to_atom_spec(f.atom, src)); }
    void operator()(const ast::Assumption& a) const { spec.assumptions.push_back(to_atom_spec(a.atom, src)); }
    void operator()(const ast::Rule& r) const { spec.rules.push_back(to_rule_spec(r, src)); }
    void operator()(const ast::Input& i) const { spec.inputs.push_back(to_atom_spec(i.atom, src)); }
    void operator()(const ast::Output& o) const { spec.outputs.push_back(to_atom_spec(o.atom, src)); }
    void operator()(const ast::Cite& c) const { spec.citations.push_back(CitationSpec{c.text.text, at(c, src)}); }
    void operator()(const ast::Prefer& p) const {
        PreferenceSpec out{to_atom_spec(p.choice, src), to_atom_spec(p.rank, src), std::nullopt, at(p, src)};
        if (p.up_to) out.up_to = p.up_to->value;
        spec.preferences.push_back(std::move(out));
    }
};

}  // namespace

TermSpec to_term_spec(const ast::Term& term, const SourceText& src) {
    return boost::apply_visitor(TermVisitor{src}, term);
}

AtomSpec to_atom_spec(const ast::Atom& atom, const SourceText& src) {
    return AtomSpec{atom.predicate.text, terms(atom.args, src), at(atom, src)};
}

RuleSpec to_rule_spec(const ast::Rule& rule, const SourceText& src) {
    RuleSpec r;
    r.name = rule.name.text;
    r.where = at(rule, src);
    for (const auto& c : rule.conditions) r.conditions.push_back(boost::apply_visitor(ConditionVisitor{src}, c));
    for (const auto& c : rule.consequents) r.consequents.push_back(boost::apply_visitor(ConsequentVisitor{src}, c));
    return r;
}

void add_item_to_spec(const ast::Item& item, const SourceText& src, ProgramSpec& spec) {
    boost::apply_visitor(ItemVisitor{src, spec}, item);
}

}  // namespace qm::engine
