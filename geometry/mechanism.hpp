// geometry/mechanism.hpp
// Provides:   Mechanism, the checked model of a metric scene (docs/METRIC_SCENE_FORMAT.md): its
//             parts (part.hpp), the settings of the geometry, the kinematic pairs the user named
//             (thesis 8.1, Figure 8.1 step 1), the linkages (parts sharing a shaft, 8.1.4, Def 21)
//             and the external forces, constant or depending on a part's position (8.2.1).
//             Also the lookups the later stages need: a part by name, the shaft of a part.
// Ownership:  a value type owning everything, including the source text, so that errors found
//             after reading (parts overlapping at a configuration) can still point at the line.
// Invariants: (established by read_mechanism, metric_scene_parser.hpp) part names are unique;
//             every PartId names a part; a pair names two different parts that are not both
//             fixed and not on one shaft; parts on one shaft have the same degree of freedom;
//             every tolerance is positive; angles are in radians.
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/fwd.hpp"
#include "geometry/metric_source.hpp"
#include "geometry/part.hpp"
#include "qm/diagnostics.hpp"
#include "qm/id.hpp"
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace qm::geometry {

// PartId (geometry/fwd.hpp) indexes Mechanism::parts.
struct MechanismSettings {
    double chordal_tolerance = 1e-4;      // arcs to chords, relative to each part's size
    double contact_tolerance = 1e-3;      // contact distance, relative to the smaller part's size
    double boundary_tolerance = 1e-8;     // bisection bracket: radians, or times the size for lengths
    double normal_zero_tolerance = 1e-6;  // unit-normal component taken as 0 (no flicker near an axis)
    double merge_epsilon = 0.0;           // 8.1.6 small irregularities, configuration units (0 = keep all)
    double gap_epsilon = 0.0;             // 8.1.6 gaps (play) narrower than this collapse, config. units
    std::array<int, 2> grid{64, 64};      // samples per configuration-space axis
};

// The finest settings accepted: a few hundred ulps above what double arithmetic resolves on a part of
// size 1 (bisection beyond them makes no progress; arcs would need millions of chords).
inline constexpr double min_chordal_tolerance = 1e-9;
inline constexpr double min_contact_tolerance = 1e-12;
inline constexpr double min_boundary_tolerance = 1e-13;
inline constexpr double min_normal_zero_tolerance = 1e-15;

// A window restricts a rotating part's configuration-space axis to [lo, hi] radians (not
// periodic): the region of interest, e.g. the anchor's swing. Its ends are `limit` joins.
struct AxisWindow {
    double lo = 0.0, hi = 0.0;
};

struct PairSpec {
    PartId a{0}, b{0};
    std::optional<std::array<int, 2>> grid;
    std::array<std::optional<AxisWindow>, 2> window;  // for a, for b
    SourceLocation where;
};

struct Linkage {
    std::vector<PartId> parts;  // >= 2, sharing one shaft (same pivot, or same axis)
    SourceLocation where;
};

struct ExternalForce {
    std::string cause;          // forces naming one cause cancel together (section 5)
    PartId part{0};
    enum class Kind { torque, push } kind = Kind::push;
    int torque_sign = 0;        // torque: +1 counter-clockwise, -1 clockwise
    Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // push: a fixed world direction (gravity)
    std::optional<Eigen::Vector2d> at;  // push: point of application on the part, as drawn
    std::optional<std::pair<double, double>> when;  // active only while the part's coordinate is in [lo, hi]
    SourceLocation where;
};

// A configuration of the whole mechanism: one coordinate per part (radians for a rotation, the
// offset along the axis for a translation, 0 for a fixed part); parts on one shaft share it.
struct Configuration {
    std::vector<double> q;  // indexed by PartId
    [[nodiscard]] double at(PartId p) const { return q[p.value]; }
};

struct Mechanism {
    std::string name;
    MechanismSettings settings;
    IdVector<PartId, Part> parts;
    std::vector<SourceLocation> part_where;  // indexed like parts
    std::vector<PairSpec> pairs;             // as declared (empty: pairs come from Def 20)
    bool pairs_declared = false;
    std::vector<Linkage> linkages;
    std::vector<ExternalForce> forces;
    std::optional<MetricSource> source;      // the text read, for located diagnostics later
    SourceLocation where;

    [[nodiscard]] std::optional<PartId> find_part(std::string_view name) const;
    // Index of the linkage holding p, if any.
    [[nodiscard]] std::optional<std::size_t> shaft_of(PartId p) const;
    // Do a and b turn or slide together (the same part, or one shaft)?
    [[nodiscard]] bool same_shaft(PartId a, PartId b) const;
    // Pre: where came from this mechanism's source (or the line is left empty).
    void error(Diagnostics& diags, const SourceLocation& where, std::string message) const;
};

}  // namespace qm::geometry
