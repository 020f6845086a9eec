// geometry/place_cache.hpp
// Provides:   PlaceCache, place vocabularies stored on disk and reused across runs (8.1.3: "place
//             vocabulary representations of kinematic pairs may be precomputed ... and stored"),
//             keyed by a hash of the pair's geometry (PairOracle::fingerprint) and every setting of
//             the request; and build_or_load(), which consults the cache before computing.
// Ownership:  PlaceCache holds only a directory path; files are written whole then renamed, so a
//             reader never sees half a file. The full key text is stored and compared, so a hash
//             collision is a miss, not a wrong vocabulary.
// Knows nothing of the ATMS or the engine; never prints.
#pragma once
#include "geometry/pair_oracle.hpp"
#include "geometry/place_vocabulary.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include <filesystem>
#include <string>

namespace qm::geometry {

// The text that identifies a computation: geometry fingerprint plus all settings, exactly.
[[nodiscard]] std::string place_cache_material(const PairOracle& oracle, const PlaceRequest& request);
// 16 hex digits (FNV-1a, 64 bit) of the material.
[[nodiscard]] std::string place_cache_key(const std::string& material);

enum class CacheStatus { hit, miss, corrupt };

struct CacheLoad {
    CacheStatus status = CacheStatus::miss;
    PlaceVocabulary vocabulary;  // valid when status == hit
};

class PlaceCache {
public:
    explicit PlaceCache(std::filesystem::path directory) : dir_(std::move(directory)) {}
    [[nodiscard]] CacheLoad load(const std::string& material) const;
    // Returns false if the file could not be written (the cache is an optimisation only).
    bool store(const std::string& material, const PlaceVocabulary& vocabulary) const;
    [[nodiscard]] std::filesystem::path path_for(const std::string& material) const;

private:
    std::filesystem::path dir_;
};

struct CachedPlaces {
    PlaceStatus status = PlaceStatus::ok;
    std::string message;
    PlaceVocabulary vocabulary;
    bool from_cache = false;
};

// Load from the cache, else compute and store.
[[nodiscard]] CachedPlaces build_or_load(const PairOracle& oracle, const PlaceRequest& request, const PlaceCache& cache);

}  // namespace qm::geometry
