// atms/choice_set_groups.hpp
// Provides:   ChoiceSetIndex, choice sets with the set of each member; group_by_shared_nogoods(),
//             which "members" (each a list of nodes, e.g. the nodes one part of a problem reads) and
//             which choice sets must be enumerated together: a member is tied to a set when a label
//             environment of one of its nodes needs one of that set's assumptions (beyond a base
//             environment, and otherwise only assumptions of the sets), and sets are tied to each
//             other when a stated minimal nogood spans them (beyond the base, only assumptions of the
//             sets). Groups are the connected parts of that relation (union-find): the interpretations
//             of one group's sets matter to its members only, so each group is enumerated apart.
// Ownership:  values; the Atms is borrowed for the call.
// Invariants: every member is in exactly one group; a member tied to no set is a group of its own
//             with no sets; a set tied to no member (directly or through other sets) is in no group.
//             Groups come back ordered by their first member; members and sets ascending in each.
// Coupling is read off stated nogoods only: the pairs of an at-most-one constraint (a choice set's
// own exclusivity, Atms::add_at_most_one) couple nothing.
// Knows nothing of what the members or sets stand for, nor of rules or mechanics.
#pragma once
#include "atms/atms.hpp"
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace qm::atms {

struct ChoiceSetIndex {
    std::vector<std::vector<AssumptionId>> sets;
    std::vector<std::optional<std::uint32_t>> set_of;  // by AssumptionId value: its index in sets
    [[nodiscard]] bool empty() const noexcept { return sets.empty(); }
    [[nodiscard]] std::optional<std::uint32_t> of(AssumptionId a) const {
        return a.value < set_of.size() ? set_of[a.value] : std::nullopt;
    }
};

// The index of `sets`, in the order given. Pre: no assumption is in two sets.
[[nodiscard]] ChoiceSetIndex index_choice_sets(std::vector<std::vector<AssumptionId>> sets);

struct ChoiceSetGroup {
    std::vector<std::size_t> members;  // indices into the members given, ascending
    std::vector<std::uint32_t> sets;   // indices into ChoiceSetIndex::sets, ascending
};

// Groups members[0..n) and the sets of `index` over `base` as the header says. With no sets, each
// member is a group of its own (and labels are not read). Pre: base and the nodes issued by atms.
[[nodiscard]] std::vector<ChoiceSetGroup> group_by_shared_nogoods(const Atms& atms, const ChoiceSetIndex& index,
                                                                  EnvId base,
                                                                  std::span<const std::vector<NodeId>> members);

}  // namespace qm::atms
