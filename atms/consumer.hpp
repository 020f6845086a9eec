// atms/consumer.hpp
// Provides:   Consumer, the one interface through which the ATMS calls out (the typed form of the
//             BPS enqueue procedure): a node's label became non-empty, an environment became nogood.
// Ownership:  the Atms holds registered consumers by pointer and does not own them; a consumer must
//             outlive the Atms or be removed with Atms::remove_consumer first.
// Reentrancy: events are queued during label propagation and delivered only after the operation that
//             caused them has finished, so a consumer may call any Atms member, including justify();
//             events caused by such calls are delivered after the current event, in FIFO order.
// Knows nothing of rules, patterns or mechanics.
#pragma once
#include "atms/ids.hpp"

namespace qm::atms {
class Consumer {
public:
    Consumer() = default;
    Consumer(const Consumer&) = delete;
    Consumer& operator=(const Consumer&) = delete;
    virtual ~Consumer() = default;
    // The label of `node` went from empty to non-empty (it now holds in some consistent environment).
    // Delivered on every such transition: a label emptied by nogoods and filled again fires again,
    // even when both happen inside one call (a nogood empties it and the same propagation refills
    // it), so a node whose label was non-empty before and after a call may be announced: treat
    // the event as idempotent. A label that fills and is emptied again inside one call is not
    // announced (at delivery it holds nowhere).
    virtual void label_became_nonempty(NodeId /*node*/) {}
    // `env` became a minimal nogood. Every superset of env is then also nogood (is_consistent false),
    // but only the minimal nogood is announced.
    virtual void environment_became_nogood(EnvId /*env*/) {}
};
}  // namespace qm::atms
