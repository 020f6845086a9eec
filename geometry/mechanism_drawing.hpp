// geometry/mechanism_drawing.hpp
// Provides:   what a drawing of a metric scene's parts at a configuration shows besides the
//             outlines (part_svg.hpp): the contacts of its kinematic pairs there (Def 19,
//             contact_detection.hpp) as marks with the surfaces' outward normals, named as
//             `--emit-def` names the features (<part>-s<k> a surface, <part>-c<k> a corner), and
//             the pairs whose parts overlap there (blocked configurations, drawn all the same:
//             seeing the overlap is the point).
// Ownership:  values; DrawnPart points into the Mechanism, which must outlive the result.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/contact_detection.hpp"
#include "geometry/mechanism.hpp"
#include "geometry/part_svg.hpp"
#include <vector>

namespace qm::geometry {

// The drawn parts at configuration q, in the order given.
[[nodiscard]] std::vector<DrawnPart> drawn_parts(const Mechanism& m, const Configuration& q, const std::vector<PartId>& drawn);

// The marks of one pair's contacts; `a` and `b` are the indices of its parts in the drawing.
[[nodiscard]] std::vector<ContactMark> contact_marks(const Mechanism& m, const PairSpec& pair, const ContactResult& r, std::size_t a,
                                                     std::size_t b);

struct MechanismContacts {
    std::vector<ContactMark> marks;
    std::vector<PairSpec> overlapping;  // pairs whose parts overlap at the configuration
};
// The contacts of every kinematic pair (kinematic_pairs.hpp) whose two parts are both drawn.
[[nodiscard]] MechanismContacts mechanism_contacts(const Mechanism& m, const Configuration& q, const std::vector<PartId>& drawn);

}  // namespace qm::geometry
