// geometry/pair_oracle.hpp
// Provides:   PairOracle, the metric diagram of one kinematic pair seen from its configuration
//             space (thesis 4.1, 8.1.1): is a configuration blocked (the parts overlap), and which
//             way is free space at a contact configuration, taken from the parts' geometry.
// Ownership:  an interface; implementations own their geometry and must outlive every computation
//             that is handed a reference to them.
// Invariants: blocked() is a pure function of q; for a periodic axis it is periodic in that axis.
// Knows nothing of FCL, the ATMS or the engine: FCL-backed part models adapt to this interface.
#pragma once
#include <Eigen/Core>
#include <string>

namespace qm::geometry {

class PairOracle {
public:
    virtual ~PairOracle() = default;
    // True when the two parts overlap at configuration q = (q0, q1) (interior intersection;
    // touching is free).
    [[nodiscard]] virtual bool blocked(const Eigen::Vector2d& q) const = 0;
    // Direction in configuration space in which the parts separate fastest, at a configuration q
    // on (or within tolerance of) the contact boundary: the gradient of the separation distance.
    // Need not be normalised; zero if unknown.
    [[nodiscard]] virtual Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const = 0;
    // A stable text description of the geometry (shapes, pivots, axes) used as a cache key.
    [[nodiscard]] virtual std::string fingerprint() const = 0;
};

}  // namespace qm::geometry
