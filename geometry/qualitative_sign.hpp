// geometry/qualitative_sign.hpp
// Provides:   QualDirection, a 2-tuple of signs in configuration space (thesis 2.1, Defs 1-4), the
//             tolerant sign of a real number, and the qualitative dot product (Table 2.2) used for
//             half-plane tests on places (4.2, 8.1.3).
// Ownership:  value types only.
// Invariants: every component is -1, 0 or +1.
// Knows nothing of the ATMS or the engine: the engine has its own copy of sign arithmetic as builtins.
#pragma once
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace qm::geometry {

struct QualDirection {
    std::array<std::int8_t, 2> s{0, 0};
    friend constexpr bool operator==(const QualDirection&, const QualDirection&) = default;
    friend constexpr auto operator<=>(const QualDirection&, const QualDirection&) = default;
};

// Sign of x, 0 when |x| <= zero_tolerance (so a component within tolerance of 0 never flickers).
[[nodiscard]] inline std::int8_t tolerant_sign(double x, double zero_tolerance) noexcept {
    if (std::abs(x) <= zero_tolerance) return 0;
    return x > 0 ? 1 : -1;
}

// Qualitative direction of v: components relative to |v|, zero within zero_tolerance.
[[nodiscard]] inline QualDirection qualitative(const Eigen::Vector2d& v, double zero_tolerance) noexcept {
    const double n = v.norm();
    if (n == 0.0) return {};
    return QualDirection{{tolerant_sign(v.x() / n, zero_tolerance), tolerant_sign(v.y() / n, zero_tolerance)}};
}

// Result of a qualitative dot product: a definite sign, or ambiguous when + and - terms meet.
enum class QualSign : std::int8_t { neg = -1, zero = 0, pos = 1, ambiguous = 2 };

// Table 2.2 sign sum of the component products.
[[nodiscard]] constexpr QualSign qdot(QualDirection a, QualDirection b) noexcept {
    bool pos = false, neg = false;
    for (int i = 0; i < 2; ++i) {
        const int p = a.s[i] * b.s[i];
        pos = pos || p > 0;
        neg = neg || p < 0;
    }
    if (pos && neg) return QualSign::ambiguous;
    if (pos) return QualSign::pos;
    if (neg) return QualSign::neg;
    return QualSign::zero;
}
static_assert(qdot(QualDirection{{1, 0}}, QualDirection{{1, 1}}) == QualSign::pos);
static_assert(qdot(QualDirection{{1, -1}}, QualDirection{{1, 1}}) == QualSign::ambiguous);
static_assert(qdot(QualDirection{{0, 1}}, QualDirection{{1, 0}}) == QualSign::zero);

[[nodiscard]] constexpr QualDirection negated(QualDirection d) noexcept {
    return QualDirection{{static_cast<std::int8_t>(-d.s[0]), static_cast<std::int8_t>(-d.s[1])}};
}

// "(+ 0)" in the thesis' notation.
[[nodiscard]] inline std::string to_string(QualDirection d) {
    auto c = [](std::int8_t x) { return x > 0 ? "+" : x < 0 ? "-" : "0"; };
    return std::string("(") + c(d.s[0]) + " " + c(d.s[1]) + ")";
}

}  // namespace qm::geometry
