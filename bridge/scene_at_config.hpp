// bridge/scene_at_config.hpp
// Provides:   the contacts half of the bridge from geometry to facts: the Alex scene model
//             (scene::Scene, thesis chapter 6) of a metric scene's parts at one configuration, built
//             directly from the geometry (no text is printed or read back): SceneAtConfig (the
//             pairs' collision models built once, for many configurations), scene_at_config() (one
//             configuration) and read_scene_at_config() (a file and a CONFIG text).
//             Which geometric fact becomes which scene item:
//
//   geometry (geometry/)                              scene item (scene/scene.hpp)
//   the mechanism                                     the scene: its name, 2 dimensions, one situation
//   a part, or the parts of one shaft (Def 21)        an Object (rigid-ob) named after the part (the
//                                                       shaft's first part in its linkage)
//   its degree of freedom                             its constraints: fixed (?x ?y) and (?r);
//                                                       rotating (?x ?y) (pinned: it only turns);
//                                                       sliding every translation except along its
//                                                       axis both ways, and except the way out past a
//                                                       limit it stands at, and (?r)
//   a contact of a kinematic pair at the configuration a Contact in the situation, between the two
//     (contact_detection.hpp, Def 19)                   features' surfaces
//   a feature that is a point of a segment            a Surface `<part>-s<k>` (segment k counted
//                                                       through the part's outlines): normal = the
//                                                       qualitative outward normal (Def 16); origin =
//                                                       the direction from the contact point to the
//                                                       part's pivot (Def 17), (0 0) if it does not
//                                                       turn, resolved against the contact's normal
//                                                       where the qualitative turn across it is
//                                                       ambiguous and the exact one is not
//                                                       (geometry::origin_direction_at_contact; 7.3,
//                                                       docs/LAWS.md "The metric and the symbolic
//                                                       routes"); `-2`, `-3` ... when one feature needs
//                                                       several qualitatively different surfaces
//   a convex corner (Def 18)                          a corner `<part>-c<k>` between its two sides
//                                                       (Surfaces with their normals), with its own
//                                                       origin direction (resolved likewise against
//                                                       the face it touches; not against another
//                                                       corner, Def 26); how it constrains (3.1.1,
//                                                       Defs 25-26) is rules/corners.rules' business
//   an external force acting at the configuration     a Force of the situation, with its cause (a
//     (external_force.hpp, 8.2.1)                       cause named twice is one cause): a torque s
//                                                       as the force (0 s) at origin (- 0) (applied
//                                                       right of the centre); a direction force as
//                                                       its qualitative direction, origin from its
//                                                       point of application to the pivot
//
//             Qualitative signs take a unit-normal component within the normal zero tolerance as 0,
//             and a length within the contact tolerance (times the part's size) as 0.
//             Locations: an object is located at its part's declaration, a surface and a contact
//             at the pair's declaration, a force at the force's, the scene and its situation at
//             the Defmechanism; so --why and warnings point into the metric scene.
// Invariants: the result satisfies scene/scene.hpp's invariants (the checker's): it equals the
//             scene that reading scene::print_scene(result) back gives (tests/bridge/).
// Errors:     parts overlapping at the configuration by more than the contact tolerance are bad
//             input: one error per pair, located at the pair, and no scene.
// Ownership:  results are values; SceneAtConfig owns its pairs' oracles and reads the mechanism,
//             which must outlive it.
// Knows nothing of the ATMS, the rule engine or the laws; never prints.
#pragma once
#include "bridge/fwd.hpp"
#include "geometry/mechanism.hpp"
#include "scene/scene.hpp"
#include "geometry/fcl_pair_oracle.hpp"
#include "qm/diagnostics.hpp"
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace qm::bridge {

class SceneAtConfig {
public:
    // The contacts of `pairs` are taken; empty: every modelled pair of the mechanism
    // (geometry::kinematic_pairs). A pair given is taken as it is (its envelopes are not checked).
    explicit SceneAtConfig(const geometry::Mechanism& m, std::vector<geometry::PairSpec> pairs = {});

    // The scene at q. `config_text` is what the configuration is called in messages (the CONFIG
    // as typed); empty: "as drawn".
    // Pre: q has one coordinate per part of the mechanism (parts on one shaft sharing it), as
    // geometry::parse_configuration gives.
    [[nodiscard]] std::optional<scene::Scene> at(const geometry::Configuration& q, Diagnostics& diags,
                                                 const std::string& config_text = {}) const;

private:
    const geometry::Mechanism& m_;
    std::vector<geometry::PairSpec> pairs_;
    std::vector<std::unique_ptr<geometry::FclPairOracle>> oracles_;  // one per pair
};

// SceneAtConfig(m).at(q, diags): one configuration, every modelled pair.
[[nodiscard]] std::optional<scene::Scene> scene_at_config(const geometry::Mechanism& m, const geometry::Configuration& q,
                                                          Diagnostics& diags);

// Reads the metric scene file `path` and CONFIG `config` (geometry/metric_scene_parser.hpp), then
// scene_at_config(). Errors (an unreadable file, a bad scene or CONFIG, overlapping parts) go to
// diags.
[[nodiscard]] std::optional<scene::Scene> read_scene_at_config(const std::string& path, const std::string& config, Diagnostics& diags);

}  // namespace qm::bridge
