// tests/geometry/part_svg_test.cpp: the drawing of parts read back as SVG: each part's outline,
// moved by its group's transform and the world transform, lands on the exact geometry placed at
// its coordinate (vertices, and every arc's radius, centre and sense); one scale on both axes;
// every part stays inside the drawing area anywhere along its motion; pivots and translation
// axes are marked where they are; contact marks point along the surfaces' outward normals and
// name their qualitative directions; the legend names the parts.
#include "geometry/part_svg.hpp"
#include "geometry/placed_part.hpp"
#include "mechanism_text.hpp"
#include "svg_tree.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <sstream>

using namespace qm::geometry;
using qm::geometry::test::parse_svg;
using qm::geometry::test::parse_transform;
using qm::geometry::test::path_vertices;
using qm::geometry::test::PathArc;
using qm::geometry::test::SvgElement;

namespace {

// A scape wheel (arcs and lines) turning about (0.3, -0.2) and a follower sliding along a tilted axis.
Mechanism scene() {
    return qm::geometry::test::read(
        "(Defmechanism drawn\n"
        "  Parts ((wheel (scape-wheel (teeth 7) (root-radius 0.85) (tip-radius 1.0) (lean 0.8) (root-land 0.2)) (at 0.3 -0.2) (rotation))\n"
        "         (slider (follower (width 1) (height 0.4)) (at 2 1) (translation (0.6 0.8) (limits -0.5 1.5)))))\n");
}

std::string drawing(const std::vector<DrawnPart>& parts, const std::vector<ContactMark>& contacts, int width = 640, int height = 480) {
    std::ostringstream os;
    write_parts_svg(os, parts, contacts, {width, height, "drawn", true, 1e-6});
    return os.str();
}

// The centre of an SVG arc from its ends, radius and flags, in a y-up frame.
Eigen::Vector2d arc_centre(const PathArc& a) {
    const Eigen::Vector2d m = 0.5 * (a.from + a.to), chord = a.to - a.from;
    const double h = 0.5 * chord.norm(), d = std::sqrt(std::max(0.0, a.radius * a.radius - h * h));
    const Eigen::Vector2d left = Eigen::Vector2d(-chord.y(), chord.x()).normalized();
    return m + (a.large != a.sweep ? 1.0 : -1.0) * d * left;
}

}  // namespace

TEST_CASE("geometry/part_svg: outlines, moved by their transforms, are the geometry at the configuration") {
    const Mechanism m = scene();
    const Part& wheel = m.parts[PartId{0}];
    const Part& slider = m.parts[PartId{1}];
    for (auto [qw, qs] : {std::pair{0.0, 0.0}, std::pair{0.7, 1.2}, std::pair{-2.5, -0.4}}) {
        CAPTURE(qw);
        const std::vector<DrawnPart> parts{{&wheel, qw}, {&slider, qs}};
        const auto svg = parse_svg(drawing(parts, {}));
        const SvgElement* world = svg->with_class("world");
        REQUIRE(world != nullptr);
        const Eigen::Affine2d W = parse_transform(world->attr("transform"));
        // One scale on both axes, y up.
        CHECK(W.linear()(0, 1) == doctest::Approx(0));
        CHECK(W.linear()(1, 0) == doctest::Approx(0));
        CHECK(W.linear()(1, 1) == doctest::Approx(-W.linear()(0, 0)));
        const double scale = W.linear()(0, 0);
        const auto groups = svg->all([](const SvgElement& e) { return e.has_class("part"); });
        REQUIRE(groups.size() == 2);
        for (std::size_t k = 0; k < 2; ++k) {
            const Part& part = *parts[k].part;
            CHECK(groups[k]->attr("data-part") == part.name);
            const Eigen::Affine2d T = W * parse_transform(groups[k]->attr("transform"));
            const PlacedPart placed = place(part, parts[k].q);
            std::vector<PathArc> arcs;
            const auto subpaths = path_vertices(groups[k]->named("path").front()->attr("d"), &arcs);
            REQUIRE(subpaths.size() == placed.profiles.size());
            std::size_t arc = 0;
            for (std::size_t i = 0; i < subpaths.size(); ++i) {
                const auto& segments = placed.profiles[i].segments;
                std::vector<Eigen::Vector2d> ends{segments.front().from};
                for (const auto& s : segments) ends.push_back(s.to);  // a whole-turn arc would add a half-way vertex
                REQUIRE(subpaths[i].size() == ends.size());
                for (std::size_t j = 0; j < ends.size(); ++j) CHECK((T * subpaths[i][j] - W * ends[j]).norm() < 1e-6);
                for (const auto& s : part.profiles[i].segments) {
                    if (!s.is_arc()) continue;
                    REQUIRE(arc < arcs.size());
                    CHECK(arcs[arc].radius == doctest::Approx(s.radius()));
                    CHECK(arcs[arc].sweep == s.ccw);
                    CHECK((arc_centre(arcs[arc]) - s.centre).norm() < 1e-7);
                    ++arc;
                }
            }
            CHECK(arc == arcs.size());
            if (k == 0) CHECK(arcs.size() >= 7);  // the wheel's root lands at least
        }
        // Pivot marked at the pivot; the slider's axis from its lower to its upper limit.
        const SvgElement* pivot = svg->with_class("pivot");
        REQUIRE(pivot != nullptr);
        const Eigen::Vector2d at = W * wheel.dof.pivot;
        CHECK(pivot->named("circle").front()->number("cx") == doctest::Approx(at.x()).epsilon(1e-4));
        CHECK(pivot->named("circle").front()->number("cy") == doctest::Approx(at.y()).epsilon(1e-4));
        const SvgElement* line = svg->with_class("translation-axis")->named("line").front();
        const Eigen::Vector2d a(line->number("x1"), line->number("y1")), b(line->number("x2"), line->number("y2"));
        CHECK((b - a).norm() == doctest::Approx(scale * (slider.hi - slider.lo)).epsilon(1e-3));
        CHECK((b - a).normalized().x() == doctest::Approx(0.6).epsilon(1e-3));
        CHECK((b - a).normalized().y() == doctest::Approx(-0.8).epsilon(1e-3));
    }
}

