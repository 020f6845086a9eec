// bridge/pair_places.hpp
// Provides:   the one place-vocabulary service of the commands and the envisioner:
//             - pair_places(): a kinematic pair's place vocabulary (Def 20; 8.1 Figure 8.1 steps
//               2-3), from the on-disk cache when the same pair and settings were computed before
//               (8.1.3: "Place vocabulary representations of kinematic pairs may be precomputed
//               ... and then stored"), else built and stored; the zero-play contact place when
//               the grid has no free face (docs/PLACES.md, "Zero play"). `--places`, `draw`,
//               `explore` and `envision` all take their places from here, so a place id names
//               the same place in each;
//             - mechanism_places(): every modelled pair, as an envisionment needs them (each must
//               constrain its parts);
//             - the cache's folder (--cache DIR, $QM_PLACE_CACHE, $XDG_CACHE_HOME, ~/.cache);
//             - a pair named on the command line as `A--B`, and the options of its
//               configuration-space picture (axes named after the parts, degrees for rotations).
// Ownership:  PairPlaces is a value type; its oracle, when kept, is shared and read only.
// Errors:     bad input, located at the pair: parts that overlap as drawn (worded as `--emit-def`
//             words it, bridge/scene_at_config.hpp); a part whose FCL model cannot be built (out of
//             memory; geometry/build_limits.hpp keeps models within bounds). mechanism_places()
//             also refuses a mechanism with no kinematic pair, a declared pair whose parts can
//             never touch or whose space is all free, and a pair with no free space that is not
//             drawn in contact. What the cache did besides a plain hit or store (a file refused and
//             replaced, a vocabulary not stored) is a located warning at the pair. A vocabulary
//             that cannot be built is an internal failure (InternalError).
// Knows no law.
#pragma once
#include "bridge/place_forces.hpp"
#include "geometry/cspace.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/fwd.hpp"
#include "geometry/mechanism.hpp"
#include "geometry/place_cache.hpp"
#include "geometry/place_vocabulary.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "qm/diagnostics.hpp"
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace qm::bridge {

struct PairPlaces {
    std::string name;                       // "A/B": the pair's symbol in facts and output
    geometry::PairSpec spec;                // its parts (a: axis q0, b: axis q1) and declaration
    geometry::PlaceRequest request;         // what the vocabulary was computed for (its axes: q0, q1)
    geometry::PlaceVocabulary vocabulary;
    PairForces forces;                      // position-dependent forces by place (PlaceOptions::forces)
    bool from_cache = false;
    bool no_place = false;  // no free face on the grid and not drawn in contact: no place at all
    std::shared_ptr<const geometry::FclPairOracle> oracle;  // PlaceOptions::oracle, else null
    std::optional<geometry::CSpaceResult> space;            // PlaceOptions::space, else empty
};

// What to compute besides the vocabulary. The FCL oracle is built only when something needs it:
// a cache miss, the contact place, the sampled space, parts within reach of each other as drawn.
struct PlaceOptions {
    const geometry::PlaceCache* cache = nullptr;  // null: compute every vocabulary
    bool space = false;   // the sampled space (a picture needs it; the cache does not keep it): computed, then stored
    bool oracle = false;  // keep the oracle (contacts at a place, the picture)
    bool forces = false;  // the forces by place (the envisioner's facts)
};

// The symbol of a pair of parts.
[[nodiscard]] std::string pair_symbol(std::string_view a, std::string_view b);

// Nothing when the parts overlap as drawn or a part's model cannot be built (the error is in `diags`).
[[nodiscard]] std::optional<PairPlaces> pair_places(const geometry::Mechanism& m, const geometry::PairSpec& pair,
                                                    const PlaceOptions& options, Diagnostics& diags);
// Every modelled pair (geometry/kinematic_pairs.hpp), in order; nothing after any error.
[[nodiscard]] std::optional<std::vector<PairPlaces>> mechanism_places(const geometry::Mechanism& m, const PlaceOptions& options,
                                                                      Diagnostics& diags);

// The default cache folder, or empty when no home is known.
[[nodiscard]] std::filesystem::path default_place_cache();
// The cache to use: none with --no-cache (use == false), else `dir`, else the default.
[[nodiscard]] std::optional<geometry::PlaceCache> open_place_cache(bool use, const std::optional<std::filesystem::path>& dir);

// The modelled pair named `A--B` (either order is not accepted: the first part is q0).
[[nodiscard]] std::optional<geometry::PairSpec> find_pair(const geometry::Mechanism& m, std::string_view text);
// Picture options: the title "MECH: A (across) x B (up)" and the axes' names and units.
[[nodiscard]] geometry::SvgOptions cspace_svg_options(const geometry::Mechanism& m, const geometry::PairSpec& pair, int width,
                                                      int height);

}  // namespace qm::bridge
