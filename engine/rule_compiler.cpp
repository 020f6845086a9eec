// engine/rule_compiler.cpp: ProgramSpec -> CompiledProgram (slots, builtins, binding checks).
#include "engine/rule_compiler.hpp"
#include "engine/predicate_check.hpp"
#include "engine/binding.hpp"
#include "engine/stratify_rules.hpp"
#include <set>
#include <utility>
#include <unordered_map>

namespace qm::engine {
namespace {

class RuleCompiler {
public:
    RuleCompiler(ValueTable& values, const BuiltinRegistry& builtins, Diagnostics& diagnostics)
        : values_(values), builtins_(builtins), diagnostics_(diagnostics) {}

    CompiledRule compile(const RuleSpec& spec) {
        rule_ = CompiledRule{};
        slots_.clear();
        bound_.clear();
        rule_.name = spec.name;
        rule_.where = spec.where;
        for (const auto& c : spec.conditions) rule_.conditions.push_back(condition(c));
        for (const auto& c : spec.consequents) rule_.consequents.push_back(consequent(c));
        return std::move(rule_);
    }

    // A ground term of a top-level fact: constants, and functions of constants evaluated now.
    std::optional<ValueId> ground(const TermSpec& t) {
        CompiledTerm c = term(t, true);
        // A variable anywhere (say inside a call) was reported by term(); there is nothing to evaluate.
        if (!is_ground(c, Binding{})) return std::nullopt;
        Evaluation e = evaluate(c, Binding{}, values_, builtins_);
        if (!e.error.empty()) diagnostics_.error(t.where, e.error);
        return e.value;
    }

private:
    void error(const SourceLocation& where, std::string message) { diagnostics_.error(where, std::move(message)); }

    Slot slot(const std::string& name) {
        auto [it, fresh] = slots_.emplace(name, static_cast<Slot>(rule_.slot_names.size()));
        if (fresh) rule_.slot_names.push_back("?" + name);
        return it->second;
    }
    bool is_bound(const std::string& name) const { return bound_.count(name) > 0; }

    CompiledTerm constant(ValueId v) {
        CompiledTerm c;
        c.kind = CompiledTerm::Kind::constant;
        c.constant = v;
        return c;
    }

    // must_be_bound: every variable must already be bound (else a located error).
    CompiledTerm term(const TermSpec& t, bool must_be_bound) {
        switch (t.kind) {
            case TermSpec::Kind::symbol: return constant(values_.symbol(t.text));
            case TermSpec::Kind::integer: return constant(values_.integer(t.integer));
            case TermSpec::Kind::direction:
                if (t.text.empty() || t.text.find_first_not_of("+0-?") != std::string::npos) {
                    error(t.where, "a direction is a non-empty list of the signs + 0 - ?");
                    return constant(values_.symbol("invalid-direction"));
                }
                return constant(values_.direction(t.text));
            case TermSpec::Kind::variable: {
                if (must_be_bound && !is_bound(t.text)) error(t.where, "variable ?" + t.text + " is used before it is bound");
                CompiledTerm c;
                c.kind = CompiledTerm::Kind::variable;
                c.slot = slot(t.text);
                return c;
            }
            case TermSpec::Kind::set: {
                std::vector<ValueId> elements;
                for (const auto& e : t.args) {
                    CompiledTerm c = term(e, true);
                    if (c.kind != CompiledTerm::Kind::constant) {
                        error(e.where, "a set literal holds constants only");
                        continue;
                    }
                    elements.push_back(c.constant);
                }
                return constant(values_.set(std::move(elements)));
            }
            case TermSpec::Kind::call: {
                CompiledTerm c;
                c.kind = CompiledTerm::Kind::call;
                for (const auto& a : t.args) c.args.push_back(term(a, true));
                auto id = resolve(t.text, BuiltinKind::function, t.args.size(), t.where);
                if (!id) return constant(values_.symbol("invalid-call"));
                c.function = *id;
                return c;
            }
        }
        return constant(values_.symbol("invalid-term"));
    }

    std::optional<BuiltinId> resolve(const std::string& name, BuiltinKind kind, std::size_t arity,
                                     const SourceLocation& where) {
        auto id = builtins_.find(name);
        const char* what = kind == BuiltinKind::test ? "test" : "function";
        if (!id) {
            error(where, std::string("unknown builtin ") + what + " '" + name + "'");
            return std::nullopt;
        }
        const Builtin& b = builtins_.get(*id);
        if (b.kind != kind) {
            error(where, "'" + name + "' is a builtin " + (b.kind == BuiltinKind::test ? "test" : "function") +
                             ", not a " + what);
            return std::nullopt;
        }
        if (arity < b.min_arity || arity > b.max_arity) {
            std::string expected = b.min_arity == b.max_arity ? std::to_string(b.min_arity)
                                                              : std::to_string(b.min_arity) + " to " + std::to_string(b.max_arity);
            error(where, "'" + name + "' takes " + expected + " argument(s), not " + std::to_string(arity));
            return std::nullopt;
        }
        return id;
    }

