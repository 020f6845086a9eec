// geometry/place_vocabulary.hpp
// Provides:   PlaceVocabulary, the symbolic places of one kinematic pair's configuration space
//             (thesis 4.2, 8.1.2): CSEGs (Def 28) with their qualitative normal into free space,
//             joins (Defs 29-30) with their normals and concavity, free space divisions (Def 31),
//             external place divisions (8.2.1, 9.2), full faces (Def 32) and stops (the free
//             stretches of an axis' limits where its part meets its frame); and Adjacent facts
//             (8.1.3) under every motion direction, flagged instantaneous or interval.
// Ownership:  a value type; places refer to each other by PlaceId (index into places).
// Invariants: places[k].id == PlaceId{k}; every adjacency names existing places.
// Knows nothing of the ATMS or the engine: the CLI turns places into facts.
#pragma once
#include "geometry/fwd.hpp"
#include "geometry/qualitative_sign.hpp"
#include "qm/id.hpp"
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace qm::geometry {

// PlaceId (geometry/fwd.hpp) names a place: its index in PlaceVocabulary::places.

// A stop is where an axis that ends (a translation's limits, a window's ends: CSpaceAxis::stops)
// borders free space: the part against its frame, blocked beyond as at a CSEG (Law 2), but a
// contact with the frame, not with the pair's other part, so no force passes between the two.
enum class PlaceKind { cseg, join, fsd, external_division, face, stop };
[[nodiscard]] const char* to_string(PlaceKind k) noexcept;

enum class JoinKind {
    normal_change,  // the CSEG normal changes qualitatively (a significant point, 8.1.2)
    fsd_end,        // an FSD ends on a CSEG
    crossing,       // two divisions cross
    limit,          // the boundary leaves the domain of a translation axis
};
[[nodiscard]] const char* to_string(JoinKind k) noexcept;

// An interval [lo, hi] of one coordinate; on a periodic axis it may reach past the axis' range,
// and stands for its copies a period apart.
struct Span {
    double lo = 0.0, hi = 0.0;
    friend bool operator==(const Span&, const Span&) = default;
};

struct Place {
    PlaceId id{0};
    PlaceKind kind = PlaceKind::face;
    std::vector<QualDirection> normals;  // CSEG, stop: one, into free space; join: those of the
                                         // CSEGs and stops meeting there
    std::optional<bool> concave;         // joins between two CSEGs: Def 29 (true) / Def 30 (false)
    JoinKind join_kind = JoinKind::normal_change;
    int axis = -1;                       // FSD / external division / stop: the axis it runs along
    std::string label;                   // external division: the force change it marks
    std::vector<Eigen::Vector2d> points; // CSEG/division: polyline in its direction (a division on a
                                         // periodic axis: points at most a quarter period apart, so
                                         // the way round is told); join: one point; face: one sample
    double extent = 0.0;                 // face: number of grid samples it covers
    std::array<std::vector<Span>, 2> covers;  // face: per axis, the values of that coordinate it
                                              // spans: its samples' and, beyond them, its bounding
                                              // places' (Def 34; detail/face_covers.cpp)
    bool gap = false;                    // face: 8.1.6, a gap narrower than the gap epsilon, collapsed
                                         // with the CSEGs bounding it (normals: theirs)
};

struct Adjacency {
    PlaceId from{0};
    PlaceId to{0};
    QualDirection motion;         // (motion of part 0, motion of part 1)
    bool instantaneous = false;   // the current place has zero width in this motion (8.1.3)
    bool constrained = false;     // motion into blocked space: the next place is the current one
    friend bool operator==(const Adjacency&, const Adjacency&) = default;
};

struct PlaceVocabulary {
    std::vector<Place> places;
    std::vector<Adjacency> adjacency;
    [[nodiscard]] std::size_t count(PlaceKind k) const;
    [[nodiscard]] const Place& at(PlaceId id) const { return places[id.value]; }
};

}  // namespace qm::geometry
