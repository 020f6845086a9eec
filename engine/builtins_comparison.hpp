// engine/builtins_comparison.hpp
// Provides:   the comparison tests `=`, `!=` (any two values; equality is identity of interned
//             values) and `<`, `<=`, `>`, `>=` (the total order of ValueTable::less, numeric on integers).
// Knows nothing of the ATMS or of mechanics.
#pragma once
#include "engine/builtin_registry.hpp"

namespace qm::engine {
void register_comparison_builtins(BuiltinRegistry& r);
}
