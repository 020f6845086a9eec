// envision/verify.hpp
// Provides:   verify(), the invariants every envisionment must keep, checked on the result from
//             the geometry's own description of the places (the adjacency, 8.1.3), not from the
//             laws that produced it (`envision --verify`, and the tests on every mechanism):
//             - a terminal state is a jam: every part still, and every part's definite net force
//               held, its motion along that force (alone, or with the parts on its shaft) into
//               blocked space at some pair's place (Law 2: the adjacency marks it constrained),
//               or with the pair's other part moving along its own definite force where that part
//               alone is free (the two pressed into each other at their contact);
//             - a state in which some part moves has a transition: a pair's motion that its place
//               does not block leads to a next place (the adjacency has one) or the state changes;
//             - a behavioural cycle can repeat: no part whose coordinate is bounded (an axis that is
//               not periodic in one of its pairs) moves one way in every state of it, and each
//               transient cycle has such a part;
//             - a possible rest is a state at rest.
// Ownership:  value types; reads the envisionment.
#pragma once
#include "envision/envisionment.hpp"
#include <string>
#include <vector>

namespace qm::envision {

// Every broken invariant, one sentence each naming the chain and state (empty: all hold).
[[nodiscard]] std::vector<std::string> verify(const geometry::Mechanism& m, const Envisionment& e);

}  // namespace qm::envision
