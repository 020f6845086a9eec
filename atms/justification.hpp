// atms/justification.hpp
// Provides:   Justification, a clause recorded by the ATMS with the opaque informant that says why it
//             holds (de Kleer 1986; BPS atms.lisp `just`). Two kinds:
//               horn         antecedents -> consequent (a Horn clause; the usual justification);
//               at_most_one  no two of the antecedents (assumption nodes) hold together: the
//                            contradiction follows from any two of their assumptions (not from a
//                            member node derived otherwise). It stands for the pairwise nogoods of
//                            a choice set (Atms::add_at_most_one), and it is not among any node's
//                            justifications() or consequences(): label propagation never sees it,
//                            the nogood database holds it as one constraint. Explanations use the
//                            clause of one pair, of the same kind with those two antecedents.
// Ownership:  stored by value inside Atms, referred to by JustId; never removed.
// Invariants: antecedents are distinct, none is the contradiction node; the consequent is not a
//             premise; an at_most_one clause concludes the contradiction and its antecedents are
//             assumption nodes.
// Knows nothing of rules: the informant is only an id chosen by the user.
#pragma once
#include "atms/ids.hpp"
#include <cstdint>
#include <vector>

namespace qm::atms {
struct Justification {
    enum class Kind : std::uint8_t { horn, at_most_one };
    InformantId informant;
    std::vector<NodeId> antecedents;  // distinct, in the order given (duplicates removed)
    NodeId consequent;
    Kind kind = Kind::horn;
};
}  // namespace qm::atms
