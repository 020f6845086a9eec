// tests/geometry/cspace_svg_test.cpp: the configuration-space picture read back as SVG: the
// blocked region follows the bisected boundary (its area is the exact one, not the grid cells'),
// every CSEG, division and join is drawn and tagged with its place, divisions their whole length,
// the axes carry values in the scene's units (degrees for rotations), the legend names every
// kind, and place numbers never overprint each other, the legend or the axes' text, also at the
// escapement's crowded corners at the size `--places --svg` uses and at a small size.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/place_sample.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "svg_tree.hpp"

#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

using namespace qm::geometry;
using qm::geometry::test::parse_svg;
using qm::geometry::test::path_vertices;
using qm::geometry::test::SvgElement;

namespace {

class OpenBox final : public PairOracle {  // blocked iff q in the open box (x0,x1) x (y0,y1)
public:
    OpenBox(double x0, double x1, double y0, double y1) : x0_(x0), x1_(x1), y0_(y0), y1_(y1) {}
    bool blocked(const Eigen::Vector2d& q) const override { return q[0] > x0_ && q[0] < x1_ && q[1] > y0_ && q[1] < y1_; }
    Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override {
        const double d[4] = {q[0] - x0_, x1_ - q[0], q[1] - y0_, y1_ - q[1]};
        const int k = static_cast<int>(std::min_element(d, d + 4) - d);
        const Eigen::Vector2d n[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
        return n[k];
    }
    std::string fingerprint() const override { return "box"; }
private:
    double x0_, x1_, y0_, y1_;
};

// The frame's pixel box and the map from configurations to pixels it implies.
struct FrameBox {
    double x, y, w, h;
    std::array<CSpaceAxis, 2> axes;
    [[nodiscard]] double X(double q0) const { return x + w * (q0 - axes[0].lo) / axes[0].span(); }
    [[nodiscard]] double Y(double q1) const { return y + h - h * (q1 - axes[1].lo) / axes[1].span(); }
};
FrameBox frame_of(const SvgElement& svg, const std::array<CSpaceAxis, 2>& axes) {
    const SvgElement* f = svg.with_class("frame");
    REQUIRE(f != nullptr);
    return {f->number("x"), f->number("y"), f->number("width"), f->number("height"), axes};
}

std::string picture(const PairOracle& oracle, const PlaceResult& res, const SvgOptions& o) {
    std::stringstream ss;
    write_cspace_svg(ss, oracle, res.space, res.vocabulary, o);
    return ss.str();
}

PlaceResult built(const PairOracle& oracle, const std::array<CSpaceAxis, 2>& axes) {
    PlaceRequest req;
    req.cspace.axes = axes;
    return build_place_vocabulary(oracle, req);
}

}  // namespace

TEST_CASE("geometry/cspace_svg: the blocked region is filled from the bisected boundary, not grid cells") {
    // A box obstacle with sides off the grid: its filled area is the box's up to the four corner
    // cells (marching squares cuts each corner by at most half a cell); shading whole cells round
    // every blocked sample would be off by about half a cell all round.
    const OpenBox box(0.1013, 0.2987, 0.1511, 0.4489);
    const std::array<CSpaceAxis, 2> axes{CSpaceAxis{0, 1, false, 41}, CSpaceAxis{0, 1, false, 41}};
    const auto res = built(box, axes);
    const auto svg = parse_svg(picture(box, res, {640, 480, "box", true}));
    const FrameBox f = frame_of(*svg, axes);
    const SvgElement* region = svg->with_class("blocked");
    REQUIRE(region != nullptr);
    double area = 0;
    for (const auto& poly : path_vertices(region->attr("d"))) {
        double twice = 0;
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const auto& a = poly[k];
            const auto& b = poly[(k + 1) % poly.size()];
            twice += a.x() * b.y() - b.x() * a.y();
        }
        area += 0.5 * std::abs(twice) / (f.w * f.h);  // in configuration units
        for (const auto& v : poly) {  // every vertex on or inside the box, to a pixel's rounding
            const double q0 = (v.x() - f.x) / f.w, q1 = (f.y + f.h - v.y()) / f.h;
            CHECK(q0 >= 0.1013 - 0.01 / f.w * 2);
            CHECK(q0 <= 0.2987 + 0.01 / f.w * 2);
            CHECK(q1 >= 0.1511 - 0.01 / f.h * 2);
            CHECK(q1 <= 0.4489 + 0.01 / f.h * 2);
        }
    }
    const double exact = (0.2987 - 0.1013) * (0.4489 - 0.1511), cell = 1.0 / 40;
    CHECK(area <= exact + 1e-4);
    CHECK(area >= exact - 4 * 0.5 * cell * cell - 1e-4);
    std::size_t blocked = 0;
    for (auto b : res.space.blocked) blocked += b;
    CHECK(std::abs(blocked * cell * cell - exact) > 4 * 0.5 * cell * cell);  // the cells' area would not pass
}

