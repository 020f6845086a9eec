// atms/justification.hpp
// Provides:   Justification, a Horn clause antecedents -> consequent recorded by the ATMS, with the
//             opaque informant that says why it holds (de Kleer 1986; BPS atms.lisp `just`).
// Ownership:  stored by value inside Atms, referred to by JustId; never removed.
// Invariants: antecedents are distinct, none is the contradiction node; the consequent is not a
//             premise.
// Knows nothing of rules: the informant is only an id chosen by the user.
#pragma once
#include "atms/ids.hpp"
#include <vector>

namespace qm::atms {
struct Justification {
    InformantId informant;
    std::vector<NodeId> antecedents;  // distinct, in the order given (duplicates removed)
    NodeId consequent;
};
}  // namespace qm::atms
