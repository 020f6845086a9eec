// geometry/detail/label_layout.cpp
#include "geometry/detail/label_layout.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace qm::geometry::detail {

LabelLayout layout_labels(const std::vector<LabelRequest>& requests, const std::vector<Box>& obstacles, double width, double height,
                          double gap) {
    LabelLayout out;
    std::vector<Box> taken;
    auto fits = [&](const Box& b) {
        // `gap` between labels, so that neighbours do not read as one ("35" "16": "3516"); none
        // needed from markers and reserved areas.
        const Box p = b.padded(gap, gap / 2);
        return b.x0 >= 0 && b.y0 >= 0 && b.x1 <= width && b.y1 <= height &&
               std::none_of(taken.begin(), taken.end(), [&](const Box& t) { return t.overlaps(p); }) &&
               std::none_of(obstacles.begin(), obstacles.end(), [&](const Box& t) { return t.overlaps(b); });
    };
    const double reach = std::hypot(width, height);
    // The next free spot in the rows below the picture (and below any obstacle reaching past it).
    double floor = height;
    for (const Box& o : obstacles) floor = std::max(floor, o.y1);
    double row_x = 4, row_y = floor + 12;
    for (const auto& r : requests) {
        const double w = label_char_width * static_cast<double>(r.chars);
        LabelPlacement l{r.ax + 3, r.ay - 3, false, label_box(r.ax + 3, r.ay - 3, r.chars)};
        bool found = fits(l.box);
        // Rings of growing radius, a spot about every 8 px along each.
        for (double radius = 8; !found && radius <= reach; radius += radius < 44 ? std::round(radius / 4 + 3) : 12) {
            const int spots = std::max(12, static_cast<int>(2 * std::numbers::pi * radius / 8));
            for (int k = 0; k < spots && !found; ++k) {
                const double angle = 2 * std::numbers::pi * k / spots;
                // the box centred on the ring's point
                const double x = r.ax + radius * std::cos(angle) - w / 2, y = r.ay - radius * std::sin(angle) + 4;
                if (fits(label_box(x, y, r.chars))) {
                    l = {x, y, true, label_box(x, y, r.chars)};
                    found = true;
                }
            }
        }
        if (!found) {  // nowhere in the picture: a row below it
            if (row_x + w > width && row_x > 4) {
                row_x = 4;
                row_y += 12;
            }
            l = {row_x, row_y, true, label_box(row_x, row_y, r.chars)};
            row_x += w + 2 * gap + 2;
            out.extra_height = row_y + 4 - height;
        }
        taken.push_back(l.box);
        out.labels.push_back(l);
    }
    return out;
}

}  // namespace qm::geometry::detail
