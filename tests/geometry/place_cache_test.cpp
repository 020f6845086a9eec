// tests/geometry/place_cache_test.cpp: vocabularies round-trip exactly through the disk cache,
// any change of geometry or setting changes the key, and damaged files are reported, not trusted.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/place_cache.hpp"

#include <doctest/doctest.h>
#include <fstream>

using namespace qm::geometry;

namespace {
std::filesystem::path fresh_dir(const char* name) {
    auto d = std::filesystem::path(QM_BINARY_DIR) / "test-place-cache" / name;
    std::filesystem::remove_all(d);
    return d;
}
bool same(const PlaceVocabulary& a, const PlaceVocabulary& b) {
    if (a.places.size() != b.places.size() || a.adjacency != b.adjacency) return false;
    for (std::size_t i = 0; i < a.places.size(); ++i) {
        const auto &p = a.places[i], &q = b.places[i];
        if (p.id != q.id || p.kind != q.kind || p.normals != q.normals || p.concave != q.concave || p.axis != q.axis ||
            p.label != q.label || p.points != q.points || p.extent != q.extent || (p.kind == PlaceKind::join && p.join_kind != q.join_kind))
            return false;
    }
    return true;
}
}  // namespace

TEST_CASE("geometry/place_cache: a stored vocabulary loads back identical and is reused") {
    const auto c = disk_cam_and_follower();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    req.external.push_back({0, 0.5, "label with spaces\nand a newline"});
    const PlaceCache cache(fresh_dir("roundtrip"));
    const auto first = build_or_load(c.exact, req, cache);
    CHECK(!first.from_cache);
    const auto second = build_or_load(c.exact, req, cache);
    CHECK(second.from_cache);
    CHECK(same(first.vocabulary, second.vocabulary));
    CHECK(same(second.vocabulary, build_place_vocabulary(c.exact, req).vocabulary));
}

TEST_CASE("geometry/place_cache: the key covers geometry and every setting") {
    const auto c = two_disks();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    const auto base = place_cache_material(c.exact, req);
    auto changed = [&](auto edit) {
        auto r = req;
        edit(r);
        return place_cache_key(place_cache_material(c.exact, r)) != place_cache_key(base);
    };
    CHECK(changed([](PlaceRequest& r) { r.cspace.boundary_tolerance *= 0.5; }));
    CHECK(changed([](PlaceRequest& r) { r.cspace.axes[1].samples += 1; }));
    CHECK(changed([](PlaceRequest& r) { r.cspace.axes[0].hi = std::nextafter(r.cspace.axes[0].hi, 10.0); }));
    CHECK(changed([](PlaceRequest& r) { r.merge_epsilon = 1e-3; }));
    CHECK(changed([](PlaceRequest& r) { r.cspace.axes[1].stops = !r.cspace.axes[1].stops; }));
    CHECK(changed([](PlaceRequest& r) { r.external.push_back({1, 0.0, "g"}); }));
    CHECK(place_cache_key(place_cache_material(c.tessellated(1e-3), req)) != place_cache_key(place_cache_material(c.tessellated(2e-3), req)));
    CHECK(place_cache_key(base).size() == 16);
}

TEST_CASE("geometry/place_cache: damaged files are corrupt, foreign material is a miss") {
    const auto c = pin_in_slot();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    const PlaceCache cache(fresh_dir("damage"));
    const auto material = place_cache_material(c.exact, req);
    CHECK(cache.load(material).status == CacheStatus::miss);
    REQUIRE(cache.store(material, build_place_vocabulary(c.exact, req).vocabulary));
    CHECK(cache.load(material).status == CacheStatus::hit);
    std::filesystem::resize_file(cache.path_for(material), std::filesystem::file_size(cache.path_for(material)) / 2);
    CHECK(cache.load(material).status == CacheStatus::corrupt);
    // Same file name, different material (as after a hash collision): not used.
    std::ofstream(cache.path_for(material)) << "qm-place-cache/6\n5 other\n0 0\n";
    CHECK(cache.load(material).status == CacheStatus::miss);
    const auto again = build_or_load(c.exact, req, cache);
    CHECK(!again.from_cache);
    CHECK(build_or_load(c.exact, req, cache).from_cache);
}
