// scene/scene.hpp
// Provides:   Scene, the checked model of an Alex scene (thesis chapter 6, Figure 6.1): objects with
//             their surfaces (normal + direction to the centre of rotation, section 2.4) and
//             corners (section 3.1.1, Def 18), external translational/rotational constraint
//             patterns, scene-level forces with cause ids, linkages (Def 21), and the ordered
//             situations (contacts, forces, given motions). Also QueryFact, one fact named
//             on the command line (--why / --without).
// Ownership:  plain value types; a Scene owns everything in it. Ids index the Scene's own tables.
// Invariants: (established by check_scene, scene/scene_checker.hpp)
//             - names are lower case and unique per kind (objects; surfaces across the whole scene);
//             - every Direction has the arity its role needs: translations and origins have
//               `dimensions` signs, rotations 1 (2-D) or 3 (3-D, about x, y, z; Table 2.1);
//             - every surface belongs to exactly one object, listed in that object's `surfaces`;
//             - a corner's two sides are different faces (not corners) of its own object, and
//               every face has a lower SurfaceId than every corner (the printers rely on it);
//             - a linkage joins two different objects, and no pair is listed twice.
//             Equality (==) compares content and ignores source locations, so a scene read from
//             either notation, or re-read from its printed form, compares equal.
// Knows nothing of the ATMS, the rule engine or geometry.
#pragma once
#include "scene/fwd.hpp"
#include "qm/diagnostics.hpp"
#include "qm/id.hpp"
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace qm::scene {

// A qualitative sign (section 2.1, Definition 1): one place of a qualitative direction.
enum class Sign : std::int8_t { minus = -1, zero = 0, plus = 1 };

// A qualitative direction, Direction (scene/fwd.hpp), is a tuple of signs: a 2-D translation
// (x y), a 2-D rotation (r), ...

// One place of a constraint pattern: a fixed sign, or a variable `?x` matching any sign.
struct PatternSlot {
    std::optional<Sign> sign;  // empty <=> a variable
    std::string variable;      // the variable's name without '?', when sign is empty
    friend bool operator==(const PatternSlot&, const PatternSlot&) = default;
};

// True when every fixed place of `pattern` equals the same place of `d`.
// Pre: pattern.size() == d.size().
[[nodiscard]] bool matches(const DirectionPattern& pattern, const Direction& d);

// ObjectId, SurfaceId, CauseId (scene/fwd.hpp) index the Scene's own tables.

// A convex corner (Definition 18) where two of its object's surfaces meet: a surface of zero extent
// with an origin direction but no normal (section 3.1.1).
struct CornerSides {
    SurfaceId first, second;
    friend bool operator==(const CornerSides&, const CornerSides&) = default;
};

struct Surface {
    std::string name;
    ObjectId object;    // the owner
    Direction normal;   // outward surface normal, e.g. (0 +) for a top face; empty for a corner
    Direction origin;   // from the surface to the owner's centre of rotation; all-zero = none
    std::optional<CornerSides> corner;  // set <=> this is a corner (Corners section)
    SourceLocation where;
    [[nodiscard]] bool is_corner() const noexcept { return corner.has_value(); }
    friend bool operator==(const Surface& a, const Surface& b) {
        return a.name == b.name && a.object == b.object && a.normal == b.normal && a.origin == b.origin &&
               a.corner == b.corner;
    }
};

// Two objects that are one body in two kinematic pairs (Definition 21: parts on one shaft).
struct Linkage {
    ObjectId first, second;
    SourceLocation where;
    friend bool operator==(const Linkage& a, const Linkage& b) { return a.first == b.first && a.second == b.second; }
};

struct Object {
    std::string name;
    std::string description = "rigid-ob";              // Figure 6.1 <object descriptions>
    std::vector<SurfaceId> surfaces;                   // in source order
    std::vector<DirectionPattern> trans_constraints;   // Translational-Constraints entries
    std::vector<DirectionPattern> rot_constraints;     // Rotational-Constraints entries
    SourceLocation where;
    // Where the description and each constraint entry are written, for --why's citations; a
    // scene built in code may leave them out (then `where` stands for them).
    std::optional<SourceLocation> described_at;
    std::vector<SourceLocation> trans_constraints_at, rot_constraints_at;
    friend bool operator==(const Object& a, const Object& b) {
        return a.name == b.name && a.description == b.description && a.surfaces == b.surfaces &&
               a.trans_constraints == b.trans_constraints && a.rot_constraints == b.rot_constraints;
    }
};

// Forces that share a cause cancel against each other's feedback (section 5, same-cause
// cancellation). By default every force entry is its own cause; an entry may name its cause.
struct Cause {
    std::string name;     // the given name, or "force#N" (N = 1-based entry number) when implicit
    bool is_explicit = false;
    friend bool operator==(const Cause&, const Cause&) = default;
};

struct Force {
    ObjectId object;
    Direction direction;  // translational direction of the force
    Direction origin;     // from its point of application to the centre of rotation; zero = none
    CauseId cause;
    SourceLocation where;
    friend bool operator==(const Force& a, const Force& b) {
        return a.object == b.object && a.direction == b.direction && a.origin == b.origin && a.cause == b.cause;
    }
};

struct Contact {
    SurfaceId first, second;
    SourceLocation where;
    friend bool operator==(const Contact& a, const Contact& b) { return a.first == b.first && a.second == b.second; }
};

// A motion given as current (Figure 7.18: "the pallet is moving counter-clockwise").
struct Motion {
    ObjectId object;
    Direction translation;
    Direction rotation;
    SourceLocation where;
    friend bool operator==(const Motion& a, const Motion& b) {
        return a.object == b.object && a.translation == b.translation && a.rotation == b.rotation;
    }
};

// One configuration descriptor of Figure 6.1 (a state of Defstates).
struct Situation {
    std::vector<Contact> contacts;
    std::vector<Force> forces;   // active in this situation only
    std::vector<Motion> motions;
    SourceLocation where;
    friend bool operator==(const Situation& a, const Situation& b) {
        return a.contacts == b.contacts && a.forces == b.forces && a.motions == b.motions;
    }
};

struct Scene {
    std::string name;
    int dimensions = 2;  // 2 or 3
    IdVector<ObjectId, Object> objects;     // in Individuals order
    IdVector<SurfaceId, Surface> surfaces;  // in source order
    IdVector<CauseId, Cause> causes;
    std::vector<Force> forces;              // scene-level (globally active) forces
    std::vector<Linkage> linkages;          // Linkages section
    std::vector<Situation> situations;
    SourceLocation where;

    // The first entry of that name, by hash (a scan per lookup made reading a scene quadratic in
    // its size). Pre: an entry's name is not changed once it is in the table (the
    // index learns entries as they are added).
    [[nodiscard]] std::optional<ObjectId> find_object(std::string_view name) const;
    [[nodiscard]] std::optional<SurfaceId> find_surface(std::string_view name) const;
    [[nodiscard]] std::optional<CauseId> find_cause(std::string_view name) const;
    // Pre: s is a surface of this scene.
    [[nodiscard]] ObjectId owner(SurfaceId s) const;
    // Number of signs in a rotation: 1 in 2-D, 3 in 3-D (Table 2.1).
    [[nodiscard]] std::size_t rotation_arity() const noexcept { return dimensions == 3 ? 3 : 1; }
    [[nodiscard]] std::size_t translation_arity() const noexcept { return static_cast<std::size_t>(dimensions); }

    friend bool operator==(const Scene& a, const Scene& b);

    // The index behind find_*: the ids of the first `seen` entries of a table by name, extended
    // at each lookup with the entries added since.
    struct NameIndex {
        std::size_t seen = 0;
        std::unordered_map<std::string, std::uint32_t> ids;
    };
    mutable NameIndex object_index_, surface_index_, cause_index_;
};

// A single fact named on the command line: `Rotational-Motion (follower (-))`,
// `Translational-Freedom (block (0 +))`, `Contact a b`, `Force obj` (every force on obj), `Force obj
// CAUSE` (the force of that named cause on obj).
struct QueryFact {
    enum class Kind { translational_motion, rotational_motion, translational_freedom, rotational_freedom, contact, force };
    Kind kind = Kind::contact;
    std::optional<ObjectId> object;   // all kinds but contact
    Direction direction;              // the four motion/freedom kinds
    std::optional<SurfaceId> first, second;  // contact
    std::optional<CauseId> cause;     // force: only the force(s) of this cause; empty: every force on object
    friend bool operator==(const QueryFact&, const QueryFact&) = default;
};

// A force to add to a situation (`--with 'Force ...'`). Its cause is force.cause when the scene has
// it (a cause named by an entry); otherwise `new_cause` holds the cause to add to the scene, whose
// id the adder assigns.
struct AddedForce {
    Force force;
    std::optional<Cause> new_cause;
    friend bool operator==(const AddedForce&, const AddedForce&) = default;
};

// "+", "0" or "-".
[[nodiscard]] char sign_char(Sign s) noexcept;

}  // namespace qm::scene