TEST_CASE("geometry/part_svg: the frame holds every part anywhere along its motion") {
    const Mechanism m = scene();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> turn(-std::numbers::pi, std::numbers::pi), slide(-0.5, 1.5);
    const std::vector<DrawnPart> as_drawn{{&m.parts[PartId{0}], 0.0}, {&m.parts[PartId{1}], 0.0}};
    const DrawingFrame f = parts_frame(as_drawn, {640, 480, "drawn", true, 1e-6});
    for (int k = 0; k < 50; ++k) {
        const std::vector<DrawnPart> parts{{&m.parts[PartId{0}], turn(rng)}, {&m.parts[PartId{1}], slide(rng)}};
        for (const auto& d : parts)
            for (const auto& profile : place(*d.part, d.q).profiles)
                for (const auto& s : profile.segments)
                    for (double t : {0.0, 0.25, 0.5, 0.75}) {
                        const Eigen::Vector2d p = f.pixel(s.point_at(t));
                        CHECK(p.x() >= 12 - 1e-9);
                        CHECK(p.x() <= 640 - 12 - 170 + 1e-9);  // left of the legend
                        CHECK(p.y() >= 32 - 1e-9);              // below the title
                        CHECK(p.y() <= 480 - 12 + 1e-9);
                    }
    }
}

