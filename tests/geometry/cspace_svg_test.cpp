// tests/geometry/cspace_svg_test.cpp: the picture holds the shaded blocked samples, one circle per
// join and one number per place.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/place_vocabulary_builder.hpp"

#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

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

namespace {

class Box final : public PairOracle {  // blocked iff q in the open box (x0,x1) x (y0,y1)
public:
    Box(double x0, double x1, double y0, double y1) : x0_(x0), x1_(x1), y0_(y0), y1_(y1) {}
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

Coverage fsd_coverage(const std::string& svg) {  // for a 640 x 480 picture
    Coverage c;
    const std::string head = "<polyline fill=\"none\" stroke=\"#3050c0\" stroke-dasharray=\"5,3\" points=\"";
    for (auto p = svg.find(head); p != std::string::npos; p = svg.find(head, p + 1)) {
        std::istringstream pts(svg.substr(p + head.size(), svg.find('"', p + head.size()) - p - head.size()));
        std::vector<std::pair<double, double>> xy;
        double x = 0, y = 0;
        char comma = 0;
        while (pts >> x >> comma >> y) xy.emplace_back(x, y);
        for (std::size_t k = 1; k < xy.size(); ++k) {
            const auto [x0, y0] = xy[k - 1];
            const auto [x1, y1] = xy[k];
            if (std::abs(y1 - y0) < 1e-6)
                c.horizontal[std::lround(y0)].emplace_back(std::clamp(std::min(x0, x1), 40.0, 600.0), std::clamp(std::max(x0, x1), 40.0, 600.0));
            if (std::abs(x1 - x0) < 1e-6)
                c.vertical[std::lround(x0)].emplace_back(std::clamp(std::min(y0, y1), 40.0, 440.0), std::clamp(std::max(y0, y1), 40.0, 440.0));
        }
    }
    return c;
}

}  // namespace

TEST_CASE("geometry/cspace_svg: every division is drawn its whole length, the right way round a periodic axis") {
    // Regression: a division piece was drawn from its two ends the short way round, so a piece
    // of half the period or more (the disk cam's FSD around the whole wheel angle, split into
    // two halves) was drawn over the wrong half or, on a translation axis, longer than half the
    // span, not at all.
    const double w = 640 - 80, h = 480 - 80;  // the frame inside the 40-pixel margin
    {
        // Disk cam, h = 0.5 + 0.2 sin q0, q0 in [-pi, pi), q1 in [0.2, 1]: the FSD from the top
        // (pi/2, 0.7) runs around the whole q0 axis, across the seam; verticals go up from the
        // top and from the bottom (-pi/2, 0.3).
        const auto c = disk_cam_and_follower();
        PlaceRequest req;
        req.cspace.axes = c.axes;
        const auto res = build_place_vocabulary(c.exact, req);
        std::stringstream ss;
        write_cspace_svg(ss, res.space, res.vocabulary, {640, 480, "cam", true});
        const auto cov = fsd_coverage(ss.str());
        auto Y = [&](double q1) { return 480 - 40 - h * (q1 - 0.2) / 0.8; };
        CHECK(cov.along_y(Y(0.7)) == doctest::Approx(w).epsilon(0.01));
        CHECK(cov.along_x(40 + w * 0.75) == doctest::Approx(Y(0.7) - Y(1.0)).epsilon(0.01));
        CHECK(cov.along_x(40 + w * 0.25) == doctest::Approx(Y(0.3) - Y(1.0)).epsilon(0.01));
    }
    {
        // A box obstacle near the left of a square of translations: the FSDs from its corners
        // run to the square's sides, those to the right and up longer than half the side.
        const Box box(0.1, 0.2, 0.15, 0.3);
        PlaceRequest req;
        for (auto& a : req.cspace.axes) a = CSpaceAxis{0, 1, false, 41};
        const auto res = build_place_vocabulary(box, req);
        REQUIRE(res.vocabulary.count(PlaceKind::fsd) == 8);
        std::stringstream ss;
        write_cspace_svg(ss, res.space, res.vocabulary, {640, 480, "box", true});
        const auto cov = fsd_coverage(ss.str());
        for (double y : {0.15, 0.3}) CHECK(cov.along_y(480 - 40 - h * y) == doctest::Approx(w * 0.9).epsilon(0.01));
        for (double x : {0.1, 0.2}) CHECK(cov.along_x(40 + w * x) == doctest::Approx(h * 0.85).epsilon(0.01));
    }
}

namespace {
struct Label {
    int id;
    double x0, y0, x1, y1;  // the box the picture promises (cspace_svg.cpp: 5.5 px a digit, 9.5 px tall)
};
std::vector<Label> labels(const std::string& svg) {
    std::vector<Label> out;
    const std::string group = "<g font-size=\"9\" font-family=\"sans-serif\">\n";
    const auto start = svg.find(group);
    REQUIRE(start != std::string::npos);
    std::istringstream in(svg.substr(start + group.size(), svg.find("</g>", start) - start - group.size()));
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("<text", 0) != 0) continue;
        double x = 0, y = 0;
        REQUIRE(std::sscanf(line.c_str(), "<text x=\"%lf\" y=\"%lf\"", &x, &y) == 2);
        const auto gt = line.find('>'), end = line.find("</text>");
        const std::string number = line.substr(gt + 1, end - gt - 1);
        out.push_back({std::stoi(number), x, y - 8.5, x + 5.5 * static_cast<double>(number.size()), y + 1});
    }
    return out;
}
}  // namespace

