// atms/ids.hpp
// Provides:   the strong ids of the ATMS (STYLE.md section 5): NodeId, AssumptionId, EnvId, JustId,
//             and the two ids the ATMS carries for its user without interpreting them: InformantId
//             (why a justification holds, e.g. a rule) and DatumId (what a node stands for).
// Ownership:  ids are plain values; each is issued densely from 0 by the Atms that owns the object.
// Invariants: an id is only meaningful for the Atms that issued it.
// Knows nothing of rules, facts or mechanics.
#pragma once
#include "qm/id.hpp"
#include <type_traits>

namespace qm::atms {
using NodeId = qm::Id<struct NodeTag>;
using AssumptionId = qm::Id<struct AssumptionTag>;
using EnvId = qm::Id<struct EnvTag>;
using JustId = qm::Id<struct JustTag>;
using InformantId = qm::Id<struct InformantTag>;  // opaque: the engine maps its rule ids here
using DatumId = qm::Id<struct DatumTag>;          // opaque user datum carried by each node

static_assert(!std::is_convertible_v<NodeId, EnvId>, "ids of different kinds must not mix");
static_assert(sizeof(EnvId) == 4, "ids are one 32-bit index");
}  // namespace qm::atms
