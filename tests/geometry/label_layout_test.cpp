// tests/geometry/label_layout_test.cpp: labels never overlap each other, obstacles or the edges,
// at any size: crowded onto one anchor in a small picture, those that find no room go to rows
// below it, which the layout reports; a label that fits stays beside its anchor.
#include "geometry/detail/label_layout.hpp"

#include <doctest/doctest.h>
#include <random>
#include <tuple>

using namespace qm::geometry::detail;

namespace {
void check_apart(const LabelLayout& l, const std::vector<Box>& obstacles, double width, double height) {
    for (std::size_t i = 0; i < l.labels.size(); ++i) {
        const Box& b = l.labels[i].box;
        CHECK(b.x0 >= 0);
        CHECK(b.y0 >= 0);
        CHECK(b.x1 <= width);
        CHECK(b.y1 <= height + l.extra_height);
        for (std::size_t j = i + 1; j < l.labels.size(); ++j) CHECK_FALSE(b.padded(2, 1).overlaps(l.labels[j].box));
        for (const Box& o : obstacles) CHECK_FALSE(b.overlaps(o));
    }
}
}  // namespace

TEST_CASE("geometry/label_layout: a lone label stays beside its anchor") {
    const auto l = layout_labels({{100, 100, 2}}, {}, 400, 300);
    REQUIRE(l.labels.size() == 1);
    CHECK_FALSE(l.labels[0].moved);
    CHECK(l.labels[0].x == 103);
    CHECK(l.labels[0].y == 97);
    CHECK(l.extra_height == 0);
}

TEST_CASE("geometry/label_layout: crowds, obstacles and pictures too small to hold them") {
    std::mt19937 rng(5);
    for (auto [width, height, count] : {std::tuple{400.0, 300.0, 60}, std::tuple{120.0, 80.0, 80}, std::tuple{40.0, 30.0, 30}}) {
        CAPTURE(width);
        std::uniform_real_distribution<double> x(0, width), y(0, height);
        std::vector<LabelRequest> requests;
        for (int k = 0; k < count; ++k) requests.push_back({width / 2 + (k % 3), height / 2, 1 + static_cast<std::size_t>(k % 3)});
        std::vector<Box> obstacles;
        for (int k = 0; k < 5; ++k) {
            const double x0 = x(rng), y0 = y(rng);
            obstacles.push_back({x0, y0, x0 + 8, y0 + 8});
        }
        const auto l = layout_labels(requests, obstacles, width, height);
        REQUIRE(l.labels.size() == requests.size());
        check_apart(l, obstacles, width, height);
        if (width < 100) CHECK(l.extra_height > 0);  // no room for all of them: rows below
    }
}