TEST_CASE("geometry/cspace_svg: every place is drawn, tagged with its id, and numbered once") {
    const auto c = pin_in_slot();
    const auto res = built(c.exact, c.axes);
    const auto svg = parse_svg(picture(c.exact, res, {640, 480, "pin in slot", true}));
    std::map<int, std::vector<const SvgElement*>> tagged;
    for (const auto* e : svg->all([](const SvgElement& e) { return !e.attr("data-place").empty(); }))
        tagged[std::stoi(e->attr("data-place"))].push_back(e);
    for (const auto& p : res.vocabulary.places) {
        CAPTURE(p.id.value);
        const auto& es = tagged[static_cast<int>(p.id.value)];
        const auto numbers = std::count_if(es.begin(), es.end(), [](const SvgElement* e) { return e->name == "text"; });
        CHECK(numbers == 1);
        if (p.kind == PlaceKind::join) CHECK(std::count_if(es.begin(), es.end(), [](const SvgElement* e) { return e->has_class("join"); }) == 1);
        if (p.kind == PlaceKind::cseg || p.kind == PlaceKind::fsd || p.kind == PlaceKind::external_division)
            CHECK(std::count_if(es.begin(), es.end(), [](const SvgElement* e) { return e->name == "polyline"; }) >= 1);
    }
    // CSEGs are coloured by their qualitative normal: one colour per normal.
    std::map<std::string, std::set<std::string>> colours;
    for (const auto& p : res.vocabulary.places)
        if (p.kind == PlaceKind::cseg)
            for (const auto* e : tagged[static_cast<int>(p.id.value)])
                if (e->name == "polyline") colours[to_string(p.normals.front())].insert(e->attr("stroke"));
    std::set<std::string> all;
    for (const auto& [normal, set] : colours) {
        CHECK(set.size() == 1);
        all.insert(set.begin(), set.end());
    }
    CHECK(all.size() == colours.size());
}

TEST_CASE("geometry/cspace_svg: the legend names blocked space, each CSEG normal present, the join kinds, divisions and faces") {
    const auto c = disk_cam_and_follower();
    const auto res = built(c.exact, c.axes);
    const auto svg = parse_svg(picture(c.exact, res, {640, 480, "cam", true}));
    const SvgElement* legend = svg->with_class("legend");
    REQUIRE(legend != nullptr);
    std::set<std::string> rows;
    for (const auto* t : legend->named("text")) rows.insert(t->text);
    for (const char* row : {"Legend", "blocked", "join, convex", "join, concave", "join, end of a division", "join, divisions cross",
                            "join, axis limit", "free space division", "external division", "face number"})
        CHECK(rows.count(row) == 1);
    for (const auto& p : res.vocabulary.places)
        if (p.kind == PlaceKind::cseg) CHECK(rows.count("CSEG, normal " + to_string(p.normals.front())) == 1);
    // No legend when asked for none; the frame then takes the room.
    const auto bare = parse_svg(picture(c.exact, res, {640, 480, "cam", true, false}));
    CHECK(bare->with_class("legend") == nullptr);
    CHECK(bare->with_class("frame")->number("width") > svg->with_class("frame")->number("width"));
}

