// envision/state_report.hpp
// Provides:   write_next() and write_previous(), the answers to "what happens next?" and "what could
//             have just happened?" (thesis 5.4, 11.2.1) for one state: the state with the forces
//             acting in it (each with its cause), the net forces, the steps the laws allow with every
//             pair's and object's options (transition_order.rules), and the transitions out; or the
//             transitions into it; and write_behaviour(), a described behaviour's path (5.4:
//             "Can a behavioral sequence occur?").
// Ownership:  writes to the stream given.
// Errors:     the laws failing on the state (they ran once already): diagnostics, false.
#pragma once
#include "envision/behaviour_query.hpp"
#include "envision/envisionment.hpp"
#include "envision/laws.hpp"
#include "envision/state_query.hpp"
#include <ostream>

namespace qm::envision {

[[nodiscard]] bool write_next(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e, const StateRef& s,
                              const EnvisionOptions& options, Diagnostics& diagnostics);
void write_previous(std::ostream& os, const Envisionment& e, const StateRef& s);
// The answer to a described behaviour (--path): the path found, each description at the state that
// matched it; or how far any path gets.
void write_behaviour(std::ostream& os, const Envisionment& e, const Behaviour& b, const BehaviourAnswer& answer);

}  // namespace qm::envision
