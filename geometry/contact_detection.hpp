// geometry/contact_detection.hpp
// Provides:   detect_contacts(), the contacts of a kinematic pair at one configuration (thesis
//             Def 19): FCL decides whether the parts are near (within the
//             tolerance, relative to the smaller part's size) or overlap beyond it; the exact
//             lines and arcs then give each contact's features: a surface (the point of a
//             segment, with its outward normal) or a convex corner (Def 18, with the normals of
//             its two sides). A concave corner is contact with both of its surfaces (2.4.1), a
//             smooth join is one surface, and two parallel edges lying on each other give a
//             contact at each end of their common stretch (a block on a table, Figure 2.3).
//             Also the qualitative pieces the Alex model needs: the origin direction from a
//             point to the part's centre of rotation (Def 17), and Def 25's test of whether a
//             corner can touch a surface, for corner-against-corner contact (3.1.1, Def 26).
// Ownership:  results are values.
// Invariants: in an ok result every contact's two points are within the tolerance of each
//             other; a corner feature's two side normals turn left (convex) by more than the
//             normal zero tolerance.
// Knows nothing of the ATMS or the engine; never prints.
#pragma once
#include "geometry/fcl_pair_oracle.hpp"
#include "geometry/qualitative_sign.hpp"
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace qm::geometry {

struct ContactRequest {
    double tolerance = 1e-3;              // contact distance, relative to the smaller part's size
    double normal_zero_tolerance = 1e-6;  // angle (radians) below which a join is smooth
};

enum class FeatureKind { surface, corner };

struct ContactFeature {
    FeatureKind kind = FeatureKind::surface;
    int profile = 0;
    int segment = 0;   // surface: the segment touched; corner: the segment that begins at the corner
    int previous = -1; // corner: the segment that ends at it
    Eigen::Vector2d point = Eigen::Vector2d::Zero();   // at the configuration, world coordinates
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();  // surface: outward unit normal at point
    std::array<Eigen::Vector2d, 2> sides{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};  // corner: outward normals (previous, segment)
    friend bool operator==(const ContactFeature& a, const ContactFeature& b) {
        return a.kind == b.kind && a.profile == b.profile && a.segment == b.segment;
    }
};

struct Contact {
    ContactFeature first, second;  // on the pair's first and second part
    double distance = 0.0;         // between the two points
};

enum class ContactStatus { ok, overlapping };

struct ContactResult {
    ContactStatus status = ContactStatus::ok;
    std::string message;            // why the configuration is refused (status != ok)
    std::vector<Contact> contacts;
    double tolerance = 0.0;         // the contact distance used (a length)
    double fcl_distance = 0.0;      // FCL's signed distance between the meshes (-1: colliding)
};

// Pre: request tolerances positive.
[[nodiscard]] ContactResult detect_contacts(const FclPairOracle& pair, const Eigen::Vector2d& q, const ContactRequest& request);
// True when the exact profiles of parts a and b at q are farther apart than the contact tolerance
// plus both meshes' chordal error: detect_contacts() would find them apart (no contact, no
// overlap), so its FCL models need not be built to know it. False says nothing.
[[nodiscard]] bool apart_beyond_contact(const Part& a, const Part& b, const Eigen::Vector2d& q, const ContactRequest& request,
                                        double chordal_tolerance);

// Def 17: the direction from `point` to the centre of rotation of `part` at coordinate q, each
// component 0 within `zero_length`; all zero when the part does not rotate.
[[nodiscard]] QualDirection origin_direction(const Part& part, double q, const Eigen::Vector2d& point, double zero_length);

// Def 17's origin direction as the laws read it at a contact whose normal lies along `normal`
// (a unit vector, either way along the normal line): Tables 3.1-3.3 use a surface's origin only
// to ask which way a rotation of its object turns the point of contact across that normal
// (Rotate-90 of the normal against the origin), the sign of the cross product of the origin and
// the normal. Where the qualitative directions leave that sign ambiguous (the two products of
// components have opposite signs) but the exact geometry decides it (|cross| above
// zero_tolerance times the origin's length), the origin's component whose product is the smaller
// is taken as 0, so the qualitative test gives the exact answer: section 7.3, "we must either know
// the center of rotation or postulate a few locations for this point at the time of
// representation" (here it is known); the liberal bias is for an ambiguity that remains.
// Otherwise (and for a part that does not turn) exactly origin_direction().
[[nodiscard]] QualDirection origin_direction_at_contact(const Part& part, double q, const Eigen::Vector2d& point,
                                                        const Eigen::Vector2d& normal, double zero_length, double zero_tolerance);

// Def 25 (as its prose reads, section 3.1.1): a corner can touch a surface whose outward normal
// lies in the intersection of the closed half planes of its sides' reverse normals.
[[nodiscard]] bool can_contact(const ContactFeature& corner, const Eigen::Vector2d& surface_normal, double zero_tolerance);

// Global index of a feature's segment across the part's profiles (for names).
[[nodiscard]] int global_segment(const Part& part, int profile, int segment);

}  // namespace qm::geometry
