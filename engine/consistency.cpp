// engine/consistency.cpp
#include "engine/consistency.hpp"
#include <algorithm>

namespace qm::engine {

RefutingRule Refutations::cite(const Firing& f) const {
    RefutingRule out;
    if (f.kind == Firing::Kind::rule && f.rule) out.rule = e_.program().rules[*f.rule].name;
    if (f.where) out.where = *f.where;
    return out;
}

std::optional<RefutingRule> Refutations::of(atms::EnvId env) {
    atms::Atms& a = e_.atms();
    if (a.is_consistent(env)) return std::nullopt;
    const atms::Environment whole = a.env(env);  // a copy: the queries below may intern environments
    const auto nogoods = a.minimal_nogoods_within(whole);
    const atms::EnvId nogood = nogoods.empty() ? env : nogoods.front();
    if (const auto it = by_nogood_.find(nogood); it != by_nogood_.end()) return it->second;
    const atms::Environment within = a.env(nogood);
    auto holds = [&](atms::NodeId n) {
        const auto& label = a.label(n);
        return std::any_of(label.begin(), label.end(), [&](atms::EnvId l) { return a.env(l).subset_of(within); });
    };
    std::optional<RefutingRule> found;
    for (const atms::JustId j : a.justifications(a.contradiction())) {
        const auto& just = a.justification(j);
        if (std::all_of(just.antecedents.begin(), just.antecedents.end(), holds)) {
            found = cite(e_.firing(just.informant));
            break;
        }
    }
    if (!found) {  // a nogood of a constraint, not of a justification: its explanation's last step
        const atms::Explanation x = a.explain_nogood(nogood);
        for (auto it = x.steps.rbegin(); it != x.steps.rend() && !found; ++it)
            if (a.justification(*it).consequent == a.contradiction()) found = cite(e_.firing(a.justification(*it).informant));
        if (!found) found = RefutingRule{};
    }
    return by_nogood_.emplace(nogood, *found).first->second;
}

}  // namespace qm::engine
