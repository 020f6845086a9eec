// geometry/detail/label_layout.hpp
// Provides:   layout_labels(): where to print short labels (place numbers) so that no two
//             overprint each other and none covers a marker or a reserved area (legend, axis
//             text), at any picture size: each label goes beside its anchor if it fits there,
//             else at the nearest free spot on rings around the anchor (a leader is drawn back to
//             it), rings growing until they span the picture; a label with no free spot left in
//             the picture goes to a row below it, which the picture grows to hold.
// Ownership:  values.
// Invariants: in the result no two label boxes (padded by `gap`) overlap, none overlaps an
//             obstacle or reserved box, and every box lies inside (0, 0)-(width, height + extra).
// Knows nothing of the ATMS or the engine. Internal to geometry/.
#pragma once
#include <cstddef>
#include <vector>

namespace qm::geometry::detail {

struct Box {
    double x0, y0, x1, y1;
    [[nodiscard]] bool overlaps(const Box& b) const noexcept { return x0 < b.x1 && b.x0 < x1 && y0 < b.y1 && b.y0 < y1; }
    [[nodiscard]] Box padded(double dx, double dy) const noexcept { return {x0 - dx, y0 - dy, x1 + dx, y1 + dy}; }
};

// A label's box for text of `chars` characters whose baseline starts at (x, y), in the 9 px
// sans-serif the pictures use (digits at most 5.5 px wide, 9.5 px from top to bottom).
inline constexpr double label_char_width = 5.5;
[[nodiscard]] inline Box label_box(double x, double y, std::size_t chars) noexcept {
    return {x, y - 8.5, x + label_char_width * static_cast<double>(chars), y + 1};
}

struct LabelRequest {
    double ax, ay;       // the anchor (pixels)
    std::size_t chars;   // text length
};

struct LabelPlacement {
    double x, y;         // baseline start
    bool moved = false;  // away from the default spot beside the anchor: draw a leader
    Box box{};
};

struct LabelLayout {
    std::vector<LabelPlacement> labels;  // in request order
    double extra_height = 0.0;           // rows added below the picture
};

// Labels are placed in request order (so earlier ones get the better spots).
[[nodiscard]] LabelLayout layout_labels(const std::vector<LabelRequest>& requests, const std::vector<Box>& obstacles,
                                        double width, double height, double gap = 2.0);

}  // namespace qm::geometry::detail