TEST_CASE("geometry/cspace_svg: axes carry ticks at their values, in degrees for rotations") {
    const auto c = disk_cam_and_follower();  // q0 the cam's angle in [-pi, pi), q1 the follower in [0.2, 1]
    const auto res = built(c.exact, c.axes);
    SvgOptions o{640, 480, "cam", true, true, {SvgAxis{"cam", AxisUnit::degrees}, SvgAxis{"follower", AxisUnit::length}}};
    const auto svg = parse_svg(picture(c.exact, res, o));
    const FrameBox f = frame_of(*svg, c.axes);
    std::vector<const SvgElement*> x_ticks, y_ticks;
    for (const auto* t : svg->all([](const SvgElement& e) { return e.has_class("tick"); }))
        (t->attr("text-anchor") == "middle" ? x_ticks : y_ticks).push_back(t);
    REQUIRE(x_ticks.size() >= 3);
    REQUIRE(y_ticks.size() >= 3);
    for (const auto* t : x_ticks) {
        CAPTURE(t->text);
        REQUIRE(t->text.size() > 2);
        CHECK(t->text.substr(t->text.size() - 2) == "\u00b0");
        const double degrees = std::stod(t->text);
        CHECK(degrees >= -180);
        CHECK(degrees <= 180);
        CHECK(t->number("x") == doctest::Approx(f.X(degrees * std::numbers::pi / 180)).epsilon(0.001));
    }
    for (const auto* t : y_ticks) {
        CAPTURE(t->text);
        const double v = std::stod(t->text);
        CHECK(t->text.find("\u00b0") == std::string::npos);
        CHECK(v >= 0.2 - 1e-9);
        CHECK(v <= 1 + 1e-9);
        CHECK(t->number("y") - 3 == doctest::Approx(f.Y(v)).epsilon(0.001));
    }
    std::set<std::string> titles;
    for (const auto* t : svg->all([](const SvgElement& e) { return e.has_class("axis-title"); })) titles.insert(t->text);
    CHECK(titles == std::set<std::string>{"cam (degrees, ccw)", "follower (offset along its axis)"});
}

namespace {

// The drawn FSDs (dashed blue polylines) as axis-parallel pixel segments: for each line (a fixed
// y for horizontal ones, x for vertical ones, to a pixel), the total length of the union of the
// intervals drawn on it inside the frame (the picture clips lines to it).
struct Coverage {
    std::map<long, std::vector<std::pair<double, double>>> horizontal, vertical;
    static double covered(std::vector<std::pair<double, double>> v) {
        std::sort(v.begin(), v.end());
        double total = 0, lo = -1e300, hi = -1e300;
        for (auto [a, b] : v) {
            if (a > hi) {
                total += std::max(0.0, hi - lo);
                lo = a;
                hi = b;
            } else {
                hi = std::max(hi, b);
            }
        }
        return total + std::max(0.0, hi - lo);
    }
    double along_y(double y) const { auto it = horizontal.find(std::lround(y)); return it == horizontal.end() ? 0 : covered(it->second); }
    double along_x(double x) const { auto it = vertical.find(std::lround(x)); return it == vertical.end() ? 0 : covered(it->second); }
};

Coverage fsd_coverage(const SvgElement& svg, const PlaceVocabulary& v, const FrameBox& f) {
    Coverage c;
    for (const auto* e : svg.named("polyline")) {
        if (v.places[std::stoul(e->attr("data-place"))].kind != PlaceKind::fsd) continue;
        std::istringstream pts(e->attr("points"));
        std::vector<std::pair<double, double>> xy;
        double x = 0, y = 0;
        char comma = 0;
        while (pts >> x >> comma >> y) xy.emplace_back(x, y);
        for (std::size_t k = 1; k < xy.size(); ++k) {
            const auto [x0, y0] = xy[k - 1];
            const auto [x1, y1] = xy[k];
            if (std::abs(y1 - y0) < 1e-6)
                c.horizontal[std::lround(y0)].emplace_back(std::clamp(std::min(x0, x1), f.x, f.x + f.w), std::clamp(std::max(x0, x1), f.x, f.x + f.w));
            if (std::abs(x1 - x0) < 1e-6)
                c.vertical[std::lround(x0)].emplace_back(std::clamp(std::min(y0, y1), f.y, f.y + f.h), std::clamp(std::max(y0, y1), f.y, f.y + f.h));
        }
    }
    return c;
}

}  // namespace

