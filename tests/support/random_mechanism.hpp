// tests/support/random_mechanism.hpp
// Test helper (not a test): seeded random mechanisms, as a user might draw them (docs/
// METRIC_SCENE_FORMAT.md): a random polygon turning on a pivot, against a random polygon that
// slides towards it (even seeds) or swings on a pivot beside it (odd seeds), with or without a
// motor, a spring or gravity. Some drawings are refused by the geometry (parts that never touch,
// or overlap as drawn); the tests that use them skip those.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace qm::test {

// A star-shaped polygon about c: n vertices at sorted angles, radii in [r0, r1].
inline std::string random_polygon(std::mt19937& rng, double cx, double cy, double r0, double r1) {
    std::uniform_int_distribution<int> count(3, 7);
    std::uniform_real_distribution<double> turn(0.0, 2 * std::numbers::pi), radius(r0, r1);
    const int n = count(rng);
    std::vector<double> angles(static_cast<std::size_t>(n));
    for (auto& a : angles) a = turn(rng);
    std::sort(angles.begin(), angles.end());
    for (std::size_t i = 1; i < angles.size(); ++i)
        if (angles[i] - angles[i - 1] < 0.3) angles[i] = angles[i - 1] + 0.3;  // no sliver
    if (angles.back() - angles.front() > 2 * std::numbers::pi - 0.3) angles.pop_back();
    std::ostringstream os;
    os << "(polygon";
    for (const double a : angles) {
        const double r = radius(rng);
        os << " (" << std::round((cx + r * std::cos(a)) * 1000) / 1000 << ' ' << std::round((cy + r * std::sin(a)) * 1000) / 1000 << ')';
    }
    return os.str() + ")";
}

inline std::string random_mechanism_text(int seed) {
    std::mt19937 rng(static_cast<std::uint32_t>(seed));
    std::uniform_int_distribution<int> pick(0, 2);
    std::uniform_real_distribution<double> gap(0.1, 0.5);
    const double ra = 0.9, rb = 0.6;
    const double d = ra + rb + gap(rng);  // apart as drawn: the envelopes, not the drawings, meet
    const bool slider = seed % 2 == 0;
    std::ostringstream os;
    os << "(Defmechanism random-" << seed << "\n  Settings ((grid 48 48))\n  Parts ((rotor " << random_polygon(rng, 0, 0, 0.4, ra) << " (rotation))\n";
    if (slider)
        os << "         (block " << random_polygon(rng, d, 0, 0.25, rb) << " (translation (-1 0) (limits 0 " << d << ")))";
    else
        os << "         (lever " << random_polygon(rng, d - 0.3, 0, 0.25, rb) << " (rotation (" << d + 0.4 << " 0.9)))";
    os << ")\n  Pairs ((rotor " << (slider ? "block" : "lever (window lever -60 60)") << "))\n  Forces (";
    const int motor = pick(rng), other = pick(rng);
    if (motor != 0) os << "(motor rotor (torque " << (motor == 1 ? '+' : '-') << ")) ";
    if (slider && other != 0) os << "(spring block (direction " << (other == 1 ? "-1" : "1") << " 0))";
    if (!slider && other == 1) os << "(gravity lever (direction 0 -1))";
    if (!slider && other == 2) os << "(spring lever (torque -))";
    os << "))\n";
    return os.str();
}

}  // namespace qm::test