    CompiledAtom pattern(const AtomSpec& a, bool must_be_ground) {
        CompiledAtom out{values_.symbol(a.predicate), {}, a.where};
        for (const auto& t : a.args) out.args.push_back(term(t, must_be_ground));
        return out;
    }
    void bind_variables(const AtomSpec& a) {
        for (const auto& t : a.args)
            if (t.kind == TermSpec::Kind::variable) bound_.insert(t.text);
    }
    CompiledTest test(const TestSpec& t) {
        CompiledTest out;
        out.where = t.where;
        for (const auto& a : t.args) out.args.push_back(term(a, true));
        if (auto id = resolve(t.name, BuiltinKind::test, t.args.size(), t.where)) out.test = *id;
        return out;
    }

    CompiledCondition condition(const ConditionSpec& c) {
        CompiledCondition out;
        out.where = c.where;
        switch (c.kind) {
            case ConditionSpec::Kind::atom:
                out.kind = CompiledCondition::Kind::match;
                out.atom = pattern(c.atom, false);
                bind_variables(c.atom);
                break;
            case ConditionSpec::Kind::test:
                out.kind = CompiledCondition::Kind::test;
                // `(= ?x TERM)` with ?x unbound binds ?x.
                if (c.test.name == "=" && c.test.args.size() == 2 && c.test.args[0].kind == TermSpec::Kind::variable &&
                    !is_bound(c.test.args[0].text)) {
                    out.test.where = c.test.where;
                    out.test.test = *builtins_.find("=");
                    CompiledTerm v;
                    v.kind = CompiledTerm::Kind::variable;
                    v.slot = slot(c.test.args[0].text);
                    out.test.args.push_back(v);
                    out.test.args.push_back(term(c.test.args[1], true));
                    bound_.insert(c.test.args[0].text);
                } else {
                    out.test = test(c.test);
                }
                break;
            case ConditionSpec::Kind::negation:
                out.kind = CompiledCondition::Kind::negation;
                out.atom = pattern(c.atom, false);  // unbound variables are local to the `not`
                break;
            case ConditionSpec::Kind::for_all:
            case ConditionSpec::Kind::exists: {
                bool exists = c.kind == ConditionSpec::Kind::exists;
                out.kind = exists ? CompiledCondition::Kind::exists : CompiledCondition::Kind::for_all;
                out.set = term(c.set, true);
                if (is_bound(c.variable)) error(c.where, "quantified variable ?" + c.variable + " is already bound");
                out.slot = slot(c.variable);
                auto saved = bound_;
                bound_.insert(c.variable);
                for (const auto& t : c.tests) out.tests.push_back(test(t));
                for (const auto& a : c.atoms) {
                    out.atoms.push_back(pattern(a, !exists));  // a `for all` atom must be ground
                    if (exists) bind_variables(a);
                }
                if (!exists) bound_ = std::move(saved);
                break;
            }
            case ConditionSpec::Kind::aggregate: {
                out.kind = CompiledCondition::Kind::aggregate;
                out.atom = pattern(c.atom, false);
                out.start = term(c.start, true);
                auto saved = bound_;
                for (const auto& t : c.atom.args)
                    if (t.kind == TermSpec::Kind::variable && !is_bound(t.text)) out.local_slots.push_back(slot(t.text));
                bind_variables(c.atom);
                out.value = term(c.value, true);
                bound_ = std::move(saved);
                if (auto id = resolve(c.function, BuiltinKind::function, 2, c.where)) out.function = *id;
                out.slot = slot(c.variable);
                bound_.insert(c.variable);
                break;
            }
        }
        if (out.kind == CompiledCondition::Kind::negation || out.kind == CompiledCondition::Kind::aggregate)
            rule_.non_monotonic = true;
        return out;
    }

