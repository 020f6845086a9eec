// tests/geometry/place_json_test.cpp: the JSON output parses and round-trips counts and fields.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/place_json.hpp"
#include "geometry/place_vocabulary_builder.hpp"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <doctest/doctest.h>
#include <sstream>

using namespace qm::geometry;

TEST_CASE("geometry/place_json: the vocabulary of the disk cam round-trips through a JSON parser") {
    const auto c = disk_cam_and_follower();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    req.external.push_back({0, 0.0, "force \"flips\""});
    const auto res = build_place_vocabulary(c.exact, req);
    std::stringstream ss;
    write_place_json(ss, req.cspace, res.vocabulary);
    boost::property_tree::ptree tree;
    REQUIRE_NOTHROW(boost::property_tree::read_json(ss, tree));
    CHECK(tree.get<std::string>("schema") == "qm-place-vocabulary/1");
    CHECK(tree.get_child("places").size() == res.vocabulary.places.size());
    CHECK(tree.get_child("adjacency").size() == res.vocabulary.adjacency.size());
    CHECK(tree.get_child("axes").front().second.get<bool>("periodic") == true);
    std::size_t k = 0;
    for (const auto& [key, place] : tree.get_child("places")) {
        const Place& p = res.vocabulary.places[k++];
        CHECK(place.get<unsigned>("id") == p.id.value);
        CHECK(place.get<std::string>("kind") == to_string(p.kind));
        CHECK(place.get_child("normals").size() == p.normals.size());
        if (p.kind == PlaceKind::external_division) CHECK(place.get<std::string>("label") == "force \"flips\"");
    }
    const auto& first = tree.get_child("adjacency").front().second;
    CHECK(first.get<unsigned>("from") == res.vocabulary.adjacency.front().from.value);
    CHECK(first.get<bool>("constrained") == res.vocabulary.adjacency.front().constrained);
}