TEST_CASE("geometry/cspace_svg: place numbers do not overprint each other, moved ones have a leader") {
    // Small pictures crowd the numbers: each must still be drawn once, inside the picture, apart
    // from every other, and a number not at its place's default spot is tied to it by a line.
    const auto cam = disk_cam_and_follower();
    PlaceRequest req;
    req.cspace.axes = cam.axes;
    const auto res = build_place_vocabulary(cam.exact, req);
    for (auto [width, height] : {std::pair{640, 480}, std::pair{320, 240}, std::pair{240, 180}}) {
        CAPTURE(width);
        std::stringstream ss;
        write_cspace_svg(ss, res.space, res.vocabulary, {width, height, "cam & <follower>", true});
        const std::string svg = ss.str();
        CHECK(svg.find("cam &amp; &lt;follower&gt;") != std::string::npos);
        const auto ls = labels(svg);
        REQUIRE(ls.size() == res.vocabulary.places.size());
        std::vector<int> ids;
        for (const Label& l : ls) ids.push_back(l.id);
        std::sort(ids.begin(), ids.end());
        CHECK(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
        for (std::size_t i = 0; i < ls.size(); ++i) {
            CHECK(ls[i].x0 >= 0);
            CHECK(ls[i].x1 <= width);
            for (std::size_t j = i + 1; j < ls.size(); ++j) {
                const bool apart = ls[i].x1 <= ls[j].x0 || ls[j].x1 <= ls[i].x0 || ls[i].y1 <= ls[j].y0 || ls[j].y1 <= ls[i].y0;
                if (!apart) {
                    CAPTURE(ls[i].id);
                    CAPTURE(ls[j].id);
                    CHECK(apart);
                }
            }
        }
        // The smallest picture cannot hold every number at its place: the moving is exercised.
        if (width == 240) CHECK(occurrences(svg, "<line ") > 0);
        // Every leader ends on the box of some number.
        for (auto p = svg.find("<line "); p != std::string::npos; p = svg.find("<line ", p + 1)) {
            double x1 = 0, y1 = 0, x2 = 0, y2 = 0;
            REQUIRE(std::sscanf(svg.c_str() + p, "<line x1=\"%lf\" y1=\"%lf\" x2=\"%lf\" y2=\"%lf\"", &x1, &y1, &x2, &y2) == 4);
            CHECK(std::any_of(ls.begin(), ls.end(), [&](const Label& l) {
                return x2 >= l.x0 - 1e-3 && x2 <= l.x1 + 1e-3 && y2 >= l.y0 - 1e-3 && y2 <= l.y1 + 1e-3;
            }));
        }
    }
}
