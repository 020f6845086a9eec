// geometry/detail/svg_writer.cpp
#include "geometry/detail/svg_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace qm::geometry::detail {

std::string xml_text(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

std::string px(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s == "-0" ? "0" : s;
}

const char* normal_colour(QualDirection d) noexcept {
    // Round the compass from (+ 0), counter-clockwise; neighbours differ in hue and lightness so
    // that adjacent CSEGs stay apart in print too.
    static constexpr const char* colours[8] = {"#d62728", "#e07b00", "#b8a000", "#2ca02c",
                                               "#008b8b", "#1f4fd0", "#8e24aa", "#d81b8f"};
    static constexpr int at[3][3] = {{5, 4, 3}, {6, -1, 2}, {7, 0, 1}};  // [sx + 1][sy + 1]
    const int k = at[d.s[0] + 1][d.s[1] + 1];
    return k < 0 ? "#000000" : colours[k];
}

const char* part_colour(std::size_t k) noexcept {
    static constexpr const char* colours[6] = {"#3b6fb6", "#c0504d", "#4e9a4e", "#8064a2", "#c08000", "#2b9a9a"};
    return colours[k % 6];
}

std::vector<Tick> axis_ticks(double lo, double hi, int max_count, bool degrees) {
    std::vector<double> steps;
    for (int e = -9; e <= 9; ++e)
        for (double m : {1.0, 2.0, 5.0}) steps.push_back(m * std::pow(10.0, e));
    if (degrees)
        for (double s : {15.0, 30.0, 45.0, 90.0}) steps.push_back(s);
    std::sort(steps.begin(), steps.end());
    std::vector<Tick> out;
    if (!(hi > lo) || max_count < 2) return out;
    const double slack = 1e-9 * (hi - lo);
    for (double s : steps) {
        const double first = std::ceil((lo - slack) / s), last = std::floor((hi + slack) / s);
        if (last - first + 1 > max_count) continue;
        const int decimals = s >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(s) - 1e-9));
        for (double k = first; k <= last; ++k) {
            const double v = std::abs(k * s) < 0.5 * s ? 0.0 : k * s;
            char buf[48];
            std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
            out.push_back({v, std::string(buf) + (degrees ? "\u00b0" : "")});
        }
        return out;
    }
    return out;
}

double write_title(std::ostream& os, const std::string& title, double x, double width, double none) {
    if (title.empty()) return none;
    const auto fits = static_cast<std::size_t>(std::max(10.0, width / 7));
    std::vector<std::string> lines{""};
    std::istringstream words(title);
    for (std::string w; words >> w;) {
        if (!lines.back().empty() && lines.back().size() + 1 + w.size() > fits) lines.emplace_back();
        lines.back() += (lines.back().empty() ? "" : " ") + w;
    }
    for (std::size_t k = 0; k < lines.size(); ++k)
        os << "<text class=\"title\" x=\"" << px(x) << "\" y=\"" << px(20 + 17.0 * static_cast<double>(k))
           << "\" font-size=\"13\" font-family=\"sans-serif\">" << xml_text(lines[k]) << "</text>\n";
    return 24 + 17.0 * static_cast<double>(lines.size() - 1);
}

double write_legend(std::ostream& os, const std::vector<LegendRow>& rows, double x, double y, const std::string& heading) {
    os << "<g class=\"legend\" font-size=\"10\" font-family=\"sans-serif\">\n<text x=\"" << px(x) << "\" y=\"" << px(y + 9)
       << "\" font-weight=\"bold\">" << xml_text(heading) << "</text>\n";
    double at = y + legend_row_height;
    for (const auto& row : rows) {
        os << "<g transform=\"translate(" << px(x) << ' ' << px(at) << ")\">" << row.swatch << "</g>\n<text x=\"" << px(x + 30)
           << "\" y=\"" << px(at + 9) << "\">" << xml_text(row.text) << "</text>\n";
        at += legend_row_height;
    }
    os << "</g>\n";
    return at;
}

}  // namespace qm::geometry::detail
