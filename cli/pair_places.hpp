// cli/pair_places.hpp
// Provides:   what `--places`, `draw --place` and `explore` share (docs/METRIC_SCENE_FORMAT.md):
//             - pair_places(): one kinematic pair's place vocabulary exactly as `--places`
//               computes it, so place ids agree between the commands: from the on-disk cache
//               (8.1.3), or built when the sampled space is wanted (a picture needs it; the cache
//               does not keep it) and then stored; the zero-play contact place when the grid has
//               no free face (docs/PLACES.md);
//             - the cache's folder (--cache DIR, $QM_PLACE_CACHE, $XDG_CACHE_HOME, ~/.cache);
//             - the options of a pair's configuration-space picture (axes named after the parts,
//               degrees for rotations);
//             - a pair named on the command line as `A--B` (as the SVG files of `--places --svg`).
// Ownership:  PairPlaces owns its oracle and results.
// Errors:     a part whose FCL model cannot be built (out of memory; geometry/build_limits.hpp
//             keeps models within bounds, but memory may still run out) is a located error at the
//             pair; what the cache did besides a plain hit or store (a file refused and replaced, a
//             vocabulary not stored) a located warning at the pair (docs/PLACES.md). A vocabulary
//             that cannot be built is an internal failure (InternalError).
#pragma once
#include "geometry/cspace_svg.hpp"
#include "geometry/fcl_pair_oracle.hpp"
#include "geometry/mechanism.hpp"
#include "geometry/place_cache.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "qm/diagnostics.hpp"
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace qm::cli {

struct PairPlaces {
    std::unique_ptr<qm::geometry::FclPairOracle> oracle;
    qm::geometry::PlaceRequest request;
    qm::geometry::PlaceVocabulary vocabulary;
    std::optional<qm::geometry::CSpaceResult> space;  // when built here
    bool from_cache = false;
    bool no_place = false;  // no free face on the grid and not drawn in contact: no place at all
};

// The default cache folder, or empty when no home is known.
[[nodiscard]] std::filesystem::path default_place_cache();
// The cache to use: none with --no-cache (use == false), else `dir`, else the default.
[[nodiscard]] std::optional<qm::geometry::PlaceCache> open_place_cache(bool use, const std::optional<std::filesystem::path>& dir);

// Nothing when a part's model cannot be built (the error is in `diags`).
[[nodiscard]] std::optional<PairPlaces> pair_places(const qm::geometry::Mechanism& m, const qm::geometry::PairSpec& pair,
                                                    const std::optional<qm::geometry::PlaceCache>& cache, bool need_space, Diagnostics& diags);
// The pair's FCL oracle, or nothing with a located error when FCL cannot build a part's model.
[[nodiscard]] std::unique_ptr<qm::geometry::FclPairOracle> pair_oracle_or_error(const qm::geometry::Mechanism& m, const qm::geometry::PairSpec& pair,
                                                                             Diagnostics& diags);

// Picture options: the title "MECH: A (across) x B (up)" and the axes' names and units.
[[nodiscard]] qm::geometry::SvgOptions cspace_svg_options(const qm::geometry::Mechanism& m, const qm::geometry::PairSpec& pair, int width,
                                                          int height);

// The modelled pair named `A--B` (either order is not accepted: the first part is q0).
[[nodiscard]] std::optional<qm::geometry::PairSpec> find_pair(const qm::geometry::Mechanism& m, std::string_view text);

}  // namespace qm::cli