TEST_CASE("geometry/part_svg: contact marks point along the outward normals and name them qualitatively") {
    const Mechanism m = scene();
    const std::vector<DrawnPart> parts{{&m.parts[PartId{0}], 0.0}, {&m.parts[PartId{1}], 0.0}};
    ContactMark c;
    c.point = {1.0, 0.5};
    c.parts = {0, 1};
    c.normals = {Eigen::Vector2d(0.6, -0.8), Eigen::Vector2d(0.0, 1.0)};
    c.note = "wheel-s3 against slider-c2 <corner>";
    ContactMark corner;  // corner against corner: no surface normal to draw
    corner.point = {1.2, 0.2};
    const auto svg = parse_svg(drawing(parts, {c, corner}));
    const Eigen::Affine2d W = parse_transform(svg->with_class("world")->attr("transform"));
    const auto marks = svg->all([](const SvgElement& e) { return e.has_class("contact"); });
    REQUIRE(marks.size() == 2);
    CHECK(marks[0]->named("title").front()->text == c.note);
    const auto dot = marks[0]->named("circle").front();
    const Eigen::Vector2d at = W * c.point;
    CHECK(dot->number("cx") == doctest::Approx(at.x()).epsilon(1e-4));
    CHECK(dot->number("cy") == doctest::Approx(at.y()).epsilon(1e-4));
    const auto lines = marks[0]->named("line");
    REQUIRE(lines.size() == 2);
    for (std::size_t k = 0; k < 2; ++k) {
        const Eigen::Vector2d d = Eigen::Vector2d(lines[k]->number("x2") - lines[k]->number("x1"), lines[k]->number("y2") - lines[k]->number("y1")).normalized();
        const Eigen::Vector2d want = (W.linear() * *c.normals[k]).normalized();
        CHECK((d - want).norm() < 1e-3);
    }
    CHECK(marks[1]->named("line").empty());
    std::multiset<std::string> names;
    for (const auto* t : svg->with_class("contacts")->named("text")) names.insert(t->text);
    CHECK(names == std::multiset<std::string>{"(+ -)", "(0 +)"});
    std::set<std::string> legend;
    for (const auto* t : svg->with_class("legend")->named("text")) legend.insert(t->text);
    for (const char* row : {"wheel (turns)", "slider (slides)", "pivot", "translation axis, limits", "contact, outward normal"})
        CHECK(legend.count(row) == 1);
}

TEST_CASE("geometry/part_svg: a part's transform is its pose") {
    const Mechanism m = scene();
    for (const Part* p : {&m.parts[PartId{0}], &m.parts[PartId{1}]})
        for (double q : {-1.0, 0.3, 2.0}) {
            const Eigen::Affine2d t = parse_transform(part_transform(*p, q));
            const Eigen::Isometry2d pose = p->pose(q);
            for (const Eigen::Vector2d& x : {Eigen::Vector2d(0, 0), Eigen::Vector2d(1.5, -0.7)}) CHECK((t * x - pose * x).norm() < 1e-8);
        }
}

TEST_CASE("geometry/part_svg: a moving part's arrow turns its way about the pivot or points its way along the axis") {
    const Mechanism m = scene();
    const Part& wheel = m.parts[PartId{0}];
    const Part& slider = m.parts[PartId{1}];
    CHECK(drawing({{&wheel, 0.3}, {&slider, 0.2}}, {}).find("class=\"motions\"") == std::string::npos);  // nothing moves
    auto points = [](const std::string& text) {
        std::vector<Eigen::Vector2d> out;
        std::istringstream in(text);
        for (std::string pair; in >> pair;) {
            const auto comma = pair.find(',');
            out.emplace_back(std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1)));
        }
        return out;
    };
    for (int sign : {1, -1}) {
        for (auto [qw, qs] : {std::pair{0.0, 0.0}, std::pair{2.0, 1.1}}) {
            CAPTURE(sign);
            CAPTURE(qw);
            const auto svg = parse_svg(drawing({{&wheel, qw, sign}, {&slider, qs, -sign}}, {}));
            const SvgElement* motions = svg->with_class("motions");
            REQUIRE(motions != nullptr);
            CHECK(motions->attr("transform") == svg->with_class("world")->attr("transform"));
            const auto arrows = motions->all([](const SvgElement& e) { return e.has_class("motion"); });
            REQUIRE(arrows.size() == 2);
            for (const SvgElement* a : arrows) {
                const bool turning = a->attr("data-part") == "wheel";
                const int s = turning ? sign : -sign;
                CHECK(a->attr("data-motion") == (s > 0 ? "+" : "-"));
                // In the world: the head's tip, and the direction from the head's base to it.
                const Eigen::Affine2d T = parse_transform(a->attr("transform"));
                const auto head = points(a->named("polygon").front()->attr("points"));
                REQUIRE(head.size() == 3);
                const Eigen::Vector2d tip = T * head[0], base = T * (0.5 * (head[1] + head[2])), d = (tip - base).normalized();
                if (turning) {
                    const Eigen::Vector2d r = tip - wheel.dof.pivot;
                    CHECK(r.norm() == doctest::Approx(0.6 * wheel.reach()));
                    CHECK(std::abs(r.normalized().dot(d)) < 0.35);                  // roughly along the circle
                    CHECK((r.x() * d.y() - r.y() * d.x()) * s > 0);                  // counter-clockwise for +
                } else {
                    CHECK(d.dot(s * slider.dof.axis.normalized()) == doctest::Approx(1.0));
                }
            }
        }
    }
}
