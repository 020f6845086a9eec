// tests/fuzz/geometry_place_cache_fuzz.cpp: PlaceCache::load on arbitrary file contents must
// report hit, miss or corrupt, never crash, and a hit must name only existing places.
#include "geometry/place_cache.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("qm-place-cache-fuzz-" + std::to_string(::getpid()));
    static const qm::geometry::PlaceCache cache(dir);
    // The material is the first line of the input, so matching and foreign material both occur.
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string material = text.substr(0, text.find('\n'));
    std::filesystem::create_directories(dir);
    std::ofstream(cache.path_for(material), std::ios::binary).write(text.data(), static_cast<std::streamsize>(text.size()));
    const auto loaded = cache.load(material);
    if (loaded.status == qm::geometry::CacheStatus::hit)
        for (const auto& a : loaded.vocabulary.adjacency)
            if (a.from.value >= loaded.vocabulary.places.size() || a.to.value >= loaded.vocabulary.places.size()) std::abort();
    return 0;
}
