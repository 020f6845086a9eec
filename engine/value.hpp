// engine/value.hpp
// Provides:   ValueId and Value, the ground terms of the rule language: symbols, integers,
//             directions (a tuple of signs `(+ 0 -)`, a lone `?` sign is ambiguous) and finite sets.
// Ownership:  Values are interned by ValueTable (value_table.hpp); everything else refers to them by
//             ValueId, so comparing two ground terms is comparing two ids.
// Invariants: a direction's text holds only the characters + 0 - ?; a set's elements are sorted
//             by ValueTable::less and distinct.
// Knows nothing of the ATMS, of rules or of mechanics.
#pragma once
#include "engine/fwd.hpp"
#include "qm/id.hpp"
#include <cstdint>
#include <string>
#include <vector>

namespace qm::engine {
// ValueId: engine/fwd.hpp.
enum class ValueKind : std::uint8_t { symbol, integer, direction, set };

struct Value {
    ValueKind kind = ValueKind::symbol;
    std::int64_t integer = 0;        // kind integer
    std::string text;                // kind symbol: the name; kind direction: one char per sign
    std::vector<ValueId> elements;   // kind set: sorted, distinct
};

static_assert(sizeof(ValueId) == 4, "a value id is one 32-bit index");
}  // namespace qm::engine
