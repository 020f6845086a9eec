// engine/shared_program.cpp
#include "engine/shared_program.hpp"
#include <algorithm>

namespace qm::engine {

std::shared_ptr<const SharedProgram> share_program(CompiledProgram program) {
    auto out = std::make_shared<SharedProgram>();
    out->program = std::move(program);
    for (std::size_t i = 0; i < out->program.rules.size(); ++i) {
        const RuleId r{static_cast<std::uint32_t>(i)};
        // The predicates whose new facts can extend a match of the rule (Engine::drain wakes it for those).
        std::vector<ValueId> triggers;
        for (const auto& c : out->program.rules[r].conditions) {
            if (c.kind == CompiledCondition::Kind::match) triggers.push_back(c.atom.predicate);
            if (c.kind == CompiledCondition::Kind::for_all || c.kind == CompiledCondition::Kind::exists)
                for (const auto& a : c.atoms) triggers.push_back(a.predicate);
        }
        std::sort(triggers.begin(), triggers.end());
        triggers.erase(std::unique(triggers.begin(), triggers.end()), triggers.end());
        for (ValueId p : triggers) out->by_trigger[p.value].push_back(r);
        out->plans.push_back(plan_matching(out->program.rules[r]));
    }
    return out;
}

}  // namespace qm::engine
