// engine/builtins_integer.hpp
// Provides:   small integer arithmetic for programs such as N-queens: functions `+`, `-` (binary, or
//             unary negation), `*`, `abs`, `min`, `max` (any totally ordered values), and the set
//             generator `(range lo hi)` = {lo, ..., hi} (at most 100000 elements).
// Errors:     non-integer arguments, overflow and oversized ranges are reported as builtin errors.
// Knows nothing of the ATMS or of mechanics.
#pragma once
#include "engine/builtin_registry.hpp"

namespace qm::engine {
void register_integer_builtins(BuiltinRegistry& r);
}
