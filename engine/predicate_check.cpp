// engine/predicate_check.cpp: where each predicate's facts come from and where they are used
// (engine/predicate_check.hpp). Two fixed points over predicate names: forward, which rules can fire
// (a rule fires only if every atom it needs can hold); backward, which rules are used (from what
// drivers read back, from `prefer`'s ranks and from `false` and choice sets).
#include "engine/predicate_check.hpp"
#include "qm/spelling.hpp"
#include <map>
#include <set>
#include <string>
#include <vector>

namespace qm::engine {
namespace {

void warn(Diagnostics& d, const SourceLocation& where, std::string message) {
    d.add({Severity::warning, where, std::move(message), {}, {}});
}

// The atoms a rule's conditions read, and whether each must hold for the rule to fire (a `not`, an
// aggregate or a `for all` over a possibly empty set does not need any fact to hold).
struct Use {
    const AtomSpec* atom;
    bool needed;
};
std::vector<Use> uses(const RuleSpec& r) {
    std::vector<Use> out;
    for (const ConditionSpec& c : r.conditions) switch (c.kind) {
            case ConditionSpec::Kind::atom: out.push_back({&c.atom, true}); break;
            case ConditionSpec::Kind::negation:
            case ConditionSpec::Kind::aggregate: out.push_back({&c.atom, false}); break;
            case ConditionSpec::Kind::exists:
                for (const AtomSpec& a : c.atoms) out.push_back({&a, true});
                break;
            case ConditionSpec::Kind::for_all:
                for (const AtomSpec& a : c.atoms) out.push_back({&a, false});
                break;
            case ConditionSpec::Kind::test: break;
        }
    return out;
}

std::vector<std::string> concluded(const RuleSpec& r) {
    std::vector<std::string> out;
    for (const ConsequentSpec& c : r.consequents)
        if (c.kind != ConsequentSpec::Kind::falsity) out.push_back(c.atom.predicate);
    return out;
}

bool shapes_interpretations(const RuleSpec& r) {
    for (const ConsequentSpec& c : r.consequents)
        if (c.kind == ConsequentSpec::Kind::falsity || c.kind == ConsequentSpec::Kind::exactly_one) return true;
    return false;
}

std::string names(const std::set<std::string>& xs) {
    std::string out;
    std::size_t i = 0;
    for (const std::string& x : xs) out += (i++ ? ", '" : "'") + x + "'";
    return out;
}

class PredicateCheck {
public:
    PredicateCheck(const ProgramSpec& spec, Diagnostics& diagnostics, const BuiltinRegistry& builtins)
        : spec_(spec), d_(diagnostics) {
        for (const AtomSpec& a : spec.inputs) stated_.insert(a.predicate);
        for (const AtomSpec& a : spec.facts) stated_.insert(a.predicate);
        for (const AtomSpec& a : spec.assumptions) stated_.insert(a.predicate);
        for (const RuleSpec& r : spec.rules)
            for (const std::string& p : concluded(r)) concluders_[p].insert(r.name);
        for (std::uint32_t i = 0; i < builtins.size(); ++i)
            if (const Builtin& b = builtins.get(BuiltinId{i}); b.kind == BuiltinKind::test) tests_.insert(b.name);
    }

    bool run() {
        declarations(spec_.inputs, "input");
        declarations(spec_.outputs, "output");
        for (const AtomSpec& o : spec_.outputs) known(o, "read back by a driver (`output`)");
        for (const PreferenceSpec& p : spec_.preferences) {
            known(p.choice, "chosen among by `prefer`");
            known(p.rank, "ranking a `prefer`");
        }
        for (const RuleSpec& r : spec_.rules)
            for (const Use& u : uses(r)) known(*u.atom, "used in a condition of rule '" + r.name + "'");
        never_firing();
        if (!spec_.outputs.empty()) unused();
        return ok_;
    }

private:
    [[nodiscard]] bool is_known(const std::string& p) const { return stated_.contains(p) || concluders_.contains(p); }

    void declarations(const std::vector<AtomSpec>& atoms, const char* keyword) {
        for (const AtomSpec& a : atoms)
            for (const TermSpec& t : a.args)
                if (t.kind != TermSpec::Kind::variable) {
                    ok_ = false;
                    d_.error(t.where, std::string("`") + keyword + "` declares a predicate: write its arguments as variables, e.g. " +
                                          keyword + " (" + a.predicate + " ?x), not values");
                    break;
                }
    }

