// atms/pareto_front.hpp
// Provides:   pareto_front(), the generic preference query behind "prefer the nearest": of
//             candidates (e.g. interpretations) each ranked by a vector of integers (one rank per
//             criterion, smaller is preferred), the positions of those that no other candidate
//             dominates, i.e. is ranked no worse by every criterion and better by one (a Pareto
//             preference, as clingo's asprin offers). Candidates with equal rank vectors are all
//             kept.
// Ownership:  a pure function.
// Complexity: O(n^2 k) for n candidates of k ranks (n is small where it is used: the states that
//             share a place vector).
// Knows nothing of what is ranked, nor of rules or mechanics.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace qm::atms {
// Pre: every rank vector has the same length. Returns positions in increasing order.
[[nodiscard]] std::vector<std::size_t> pareto_front(std::span<const std::vector<int>> ranks);
[[nodiscard]] std::vector<std::size_t> pareto_front(std::span<const std::vector<std::int64_t>> ranks);
}  // namespace qm::atms
