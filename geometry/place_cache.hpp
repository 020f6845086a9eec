// geometry/place_cache.hpp
// Provides:   PlaceCache, place vocabularies stored on disk and reused across runs (8.1.3: "place
//             vocabulary representations of kinematic pairs may be precomputed ... and stored"),
//             keyed by a hash of the pair's geometry (PairOracle::fingerprint) and every setting of
//             the request; and build_or_load(), which consults the cache before computing and says
//             what the cache did.
// Ownership:  PlaceCache holds only a directory path.
// Invariants: a file is served (status hit) only if its last line is the checksum of everything
//             before it (so a truncated, damaged or edited file is refused: a flipped normal sign or
//             a changed adjacency target as much as random bytes), its first line is this format's,
//             its stored key text equals the request's exactly (a hash collision or a copied file is
//             not served), and the body parses completely into places and adjacencies that name
//             existing places. Writers write a file of their own and rename it over the entry, so
//             readers never see half a file and processes filling one cache at once leave one whole
//             file. The checksum guards against accidents, not against someone who recomputes it.
// Knows nothing of the ATMS or the engine; never prints.
#pragma once
#include "geometry/pair_oracle.hpp"
#include "geometry/place_vocabulary.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include <filesystem>
#include <string>
#include <string_view>

namespace qm::geometry {

// The text that identifies a computation: geometry fingerprint plus all settings, exactly.
[[nodiscard]] std::string place_cache_material(const PairOracle& oracle, const PlaceRequest& request);
// The same from the oracle's fingerprint alone (FclPairOracle::fingerprint_of: no meshes built).
[[nodiscard]] std::string place_cache_material(std::string_view fingerprint, const PlaceRequest& request);
// 16 hex digits (FNV-1a, 64 bit) of the material.
[[nodiscard]] std::string place_cache_key(const std::string& material);
// The checksum a cache file ends with (`checksum <16 hex digits>`): FNV-1a 64 of the text before it.
[[nodiscard]] std::string place_cache_checksum(std::string_view text);

enum class CacheStatus {
    hit,      // served: the stored vocabulary of this very computation
    miss,     // no file for this key
    corrupt,  // a file that is truncated, damaged, edited or not a place cache file at all
    stale,    // written by another version of the cache format
    foreign,  // a whole file of another computation under this key (a hash collision, a copied file)
};
[[nodiscard]] const char* to_string(CacheStatus s) noexcept;

struct CacheLoad {
    CacheStatus status = CacheStatus::miss;
    PlaceVocabulary vocabulary;  // valid when status == hit
    std::string why;             // what was wrong with the file (corrupt, stale, foreign)
};

struct CacheStore {
    bool stored = false;
    std::string why;  // why not (the folder or file could not be written, and the system's reason)
    explicit operator bool() const noexcept { return stored; }
};

class PlaceCache {
public:
    explicit PlaceCache(std::filesystem::path directory) : dir_(std::move(directory)) {}
    [[nodiscard]] CacheLoad load(const std::string& material) const;
    // The cache is an optimisation only: a failure to write is reported, never thrown.
    CacheStore store(const std::string& material, const PlaceVocabulary& vocabulary) const;
    [[nodiscard]] std::filesystem::path path_for(const std::string& material) const;
    [[nodiscard]] const std::filesystem::path& directory() const noexcept { return dir_; }

private:
    std::filesystem::path dir_;
};

struct CachedPlaces {
    PlaceStatus status = PlaceStatus::ok;
    std::string message;
    PlaceVocabulary vocabulary;
    bool from_cache = false;
    CacheStatus cache_status = CacheStatus::miss;  // what the load found
    bool stored = false;                           // the computed vocabulary was written
    // What the cache did, for the user, when it is not the plain hit or miss-and-store: a file
    // refused (and why) and computed again, or a vocabulary that could not be stored (and why).
    std::string note;
};

// Load from the cache, else compute and store (also over a refused file).
[[nodiscard]] CachedPlaces build_or_load(const PairOracle& oracle, const PlaceRequest& request, const PlaceCache& cache);
// The note for a vocabulary computed after `load` and then stored (or not) with `store`; empty when
// there is nothing to say (a plain miss, stored).
[[nodiscard]] std::string cache_note(const PlaceCache& cache, const std::string& material, const CacheLoad& load, const CacheStore& store);

}  // namespace qm::geometry
