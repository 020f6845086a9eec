// envision/why_not.hpp
// Provides:   write_why_not(), the envisioner's answer to `--why-not 'STATE -> STATE'` (a question
//             only an ATMS answers): why the envisionment has no such transition.
//             - A side that is not a state: the minimal nogoods of the chain's state-space engine
//               that exclude it, each with the laws (rule, file:line, binding) and premises that
//               derive `false` (Law 2 at a place, a shaft, a fixed part, Def 34).
//             - Two states with no transition: for every step the first state may take, why none of
//               its hypotheses gives the second (a place the step does not reach, a collision's
//               outcome, a part that must change, a nearer state), and which steps preempt which;
//               then how the laws derived the first state's net forces and steps.
//             - A transition that exists: said so.
// Errors:     malformed or unknown states (located in the option's text); the laws failing.
#pragma once
#include "envision/envisionment.hpp"
#include <ostream>
#include <string>

namespace qm::envision {

[[nodiscard]] bool write_why_not(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e, const EnvisionOptions& options,
                                 const std::string& question, Diagnostics& diagnostics);

}  // namespace qm::envision
