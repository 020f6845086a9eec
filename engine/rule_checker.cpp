// engine/rule_checker.cpp: predicate arity consistency and unique rule names over a ProgramSpec.
#include "engine/rule_checker.hpp"
#include <map>
#include <set>

namespace qm::engine {
namespace {

class Checker {
public:
    Checker(Diagnostics& diagnostics, const BuiltinRegistry& builtins) : diagnostics_(diagnostics), builtins_(builtins) {}

    // The first use of a predicate fixes its arity (as the thesis' relations have fixed places,
    // e.g. (contact ?a ?b) in Table 3.1); later uses must agree.
    void use(const AtomSpec& a, const char* hint = "") {
        if (auto id = builtins_.find(a.predicate); id && builtins_.get(*id).kind == BuiltinKind::test) {
            // A condition `(< ...)` always calls the test, so no fact of this "predicate" could be matched.
            ok_ = false;
            diagnostics_.error(a.where, "'" + a.predicate + "' is a builtin test, not a predicate" + hint);
            return;
        }
        auto [it, fresh] = first_use_.try_emplace(a.predicate, &a);
        if (fresh || it->second->args.size() == a.args.size()) return;
        ok_ = false;
        diagnostics_.error(a.where, "predicate '" + a.predicate + "' is used here with " + std::to_string(a.args.size()) +
                                        " argument(s) but with " + std::to_string(it->second->args.size()) +
                                        " at " + to_string(it->second->where));
    }

    void rule(const RuleSpec& r) {
        auto [it, fresh] = first_rule_.try_emplace(r.name, &r);
        if (!fresh) {
            ok_ = false;
            diagnostics_.error(r.where, "rule '" + r.name + "' is already defined at " + to_string(it->second->where));
        }
        for (const ConditionSpec& c : r.conditions) {
            switch (c.kind) {
                case ConditionSpec::Kind::atom:
                case ConditionSpec::Kind::aggregate: use(c.atom); break;
                case ConditionSpec::Kind::negation:
                    use(c.atom, ": `not` applies to atoms; write the opposite test instead");
                    break;
                case ConditionSpec::Kind::for_all:
                case ConditionSpec::Kind::exists:
                    for (const AtomSpec& a : c.atoms) use(a, ": put tests after `where`");
                    break;
                case ConditionSpec::Kind::test: break;
            }
        }
        for (const ConsequentSpec& c : r.consequents)
            if (c.kind != ConsequentSpec::Kind::falsity) use(c.atom);
    }

    // `prefer (c ?x ...) by (r ?x ... ?k)` (docs/RULES.md "Preferences"): c's arguments are distinct
    // variables; r's are those variables and one more, the rank, each once; one preference per c.
    // A warning where no `exactly one` assumes c: the preference chooses among c's choice sets.
    void preference(const PreferenceSpec& p, const std::set<std::string>& chosen) {
        use(p.choice);
        use(p.rank);
        auto fail = [&](const SourceLocation& where, const std::string& why) {
            ok_ = false;
            diagnostics_.error(where, "`prefer`: " + why);
        };
        std::set<std::string> choice_vars, rank_vars;
        for (const TermSpec& t : p.choice.args)
            if (t.kind != TermSpec::Kind::variable || !choice_vars.insert(t.text).second)
                return fail(t.where, "the chosen atom's arguments must be distinct variables, e.g. (" + p.choice.predicate +
                                         " ?x ?d)");
        std::vector<std::string> extra;
        for (const TermSpec& t : p.rank.args) {
            if (t.kind != TermSpec::Kind::variable || !rank_vars.insert(t.text).second)
                return fail(t.where, "the rank atom's arguments must be distinct variables");
            if (!choice_vars.contains(t.text)) extra.push_back(t.text);
        }
        for (const std::string& v : choice_vars)
            if (!rank_vars.contains(v))
                return fail(p.rank.where, "the rank atom must have every variable of the chosen atom, but has no ?" + v);
        if (extra.size() != 1)
            return fail(p.rank.where, "the rank atom must have exactly one variable that the chosen atom does not have "
                                      "(the rank), but has " + std::to_string(extra.size()));
        if (auto [it, fresh] = preferred_.try_emplace(p.choice.predicate, &p); !fresh)
            return fail(p.choice.where, "(" + p.choice.predicate + " ...) already has a preference at " + to_string(it->second->where));
        // A warning, not an error: such a preference chooses nothing (e.g. a few laws loaded alone,
        // their motions stated as inputs, as tests/rules/law_harness.hpp does).
        if (!chosen.contains(p.choice.predicate))
            diagnostics_.add({Severity::warning, p.choice.where,
                              "`prefer`: no `exactly one` assumes (" + p.choice.predicate +
                                  " ...): the preference chooses nothing, since it chooses among the members of choice sets",
                              {}, {}});
    }

    [[nodiscard]] bool ok() const { return ok_; }

private:
    Diagnostics& diagnostics_;
    const BuiltinRegistry& builtins_;
    std::map<std::string, const AtomSpec*> first_use_;
    std::map<std::string, const RuleSpec*> first_rule_;
    std::map<std::string, const PreferenceSpec*> preferred_;
    bool ok_ = true;
};

}  // namespace

bool check_program(const ProgramSpec& spec, Diagnostics& diagnostics, const BuiltinRegistry& builtins) {
    Checker checker(diagnostics, builtins);
    for (const AtomSpec& f : spec.facts) checker.use(f);
    for (const AtomSpec& a : spec.assumptions) checker.use(a);
    for (const AtomSpec& a : spec.inputs) checker.use(a);
    for (const AtomSpec& a : spec.outputs) checker.use(a);
    for (const RuleSpec& r : spec.rules) checker.rule(r);
    std::set<std::string> chosen;  // predicates some `exactly one` assumes
    for (const RuleSpec& r : spec.rules)
        for (const ConsequentSpec& c : r.consequents)
            if (c.kind == ConsequentSpec::Kind::exactly_one) chosen.insert(c.atom.predicate);
    for (const PreferenceSpec& p : spec.preferences) checker.preference(p, chosen);
    return checker.ok();
}

}  // namespace qm::engine
