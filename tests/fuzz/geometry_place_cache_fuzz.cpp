// tests/fuzz/geometry_place_cache_fuzz.cpp: PlaceCache::load on arbitrary file contents must
// report hit, miss, corrupt, stale or foreign, never crash or throw, and a file it serves must be
// sound: every adjacency names existing places, and the vocabulary stored again loads back equal.
// Input: one mode byte, then the file. Mode bit 0 reseals the file (its last line replaced by the
// checksum of the rest), so that the parser behind the checksum is fuzzed too; without it the
// checksum refuses nearly every mutation. The material (the key text) is the file's first line,
// so matching and foreign material both occur.
// Assertions are on in every object of a fuzz build, whatever its type (cmake/QmDefaults.cmake):
// BOOST_ASSERT guards Spirit's preconditions, QM_ASSERT the model's.
#include "geometry/place_cache.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

namespace g = qm::geometry;

bool same(const g::PlaceVocabulary& a, const g::PlaceVocabulary& b) {
    if (a.places.size() != b.places.size() || !(a.adjacency == b.adjacency)) return false;
    for (std::size_t i = 0; i < a.places.size(); ++i) {
        const auto &p = a.places[i], &q = b.places[i];
        // Points and extents may be NaN in a fuzzed file: compare their bits' text.
        if (p.id != q.id || p.kind != q.kind || p.join_kind != q.join_kind || p.normals != q.normals || p.concave != q.concave ||
            p.axis != q.axis || p.label != q.label || p.gap != q.gap || p.points.size() != q.points.size())
            return false;
    }
    return true;
}

std::string resealed(const std::string& text) {
    const std::size_t last = text.size() >= 2 ? text.rfind('\n', text.size() - 2) : std::string::npos;
    const std::string body = last == std::string::npos ? text + "\n" : text.substr(0, last + 1);
    return body + "checksum " + g::place_cache_checksum(body) + "\n";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path base =
        std::filesystem::temp_directory_path() / ("qm-place-cache-fuzz-" + std::to_string(::getpid()));
    static const g::PlaceCache cache(base / "in"), again(base / "again");
    if (size == 0) return 0;
    const bool reseal = (data[0] & 1) != 0;
    std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
    if (reseal) text = resealed(text);
    const std::string material = text.substr(0, text.find('\n'));
    std::filesystem::create_directories(cache.directory());
    std::ofstream(cache.path_for(material), std::ios::binary).write(text.data(), static_cast<std::streamsize>(text.size()));
    const auto loaded = cache.load(material);
    if (loaded.status == g::CacheStatus::miss) std::abort();  // the file is there
    if (loaded.status != g::CacheStatus::hit) {
        if (loaded.why.empty()) std::abort();  // a refusal says why
        return 0;
    }
    for (const auto& a : loaded.vocabulary.adjacency)
        if (a.from.value >= loaded.vocabulary.places.size() || a.to.value >= loaded.vocabulary.places.size()) std::abort();
    // What is served stores and loads back the same.
    if (!again.store(material, loaded.vocabulary)) std::abort();
    const auto round = again.load(material);
    if (round.status != g::CacheStatus::hit || !same(round.vocabulary, loaded.vocabulary)) std::abort();
    return 0;
}
