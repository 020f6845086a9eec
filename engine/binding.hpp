// engine/binding.hpp
// Provides:   Binding, the values of a rule's variable slots during matching (unbound slots are
//             empty), and evaluate(), which computes a term's value under a binding.
// Ownership:  a value type, one per match in progress.
// Invariants: size() == the rule's slot_count.
// Knows nothing of the ATMS.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/compiled_rule.hpp"
#include <optional>
#include <string>
#include <vector>

namespace qm::engine {
using Binding = std::vector<std::optional<ValueId>>;

struct Evaluation {
    std::optional<ValueId> value;  // empty: an unbound variable was met, or a builtin failed
    std::string error;             // non-empty: a builtin failed (its error text)
};

// Pre: every slot of term is < binding.size(); every call in term is to a function builtin.
[[nodiscard]] Evaluation evaluate(const CompiledTerm& term, const Binding& binding, ValueTable& values,
                                  const BuiltinRegistry& builtins);
// True iff evaluate() would reach no unbound variable.
[[nodiscard]] bool is_ground(const CompiledTerm& term, const Binding& binding) noexcept;
}  // namespace qm::engine
