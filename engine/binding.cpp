// engine/binding.cpp
#include "engine/binding.hpp"
#include "qm/assert.hpp"

namespace qm::engine {

Evaluation evaluate(const CompiledTerm& term, const Binding& binding, ValueTable& values,
                    const BuiltinRegistry& builtins) {
    switch (term.kind) {
        case CompiledTerm::Kind::constant: return {term.constant, {}};
        case CompiledTerm::Kind::variable:
            QM_ASSERT(term.slot < binding.size(), "slot out of range");
            return {binding[term.slot], {}};
        case CompiledTerm::Kind::call: {
            std::vector<ValueId> args;
            args.reserve(term.args.size());
            for (const auto& a : term.args) {
                Evaluation e = evaluate(a, binding, values, builtins);
                if (!e.value) return e;
                args.push_back(*e.value);
            }
            BuiltinResult r = builtins.apply(term.function, values, args);
            if (!r.error.empty()) return {std::nullopt, std::move(r.error)};
            QM_ASSERT(r.value.has_value(), "a function builtin returned no value");
            return {r.value, {}};
        }
    }
    return {};
}

bool is_ground(const CompiledTerm& term, const Binding& binding) noexcept {
    switch (term.kind) {
        case CompiledTerm::Kind::constant: return true;
        case CompiledTerm::Kind::variable: return term.slot < binding.size() && binding[term.slot].has_value();
        case CompiledTerm::Kind::call:
            for (const auto& a : term.args)
                if (!is_ground(a, binding)) return false;
            return true;
    }
    return false;
}

}  // namespace qm::engine
