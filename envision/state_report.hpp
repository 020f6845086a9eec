// envision/state_report.hpp
// Provides:   write_next() and write_previous(), the answers to "what happens next?" and "what could
//             have just happened?" (thesis 5.4, 11.2.1) for one state: the state with the forces
//             acting in it (each with its cause), the net forces, the steps the laws allow with every
//             pair's and object's options (transition_order.rules), and the transitions out; or the
//             transitions into it.
// Ownership:  writes to the stream given.
// Errors:     the laws failing on the state (they ran once already): diagnostics, false.
#pragma once
#include "envision/envisionment.hpp"
#include "envision/laws.hpp"
#include "envision/state_query.hpp"
#include <ostream>

namespace qm::envision {

[[nodiscard]] bool write_next(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e, const StateRef& s,
                              const EnvisionOptions& options, Diagnostics& diagnostics);
void write_previous(std::ostream& os, const Envisionment& e, const StateRef& s);

}  // namespace qm::envision
