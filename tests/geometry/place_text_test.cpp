// tests/geometry/place_text_test.cpp: one line per place and per adjacency, in the thesis' notation.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/place_text.hpp"
#include "geometry/place_vocabulary_builder.hpp"

#include <doctest/doctest.h>
#include <sstream>

using namespace qm::geometry;

TEST_CASE("geometry/place_text: lists every place and every adjacency") {
    const auto c = two_disks();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    const auto v = build_place_vocabulary(c.exact, req).vocabulary;
    std::stringstream ss;
    write_place_text(ss, v);
    std::size_t places = 0, adjacent = 0, constrained = 0;
    for (std::string line; std::getline(ss, line);) {
        places += line.rfind("place ", 0) == 0;
        adjacent += line.rfind("(adjacent ", 0) == 0;
        constrained += line.find(" constrained") != std::string::npos;
    }
    CHECK(places == v.places.size());
    CHECK(adjacent == v.adjacency.size());
    std::size_t expected = 0;
    for (const auto& a : v.adjacency) expected += a.constrained;
    CHECK(constrained == expected);
    CHECK(expected > 0);  // some CSEG forbids some motion (Law 2)
}
