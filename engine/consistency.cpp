// engine/consistency.cpp
#include "engine/consistency.hpp"

namespace qm::engine {

std::optional<RefutingRule> refuting_rule(Engine& e, atms::EnvId env) {
    if (e.atms().is_consistent(env)) return std::nullopt;
    const atms::Explanation x = e.atms().explain_nogood(env);
    RefutingRule out;
    // Steps come leaves first, so the last one justifies the contradiction.
    for (auto it = x.steps.rbegin(); it != x.steps.rend(); ++it) {
        const auto& just = e.atms().justification(*it);
        if (just.consequent != e.atms().contradiction()) continue;
        const Firing& f = e.firing(just.informant);
        if (f.kind == Firing::Kind::rule && f.rule) out.rule = e.program().rules[*f.rule].name;
        if (f.where) out.where = *f.where;
        break;
    }
    return out;
}

}  // namespace qm::engine
