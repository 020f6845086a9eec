// geometry/detail/metric_checker.hpp (internal)
// Provides:   MetricChecker, the state and helpers of one check_mechanism() call, shared by its
//             stages: settings, pairs, linkages and forces (metric_scene_checker.cpp) and parts
//             (detail/metric_part_checker.cpp).
// Ownership:  references the caller's positions, source and diagnostics for the call.
#pragma once
#include "geometry/mechanism.hpp"
#include "geometry/metric_scene_ast.hpp"
#include "geometry/metric_source.hpp"
#include "qm/diagnostics.hpp"

#include <boost/variant/get.hpp>
#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace qm::geometry::detail {

using Node = boost::spirit::x3::position_tagged;
inline constexpr double degree = std::numbers::pi / 180;

inline std::string num(double x) {
    std::ostringstream os;
    os.precision(6);
    os << x;
    return os.str();
}

inline std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// A profile being built, with the AST node behind each segment (to locate segment problems).
struct DrawnProfile {
    Profile profile;
    const Node* item = nullptr;
    std::vector<const Node*> segment_nodes;
};

struct Checker {  // the checking of one metric scene
    const MetricPositions& pos;
    const MetricSource& src;
    Diagnostics& diags;
    bool ok = true;

    void error(const Node& n, std::string msg) {
        src.error(diags, pos.offset_of(n), std::move(msg));
        ok = false;
    }
    [[nodiscard]] SourceLocation where(const Node& n) const { return src.locate(pos.offset_of(n)); }
    // The number's value, or an error if it is not finite (X3 reads "inf" and "nan") or so large
    // that FCL's double arithmetic loses the scene's detail (its eigen-solvers stop converging).
    static constexpr double largest_magnitude = 1e9;
    double value(const mast::Number& n) {
        if (!std::isfinite(n.value)) {
            error(n, "expected a finite number");
            return 0.0;
        }
        if (std::abs(n.value) > largest_magnitude) {
            error(n, "expected a number of magnitude at most " + num(largest_magnitude) + ", not " + num(n.value));
            return 0.0;
        }
        return n.value;
    }
    std::optional<int> whole(const mast::Number& n, int lo, int hi, const std::string& what) {
        const double x = value(n);
        if (x != std::floor(x) || x < lo || x > hi) {
            error(n, what + " must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", not " + num(x));
            return std::nullopt;
        }
        return static_cast<int>(x);
    }
    Eigen::Vector2d point(const mast::Point& p) { return {value(p.x), value(p.y)}; }

    void settings(const mast::SettingsSection& s, MechanismSettings& out);
    void part(const mast::PartEntry& e, Mechanism& m);
    bool draw(const mast::PartItem& item, std::vector<DrawnProfile>& drawn);
    void linkages(const mast::LinkagesSection& s, Mechanism& m);
    void pairs(const mast::PairsSection& s, Mechanism& m);
    void forces(const mast::ForcesSection& s, Mechanism& m);
    // The parts against the build limits (build_limits.hpp): size, precision, chords.
    void limits(const Mechanism& m);
};

}  // namespace qm::geometry::detail
