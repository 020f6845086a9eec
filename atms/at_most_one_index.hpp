// atms/at_most_one_index.hpp
// Provides:   AtMostOneIndex, the at-most-one constraints of an ATMS: each is a set of assumptions
//             no two of which hold together, i.e. the S(S-1)/2 pairwise nogoods of an `exactly one`
//             choice set of S members kept as one constraint (its at-least-one half is the
//             interpretations' business: interpretations.hpp). other_member(a, set) answers,
//             without forming a pair, whether a set holds a member other than a of one of a's
//             constraints (so a set holding a holds two members of one): at the cost of what the
//             set lists, never of a walk through all members (members are stored sparsely,
//             environment.hpp).
// Ownership:  owns copies of the member sets; constraints are numbered densely from 0 in the order
//             added and never removed.
// Invariants: a constraint has at least two distinct members (smaller ones constrain nothing and
//             are not stored: add() returns nullopt); an assumption may be in several constraints.
// Knows nothing of nodes, labels or rules: an assumption is only an id.
#pragma once
#include "atms/environment.hpp"
#include "atms/ids.hpp"
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace qm::atms {
class AtMostOneIndex {
public:
    // Adds the constraint "at most one of members" (duplicates collapse) and returns its number,
    // or nullopt if it has fewer than two distinct members.
    std::optional<std::uint32_t> add(std::span<const AssumptionId> members);

    [[nodiscard]] bool empty() const noexcept { return members_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return members_.size(); }
    // The members of constraint c as a set. Pre: c < size().
    [[nodiscard]] const Environment& members(std::uint32_t c) const;
    // The constraints that have a as a member, in the order added.
    [[nodiscard]] std::span<const std::uint32_t> of(AssumptionId a) const noexcept {
        return a.value < of_.size() ? std::span<const std::uint32_t>(of_[a.value]) : std::span<const std::uint32_t>();
    }

    // Some constraint of a has a member other than a in the set (a itself may or may not be in it).
    [[nodiscard]] bool other_member(AssumptionId a, SparseWords set) const noexcept;

private:
    std::vector<Environment> members_;
    std::vector<std::vector<std::uint32_t>> of_;  // assumption -> constraints holding it
};
}  // namespace qm::atms
