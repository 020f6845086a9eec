// geometry/cspace_boundary.hpp
// Provides:   trace_boundary(): the contact boundary of a classified configuration space as
//             ordered chains of boundary points (marching squares over the sample grid, with
//             wrap on periodic axes). A chain is closed (a cycle) or ends where the boundary
//             leaves the domain of a translation axis.
// Ownership:  BoundaryChain holds indices into CSpaceResult::boundary; valid while that result is.
// Invariants: every boundary point belongs to exactly one chain; consecutive points share a cell.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/pair_oracle.hpp"
#include <vector>

namespace qm::geometry {

struct BoundaryChain {
    std::vector<int> points;  // indices into CSpaceResult::boundary, in order along the boundary
    bool closed = false;
};

// Pre: space.status == ok. The oracle resolves saddle cells (four crossings) by their centre.
[[nodiscard]] std::vector<BoundaryChain> trace_boundary(const PairOracle& oracle, const CSpaceResult& space);

}  // namespace qm::geometry
