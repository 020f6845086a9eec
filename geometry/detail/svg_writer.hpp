// geometry/detail/svg_writer.hpp
// Provides:   the small pieces the geometry's SVG pictures share (cspace_svg.cpp, part_svg.cpp),
//             so that the configuration-space pictures and the drawings of parts look alike:
//             XML escaping, compact pixel numbers, the colour of a qualitative normal, axis ticks
//             at round values, and the legend's rows.
// Ownership:  free functions on values.
// Knows nothing of the ATMS or the engine. Internal to geometry/.
#pragma once
#include "geometry/qualitative_sign.hpp"
#include <ostream>
#include <string>
#include <vector>

namespace qm::geometry::detail {

// Text for an SVG text node or attribute value (part names may hold XML's special characters).
[[nodiscard]] std::string xml_text(const std::string& s);
// A pixel coordinate with at most two decimals ("12.5", "-3", "0.25").
[[nodiscard]] std::string px(double v);
// One colour per qualitative direction (the eight non-zero ones; (0 0) is black), the same in
// every picture: a CSEG and a contact normal pointing the same way are drawn alike.
[[nodiscard]] const char* normal_colour(QualDirection d) noexcept;
// The colour of the k-th part of a drawing.
[[nodiscard]] const char* part_colour(std::size_t k) noexcept;

// Ticks at round values covering [lo, hi], at most max_count of them: steps of 1, 2 or 5 times a
// power of ten, or for degrees also 15, 30, 45, 90 (a quarter turn reads better than 100).
struct Tick {
    double value;
    std::string text;
};
[[nodiscard]] std::vector<Tick> axis_ticks(double lo, double hi, int max_count, bool degrees);

// A picture's title in 13 px sans-serif, broken at spaces into lines that fit `width` pixels
// (about 7 px a character), written from (x, 20) one line every 17 px. Returns the title's bottom
// (y), or `none` when there is no title.
double write_title(std::ostream& os, const std::string& title, double x, double width, double none);

// Rows of a legend, drawn top-down from (x, y) under a heading: a swatch (an SVG fragment drawn
// in the box (0, 0)-(24, 10), moved into place) and a text.
struct LegendRow {
    std::string swatch;  // e.g. "<rect width=\"24\" height=\"10\" fill=\"#ccc\"/>"
    std::string text;
};
inline constexpr double legend_row_height = 14.0;
// Writes the rows and returns the legend's bottom.
double write_legend(std::ostream& os, const std::vector<LegendRow>& rows, double x, double y, const std::string& heading);

}  // namespace qm::geometry::detail