TEST_CASE("geometry/cspace_svg: every division is drawn its whole length, the right way round a periodic axis") {
    // A division piece drawn from its two ends the short way round would put a piece of half the
    // period or more (the disk cam's FSD around the whole wheel angle, split into two halves) over
    // the wrong half or, on a translation axis, one longer than half the span nowhere.
    {
        // Disk cam, h = 0.5 + 0.2 sin q0, q0 in [-pi, pi), q1 in [0.2, 1]: the FSD from the top
        // (pi/2, 0.7) runs around the whole q0 axis, across the seam; verticals go up from the
        // top and from the bottom (-pi/2, 0.3).
        const auto c = disk_cam_and_follower();
        const auto res = built(c.exact, c.axes);
        const auto svg = parse_svg(picture(c.exact, res, {640, 480, "cam", true}));
        const FrameBox f = frame_of(*svg, c.axes);
        const auto cov = fsd_coverage(*svg, res.vocabulary, f);
        CHECK(cov.along_y(f.Y(0.7)) == doctest::Approx(f.w).epsilon(0.01));
        CHECK(cov.along_x(f.X(std::numbers::pi / 2)) == doctest::Approx(f.Y(0.7) - f.Y(1.0)).epsilon(0.01));
        CHECK(cov.along_x(f.X(-std::numbers::pi / 2)) == doctest::Approx(f.Y(0.3) - f.Y(1.0)).epsilon(0.01));
    }
    {
        // A box obstacle near the left of a square of translations: the FSDs from its corners
        // run to the square's sides, those to the right and up longer than half the side.
        const OpenBox box(0.1, 0.2, 0.15, 0.3);
        const std::array<CSpaceAxis, 2> axes{CSpaceAxis{0, 1, false, 41}, CSpaceAxis{0, 1, false, 41}};
        const auto res = built(box, axes);
        REQUIRE(res.vocabulary.count(PlaceKind::fsd) == 8);
        const auto svg = parse_svg(picture(box, res, {640, 480, "box", true}));
        const FrameBox f = frame_of(*svg, axes);
        const auto cov = fsd_coverage(*svg, res.vocabulary, f);
        for (double y : {0.15, 0.3}) CHECK(cov.along_y(f.Y(y)) == doctest::Approx(f.w * 0.9).epsilon(0.01));
        for (double x : {0.1, 0.2}) CHECK(cov.along_x(f.X(x)) == doctest::Approx(f.h * 0.85).epsilon(0.01));
    }
}

namespace {

struct Label {
    int id;
    double x0, y0, x1, y1;  // the box the picture promises (5.5 px a digit, 9.5 px tall)
};
std::vector<Label> labels(const SvgElement& svg) {
    std::vector<Label> out;
    const SvgElement* group = svg.with_class("place-numbers");
    REQUIRE(group != nullptr);
    for (const auto* t : group->named("text")) {
        const double x = t->number("x"), y = t->number("y");
        out.push_back({std::stoi(t->text), x, y - 8.5, x + 5.5 * static_cast<double>(t->text.size()), y + 1});
    }
    return out;
}

bool apart(double ax0, double ay0, double ax1, double ay1, double bx0, double by0, double bx1, double by1) {
    return ax1 <= bx0 || bx1 <= ax0 || ay1 <= by0 || by1 <= ay0;
}

// Every number once, inside the picture, apart from every other number, from the joins' markers
// and from the other text (ticks, axis titles, legend); every leader ends on a number.
void check_numbers(const std::string& text, const PlaceVocabulary& v, int width) {
    const auto svg = parse_svg(text);
    const SvgElement* root = svg->named("svg").front();
    const double height = root->number("height");
    const auto ls = labels(*svg);
    REQUIRE(ls.size() == v.places.size());
    std::vector<int> ids;
    for (const Label& l : ls) ids.push_back(l.id);
    std::sort(ids.begin(), ids.end());
    CHECK(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
    std::vector<Label> others;  // other text, by its approximate box, and join markers
    for (const auto* t : svg->named("text")) {
        if (t->parent->has_class("place-numbers")) continue;
        if (t->has_class("tick")) {
            const double x = t->number("x"), y = t->number("y"), w = 5.5 * (static_cast<double>(t->text.size()) - 1);
            const double x0 = t->attr("text-anchor") == "middle" ? x - w / 2 : x - w;
            others.push_back({-1, x0, y - 8, x0 + w, y + 1});
        }
    }
    for (const auto* j : svg->all([](const SvgElement& e) { return e.has_class("join"); })) {
        Label box{-2, 1e9, 1e9, -1e9, -1e9};
        auto extend = [&](double x, double y) {
            box = {-2, std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x), std::max(box.y1, y)};
        };
        if (j->name == "circle") {
            extend(j->number("cx") - 3, j->number("cy") - 3);
            extend(j->number("cx") + 3, j->number("cy") + 3);
        } else if (j->name == "rect") {
            extend(j->number("x"), j->number("y"));
            extend(j->number("x") + 5, j->number("y") + 5);
        } else {
            std::istringstream pts(j->attr("points"));
            double x = 0, y = 0;
            char comma = 0;
            while (pts >> x >> comma >> y) extend(x, y);
        }
        others.push_back(box);
    }
    const SvgElement* legend = svg->with_class("legend");
    if (legend) {
        double bottom = 0, left = 1e9;
        for (const auto* t : legend->named("text")) {
            if (t->parent != legend) continue;  // a swatch's sample number, in its own coordinates
            bottom = std::max(bottom, t->number("y") + 2);
            left = std::min(left, t->number("x"));
        }
        others.push_back({-3, left, 0, static_cast<double>(width), bottom});
    }
    for (std::size_t i = 0; i < ls.size(); ++i) {
        CAPTURE(ls[i].id);
        CHECK(ls[i].x0 >= 0);
        CHECK(ls[i].x1 <= width);
        CHECK(ls[i].y0 >= 0);
        CHECK(ls[i].y1 <= height);
        for (std::size_t j = i + 1; j < ls.size(); ++j)
            if (!apart(ls[i].x0, ls[i].y0, ls[i].x1, ls[i].y1, ls[j].x0, ls[j].y0, ls[j].x1, ls[j].y1)) {
                CAPTURE(ls[j].id);
                FAIL_CHECK("two place numbers overlap");
            }
        for (const Label& o : others)
            if (!apart(ls[i].x0, ls[i].y0, ls[i].x1, ls[i].y1, o.x0, o.y0, o.x1, o.y1)) {
                CAPTURE(o.id);
                FAIL_CHECK("a place number covers a marker, a tick or the legend");
            }
    }
    for (const auto* line : svg->with_class("place-numbers")->named("line")) {
        const double x2 = line->number("x2"), y2 = line->number("y2");
        CHECK(std::any_of(ls.begin(), ls.end(), [&](const Label& l) {
            return x2 >= l.x0 - 1e-3 && x2 <= l.x1 + 1e-3 && y2 >= l.y0 - 1e-3 && y2 <= l.y1 + 1e-3;
        }));
    }
}

}  // namespace

