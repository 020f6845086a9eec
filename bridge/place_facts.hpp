// bridge/place_facts.hpp
// Provides:   the place-vocabulary half of the bridge from geometry to the engine: the functions
//             that assert a pair's places (PairPlaces, pair_places.hpp), the chain's parts and the current state as facts for the
//             laws of rules/clock/. Which geometric fact becomes which premise or assumption:
//
//   geometry                                         fact (premise unless said)
//   a pair P of parts A (axis q0) and B (axis q1)    (pair P A B); P is the symbol "A/B"
//   its configuration space's axis I (1 = q0, 2 = q1) (axis P I periodic) or (axis P I bounded)
//                                                     (a rotation's period, or a translation's
//                                                     limits / a window)
//   the ids of its places (choice set source)        (pair-places P {0 1 ...})        [states only]
//   a place's kind (Defs 28-32, 8.1.2; a stop: the   (place-kind P ID cseg|join|fsd|external-division|face|stop)
//     end of an axis, docs/PLACES.md)
//   a join's kind                                    (join-kind P ID normal-change|fsd-end|crossing|limit)
//   each normal into free space (CSEG, join, gap)    (place-normal P ID N), and all of them as
//                                                     (place-normals P ID {N ...})
//   a normal-change join's concavity (Defs 29-30)    (join-concave P ID) or (join-convex P ID)
//   a gap collapsed by 8.1.6                         (gap-place P ID)
//   an adjacency under the motion V = (mA mB)        (adjacent P ID NEXT V instant|interval|constrained)
//   a position-dependent force of CAUSE on part O    (force-sign-at P ID O S CAUSE), S its sign at
//     at the place (place_forces.hpp)                 the place: (+), (0) or (-)
//   a force not depending on position                (constant-force O S CAUSE)
//   places of two pairs sharing a part's coordinate   (places-apart P PLACE Q PLACE2)
//     that cover disjoint values of it (Def 34,       [states only; place_correlation.hpp]
//     place_correlation.hpp)
//   a part of the chain                              (clock-object O); a fixed one also (fixed-part O)
//   the motions a part may have (8.2.2)              (possible-motions O {(+) (0) (-)}) [states only]
//   two parts on one shaft (Def 21)                  (linkage A B)
//   a cause of external force                        (cause C)
//   an external force of CAUSE acting on part O      ASSUMPTION (external-force O CAUSE), so that a
//                                                     conclusion's label names the forces it rests on
//                                                     and a force can be taken away (--without)
//   the current state                                (current-place P ID), (current-motion O M): premises,
//                                                     or the motions as assumptions when one engine
//                                                     holds the states of one place vector
//
//             Signs and directions are the rule language's: (+) counter-clockwise or along the
//             axis. A place id is the place's index in the vocabulary, as `--places` prints it.
// Ownership:  the functions add facts to the engine given and keep nothing.
// Pre:        every function is called before the engine first runs a rule with `not` or an
//             aggregate (engine/engine.hpp: a closed world must not grow).
// Knows nothing of any law: rules/clock/ decides what the facts mean.
#pragma once
#include "bridge/pair_places.hpp"
#include "bridge/place_forces.hpp"
#include "geometry/cspace.hpp"
#include "engine/engine.hpp"
#include "geometry/mechanism.hpp"
#include "geometry/place_vocabulary.hpp"
#include "geometry/qualitative_sign.hpp"
#include <array>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace qm::bridge {

// Which of a pair's places to describe, and which adjacency.
struct PlaceFactOptions {
    std::optional<geometry::PlaceId> only;           // one place (the current one), else all
    std::optional<geometry::QualDirection> motion;   // only the adjacency under this motion
    bool choice = false;                             // also (pair-places P SET)
    bool kinds = true;                               // (place-kind ...), (join-kind ...)
    std::set<geometry::QualDirection> motions;       // with `motion` unset: only these (empty: all)
};

// (pair ...), (axis ...), the places' kind, normals, concavity, gaps, adjacency and force signs.
void assert_pair(engine::Engine& e, const geometry::Mechanism& m, const PairPlaces& pair, const PlaceFactOptions& options);

// (places-apart P PLACE Q PLACE2) for every two places of pairs p and q (distinct, sharing a part's
// coordinate) that cannot hold at once (place_correlation.hpp).
void assert_correlation(engine::Engine& e, const geometry::Mechanism& m, const PairPlaces& p, const PairPlaces& q);

// (clock-object O) for each part, (fixed-part O), and with `choices`, (possible-motions O ...).
void assert_parts(engine::Engine& e, const geometry::Mechanism& m, std::span<const geometry::PartId> parts, bool choices);
// (linkage A B) for consecutive parts of each shaft among `parts`.
void assert_linkages(engine::Engine& e, const geometry::Mechanism& m, std::span<const geometry::PartId> parts);
// (cause C) for every cause of a force on one of `parts`; (constant-force ...) for those forces;
// and (external-force O C) for every force on one of `parts` whose (part, cause) is not in `without`:
// an assumption (so that labels name the forces a conclusion rests on), or a premise when only the
// conclusions are wanted (an engine of premises alone runs without contexts), or not at all.
// Returns the facts asserted.
enum class ForceFacts { none, premises, assumptions };
struct ForceRef {
    geometry::PartId part{0};
    std::optional<std::string> cause;  // empty: every cause on the part
};
std::vector<engine::FactId> assert_forces(engine::Engine& e, const geometry::Mechanism& m,
                                          std::span<const geometry::PartId> parts, ForceFacts how,
                                          std::span<const ForceRef> without);
// (current-place P ID) and (current-motion O M), M one of "+", "0", "-".
void assert_current_place(engine::Engine& e, const PairPlaces& pair, geometry::PlaceId place);
void assert_current_motion(engine::Engine& e, const geometry::Mechanism& m, geometry::PartId part, int sign);
// (current-motion O M) as an assumption: one engine for several states (each a context).
engine::FactId assume_current_motion(engine::Engine& e, const geometry::Mechanism& m, geometry::PartId part, int sign);

// The rule language's one-sign direction for a sign (-1, 0, +1), and the pair direction.
[[nodiscard]] std::string sign_text(int sign);
[[nodiscard]] std::string direction_text(geometry::QualDirection d);

}  // namespace qm::bridge
