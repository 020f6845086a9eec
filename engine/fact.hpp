// engine/fact.hpp
// Provides:   FactId and Fact, a ground atom `(predicate value...)` as the engine stores it.
// Ownership:  Facts are interned by FactStore (fact_store.hpp) and referred to by FactId.
// Invariants: predicate is a symbol value; a fact's identity is its predicate and arguments.
// Knows nothing of the ATMS: which node stands for a fact is the Engine's business.
#pragma once
#include "engine/fwd.hpp"
#include "engine/value.hpp"
#include <vector>

namespace qm::engine {

struct Fact {
    ValueId predicate;
    std::vector<ValueId> args;
};

static_assert(sizeof(FactId) == 4, "a fact id is one 32-bit index");
}  // namespace qm::engine