    // An unknown predicate is almost always a misspelling: no fact of it can ever exist.
    void known(const AtomSpec& a, const std::string& where_used) {
        // A builtin test's name as a predicate is rule_checker.hpp's error.
        if (is_known(a.predicate) || tests_.contains(a.predicate) || !reported_.insert(to_string(a.where)).second) return;
        ok_ = false;
        std::vector<std::string> candidates;
        for (const std::string& p : stated_) candidates.push_back(p);
        for (const auto& [p, rules] : concluders_) candidates.push_back(p);
        std::string hint = did_you_mean(a.predicate, candidates);
        if (hint.empty()) {
            hint = did_you_mean(a.predicate, tests_);
            if (!hint.empty()) hint.insert(hint.size() - 1, " (a builtin test)");
        }
        unknown_.insert(a.predicate);
        d_.error(a.where, "unknown predicate '" + a.predicate + "', " + where_used +
                              ": no rule concludes it, no fact or assumption states it and no `input` declares it" + hint);
    }

    // Forward: a predicate can hold if it is stated or concluded by a rule that can fire.
    void never_firing() {
        // An unknown predicate is already an error: taken as holding (as once its spelling is
        // fixed), so that its rule and those after it get no warning of their own.
        std::set<std::string> can_hold = stated_;
        can_hold.insert(unknown_.begin(), unknown_.end());
        std::vector<bool> fires(spec_.rules.size(), false);
        for (bool changed = true; changed;) {
            changed = false;
            for (std::size_t i = 0; i < spec_.rules.size(); ++i) {
                if (fires[i]) continue;
                bool all = true;
                for (const Use& u : uses(spec_.rules[i])) all = all && (!u.needed || can_hold.contains(u.atom->predicate));
                if (!all) continue;
                fires[i] = changed = true;
                for (const std::string& p : concluded(spec_.rules[i])) can_hold.insert(p);
            }
        }
        for (std::size_t i = 0; i < spec_.rules.size(); ++i) {
            if (fires[i]) continue;
            const RuleSpec& r = spec_.rules[i];
            dead_.insert(r.name);
            for (const Use& u : uses(r)) {
                const std::string& p = u.atom->predicate;
                if (!u.needed || can_hold.contains(p)) continue;
                if (unknown_.contains(p)) break;  // already an error
                warn(d_, u.atom->where, "rule '" + r.name + "' can never fire: no fact of '" + p +
                                            "' can hold, since it is concluded only by " +
                                            (concluders_[p].size() == 1 ? "rule " : "rules ") + names(concluders_[p]) +
                                            ", which can never fire either");
                break;
            }
        }
    }

    // Backward: a rule is used if it shapes the interpretations or concludes a used predicate; a
    // predicate is used if a driver reads it back or a used rule reads it.
    void unused() {
        std::set<std::string> read;
        for (const AtomSpec& o : spec_.outputs) read.insert(o.predicate);
        for (const PreferenceSpec& p : spec_.preferences) read.insert(p.rank.predicate);  // the query reads the ranks
        std::vector<bool> used(spec_.rules.size(), false);
        for (bool changed = true; changed;) {
            changed = false;
            for (std::size_t i = 0; i < spec_.rules.size(); ++i) {
                if (used[i]) continue;
                const RuleSpec& r = spec_.rules[i];
                bool u = shapes_interpretations(r);
                for (const std::string& p : concluded(r)) u = u || read.contains(p);
                if (!u) continue;
                used[i] = changed = true;
                for (const Use& x : uses(r)) read.insert(x.atom->predicate);
            }
        }
        for (std::size_t i = 0; i < spec_.rules.size(); ++i) {
            const RuleSpec& r = spec_.rules[i];
            if (used[i] || dead_.contains(r.name)) continue;
            std::set<std::string> what;
            for (const std::string& p : concluded(r)) what.insert(p);
            warn(d_, r.where, "rule '" + r.name + "' is unused: nothing reads what it concludes (" + names(what) +
                                  "): no used rule has a condition on it and no `output` declares it");
        }
    }

    const ProgramSpec& spec_;
    Diagnostics& d_;
    std::set<std::string> stated_;                             // inputs, facts, assumptions
    std::map<std::string, std::set<std::string>> concluders_;  // predicate -> rules concluding it
    std::set<std::string> tests_;
    std::set<std::string> unknown_, dead_, reported_;
    bool ok_ = true;
};

}  // namespace

bool check_predicates(const ProgramSpec& spec, Diagnostics& diagnostics, const BuiltinRegistry& builtins) {
    return PredicateCheck(spec, diagnostics, builtins).run();
}

}  // namespace qm::engine