TEST_CASE("geometry/cspace_svg: place numbers do not overprint each other, moved ones have a leader") {
    // Small pictures crowd the numbers: each must still be drawn once, inside the picture, apart
    // from every other, and a number not at its place's default spot is tied to it by a line.
    const auto cam = disk_cam_and_follower();
    const auto res = built(cam.exact, cam.axes);
    for (auto [width, height] : {std::pair{640, 480}, std::pair{320, 240}, std::pair{240, 180}}) {
        CAPTURE(width);
        const std::string text = picture(cam.exact, res, {width, height, "cam & <follower>", true, width > 300});
        CHECK(parse_svg(text)->named("text").front()->text == "cam & <follower>");
        check_numbers(text, res.vocabulary, width);
        // The smallest picture cannot hold every number at its place: the moving is exercised.
        if (width == 240) CHECK(parse_svg(text)->with_class("place-numbers")->named("line").size() > 0);
    }
}

TEST_CASE("geometry/cspace_svg: the escapement's crowded corners, at the size of --places --svg and smaller") {
    qm::Diagnostics d;
    const auto m = read_mechanism_file(std::string(QM_SOURCE_DIR) + "/scenarios/metric/escapement.def", d);
    REQUIRE(m);
    const auto pair = kinematic_pairs(*m).modelled.at(0);
    const auto oracle = pair_oracle(*m, pair);
    const auto res = build_place_vocabulary(*oracle, place_request(*m, pair));
    REQUIRE(res.vocabulary.places.size() > 30);
    const SvgOptions base{720, 540, "escapement", true, true, {SvgAxis{"scape-wheel", AxisUnit::degrees}, SvgAxis{"pallets", AxisUnit::degrees}}};
    for (auto [width, height, legend] : {std::tuple{720, 540, true}, std::tuple{480, 360, true}, std::tuple{300, 220, false}}) {
        CAPTURE(width);
        SvgOptions o = base;
        o.width = width;
        o.height = height;
        o.legend = legend;
        std::stringstream ss;
        write_cspace_svg(ss, *oracle, res.space, res.vocabulary, o);
        check_numbers(ss.str(), res.vocabulary, width);
        std::ofstream(std::string(QM_BINARY_DIR) + "/escapement_cspace_" + std::to_string(width) + ".svg") << ss.str();  // for inspection
    }
    // The pallets' window is -20..20 degrees: the vertical axis is labelled so.
    std::stringstream ss;
    write_cspace_svg(ss, *oracle, res.space, res.vocabulary, base);
    std::set<std::string> ticks;
    const auto tree = parse_svg(ss.str());  // (a temporary tree would die before the loop)
    for (const auto* t : tree->all([](const SvgElement& e) { return e.has_class("tick") && e.attr("text-anchor") == "end"; }))
        ticks.insert(t->text);
    CHECK(ticks.count("-20\u00b0") == 1);
    CHECK(ticks.count("0\u00b0") == 1);
    CHECK(ticks.count("20\u00b0") == 1);
}
