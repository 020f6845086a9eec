// support/qm/limit_reached.hpp
// Provides:   LimitReached, the exception a module throws when a resource limit its driver set is
//             reached (the ATMS' environment limit, the engine's fact limit, the envisioner's state
//             limit): a runaway program or scene stops there instead of running until the machine's
//             memory is gone.
//             It is bad input, not a bug: the command line reports it as
//             `error: fact limit 500000 reached while firing rule 'grow'; raise it with --max-facts`
//             and exits with 2 (cli/resource_limits.hpp).
// Why an exception: a limit can be reached deep inside an ATMS label update or an enumeration of
//             interpretations, which have no diagnostics to report into; unwinding to the driver is
//             the only way out that leaves nothing half-done visible.
// Contract:   an object that threw it (an Atms, an Engine, an analysis) may be left mid-update and
//             must not be used again, only destroyed. Modules on the way up may fill in `doing`
//             and `where` if still empty (the innermost one knows best) and rethrow.
// Ownership:  a value type.
#pragma once
#include "qm/diagnostics.hpp"
#include <cstddef>
#include <exception>
#include <optional>
#include <string>

namespace qm {

struct LimitReached : std::exception {
    enum class Kind { facts, environments, states };
    LimitReached(Kind k, std::size_t n) : kind(k), limit(n) {}
    Kind kind;
    std::size_t limit = 0;               // the limit that was reached
    std::string doing;                   // e.g. "firing rule 'grow'"; empty: not known
    std::optional<SourceLocation> where;  // what the work was about, e.g. the rule's location
    [[nodiscard]] const char* what() const noexcept override {
        return kind == Kind::facts ? "fact limit reached" : kind == Kind::environments ? "environment limit reached" : "state limit reached";
    }
};

// "fact", "environment" or "state", for messages.
[[nodiscard]] inline const char* limit_noun(LimitReached::Kind k) noexcept {
    return k == LimitReached::Kind::facts ? "fact" : k == LimitReached::Kind::environments ? "environment" : "state";
}

}  // namespace qm
