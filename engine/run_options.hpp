// engine/run_options.hpp
// Provides:   RunOptions, what a driver may ask of one Engine::run or run_in_context beyond the
//             program: an optional bound on the work done, so that a driver running untrusted or
//             generated programs (the fuzz target, tests/fuzz/engine_rules_fuzz.cpp) always gets an
//             answer. A rule program can make the engine work for ever (a rule that counts up with
//             `+`) or for very long (a condition joining many facts, a choice set of 100000
//             elements, which needs a nogood for each of its 5 * 10^9 pairs).
//             EngineLimits, bounds for the whole life of an Engine (Engine::set_limits): the facts it
//             may hold and the environments its ATMS may intern, so that a runaway program stops
//             with qm::LimitReached (qm/limit_reached.hpp) instead of filling the memory.
// Ownership:  value types; the engine copies them.
// Invariants: the defaults ask for nothing: no limit (the command line sets its own,
//             cli/resource_limits.hpp).
// Knows nothing of the ATMS or of mechanics.
#pragma once
#include <cstddef>
#include <optional>

namespace qm::engine {
struct RunOptions {
    // The most steps one call may take. A step is one fact or set element tried by the matcher,
    // one rule firing, or one nogood a choice set needs between two of its assumptions. When the
    // next step would exceed it, the run stops where it is and reports a located error at the rule
    // it was working on; the facts, labels and nogoods found so far are sound (every label
    // environment derives its fact) but not complete. Unset: no limit.
    std::optional<std::size_t> max_steps;
};

struct EngineLimits {
    // The most facts the engine may hold (premises, assumptions and derived facts alike); interning
    // one more throws qm::LimitReached{facts}.
    std::optional<std::size_t> max_facts;
    // The most environments its ATMS may intern (labels, nogoods, interpretations and the unions
    // made on the way); one more throws qm::LimitReached{environments}.
    std::optional<std::size_t> max_environments;
};
}  // namespace qm::engine