    CompiledConsequent consequent(const ConsequentSpec& c) {
        CompiledConsequent out;
        out.where = c.where;
        switch (c.kind) {
            case ConsequentSpec::Kind::atom:
                out.kind = CompiledConsequent::Kind::assert_atom;
                out.atom = pattern(c.atom, true);
                break;
            case ConsequentSpec::Kind::falsity: out.kind = CompiledConsequent::Kind::falsity; break;
            case ConsequentSpec::Kind::assume:
                out.kind = CompiledConsequent::Kind::assume_atom;
                out.atom = pattern(c.atom, true);
                break;
            case ConsequentSpec::Kind::for_all:
            case ConsequentSpec::Kind::exactly_one: {
                out.kind = c.kind == ConsequentSpec::Kind::for_all ? CompiledConsequent::Kind::for_all_assert
                                                                   : CompiledConsequent::Kind::exactly_one;
                out.set = term(c.set, true);
                if (is_bound(c.variable)) error(c.where, "quantified variable ?" + c.variable + " is already bound");
                out.slot = slot(c.variable);
                auto saved = bound_;
                bound_.insert(c.variable);
                for (const auto& t : c.tests) out.tests.push_back(test(t));
                out.atom = pattern(c.atom, true);
                bound_ = std::move(saved);
                break;
            }
        }
        return out;
    }

    ValueTable& values_;
    const BuiltinRegistry& builtins_;
    Diagnostics& diagnostics_;
    CompiledRule rule_;
    std::unordered_map<std::string, Slot> slots_;
    std::set<std::string> bound_;
};

}  // namespace

std::optional<LoadedProgram> compile_program(const ProgramSpec& spec, Diagnostics& diagnostics,
                                             const BuiltinRegistry& builtins) {
    std::size_t errors_before = diagnostics.size();
    LoadedProgram out;
    RuleCompiler compiler(out.values, builtins, diagnostics);
    auto ground_atoms = [&](const std::vector<AtomSpec>& atoms, std::vector<CompiledGroundAtom>& into) {
        for (const auto& a : atoms) {
            CompiledGroundAtom g{out.values.symbol(a.predicate), {}, a.where};
            bool ok = true;
            for (const auto& t : a.args) {
                if (t.kind == TermSpec::Kind::variable) {
                    diagnostics.error(t.where, "a top-level fact or assumption must be ground, but has ?" + t.text);
                    ok = false;
                    continue;
                }
                auto v = compiler.ground(t);
                if (!v) ok = false;
                else g.args.push_back(*v);
            }
            if (ok) into.push_back(std::move(g));
        }
    };
    ground_atoms(spec.facts, out.program.premises);
    ground_atoms(spec.assumptions, out.program.assumptions);
    for (const auto& r : spec.rules) out.program.rules.push_back(compiler.compile(r));
    // After the rules, so that a program's values are numbered as without its preferences. A
    // malformed preference is rule_checker.hpp's error: it is left out here.
    for (const PreferenceSpec& p : spec.preferences) {
        CompiledPreference c{out.values.symbol(p.choice.predicate), out.values.symbol(p.rank.predicate), {}, 0, p.up_to, p.where};
        auto position = [&](const std::string& variable) -> std::optional<std::uint32_t> {
            for (std::uint32_t i = 0; i < p.rank.args.size(); ++i)
                if (p.rank.args[i].kind == TermSpec::Kind::variable && p.rank.args[i].text == variable) return i;
            return std::nullopt;
        };
        bool ok = p.rank.args.size() == p.choice.args.size() + 1;
        for (const TermSpec& t : p.choice.args) {
            auto at = t.kind == TermSpec::Kind::variable ? position(t.text) : std::nullopt;
            ok = ok && at.has_value();
            if (at) c.key.push_back(*at);
        }
        std::vector<std::uint8_t> keyed(p.rank.args.size(), 0);
        for (std::uint32_t k : c.key) ok = ok && !std::exchange(keyed[k], std::uint8_t{1});
        for (std::uint32_t i = 0; i < keyed.size(); ++i)
            if (!keyed[i]) c.rank_at = i;
        if (ok) out.program.preferences.push_back(std::move(c));
    }
    out.program.stratum_count = stratify_rules(out.program, out.values, diagnostics);
    bool failed = false;
    for (std::size_t i = errors_before; i < diagnostics.size(); ++i)
        failed = failed || diagnostics.items()[i].severity == Severity::error;
    if (failed) return std::nullopt;
    return out;
}

}  // namespace qm::engine

// One file: the loader of rule_folder.hpp, which reads, checks and compiles.
#include "engine/rule_folder.hpp"

namespace qm::engine {
std::optional<LoadedProgram> load_program(const std::string& path, Diagnostics& diagnostics) {
    auto checked = load_rule_files(std::span<const std::string>(&path, 1), diagnostics);
    if (!checked) return std::nullopt;
    return std::move(checked->compiled);
}
}  // namespace qm::engine
