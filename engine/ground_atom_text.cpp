// engine/ground_atom_text.cpp: one atom parsed by the rule grammar, then its constants interned.
#include "engine/ground_atom_text.hpp"
#include "engine/builtin_registry.hpp"
#include "engine/rule_parser.hpp"
#include <boost/variant/apply_visitor.hpp>

namespace qm::engine {
namespace {

struct Failure {
    std::string message;
    int offset = 0;
};

// The value of a constant term; a variable or a call is not ground.
struct ValueOf {
    ValueTable& values;
    using result_type = ValueId;
    ValueId operator()(const ast::Symbol& s) const { return values.symbol(s.text); }
    ValueId operator()(const ast::Integer& i) const { return values.integer(i.value); }
    ValueId operator()(const ast::Direction& d) const { return values.direction(d.signs); }
    ValueId operator()(const ast::Variable& v) const {
        throw Failure{"expected a constant but found the variable ?" + v.name + " (a fact is ground)", v.id_first};
    }
    ValueId operator()(const ast::Call& c) const {
        throw Failure{"expected a constant but found a call of '" + c.function.text + "' (a fact is ground)",
                      c.id_first};
    }
    ValueId operator()(const ast::Set& s) const {
        std::vector<ValueId> elements;
        for (const auto& e : s.elements) elements.push_back(boost::apply_visitor(*this, e));
        return values.set(std::move(elements));
    }
};

}  // namespace

GroundAtomParse parse_ground_atom(std::string_view text, ValueTable& values) {
    GroundAtomParse out;
    const SourceText src("--why", std::string(text));
    Diagnostics diagnostics;
    auto atom = parse_rule_atom(src, default_builtins(), diagnostics);
    if (!atom) {
        const Diagnostic& d = diagnostics.items().front();
        out.error = d.message;
        out.column = d.where.column;
        return out;
    }
    try {
        GroundAtom g{values.symbol(atom->predicate.text), {}};
        for (const auto& a : atom->args) g.args.push_back(boost::apply_visitor(ValueOf{values}, a));
        out.atom = std::move(g);
    } catch (const Failure& f) {
        out.error = f.message;
        out.column = src.locate(static_cast<std::size_t>(std::max(f.offset, 0))).column;
    }
    return out;
}

}  // namespace qm::engine
