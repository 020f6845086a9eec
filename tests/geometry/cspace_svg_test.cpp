// tests/geometry/cspace_svg_test.cpp: the picture holds the shaded blocked samples, one circle per
// join and one number per place.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/place_vocabulary_builder.hpp"

#include <doctest/doctest.h>
#include <fstream>
#include <sstream>

using namespace qm::geometry;

namespace {
std::size_t occurrences(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
}
}  // namespace

TEST_CASE("geometry/cspace_svg: blocked samples, joins and place numbers are drawn") {
    const auto c = pin_in_slot();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    const auto res = build_place_vocabulary(c.exact, req);
    std::stringstream ss;
    write_cspace_svg(ss, res.space, res.vocabulary, {640, 480, "pin in slot", true});
    const std::string svg = ss.str();
    std::size_t blocked = 0;
    for (auto b : res.space.blocked) blocked += b;
    CHECK(occurrences(svg, "<rect x=") == blocked + 2);  // + the frame and its clip path
    CHECK(occurrences(svg, "<circle") == res.vocabulary.count(PlaceKind::join));
    for (const auto& p : res.vocabulary.places) {
        std::ostringstream label;
        label << '>' << p.id.value << "</text>";
        CHECK(svg.find(label.str()) != std::string::npos);
    }
    CHECK(svg.rfind("</svg>\n") == svg.size() - 7);
    std::ofstream(std::string(QM_BINARY_DIR) + "/pin_in_slot_cspace.svg") << svg;  // for inspection
}
