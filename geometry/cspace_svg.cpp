// geometry/cspace_svg.cpp
#include "geometry/cspace_svg.hpp"

#include "geometry/cspace_region.hpp"
#include "geometry/detail/label_layout.hpp"
#include "geometry/detail/svg_writer.hpp"
#include "geometry/place_sample.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace qm::geometry {

namespace {

using detail::Box;
using detail::px;
using detail::xml_text;

constexpr double legend_width = 170;
constexpr const char* blocked_fill = "#c8c8c8";
constexpr const char* fsd_style = "stroke=\"#3050c0\" stroke-width=\"1.2\" stroke-dasharray=\"5,3\"";
constexpr const char* external_style = "stroke=\"#000000\" stroke-width=\"1.2\" stroke-dasharray=\"1.5,2.5\"";
constexpr const char* stop_style = "stroke=\"#000000\" stroke-width=\"4\"";  // contact with the frame: a heavier solid line

// Where the configuration space is drawn: the frame's pixel box and the map into it.
struct Frame {
    CSpaceRequest r;
    double left, top, right, bottom;
    [[nodiscard]] double X(double q0) const { return left + (right - left) * (q0 - r.axes[0].lo) / r.axes[0].span(); }
    [[nodiscard]] double Y(double q1) const { return bottom - (bottom - top) * (q1 - r.axes[1].lo) / r.axes[1].span(); }
};

Frame frame_for(const CSpaceRequest& r, const SvgOptions& o) {
    const double right = o.width - 12 - (o.legend ? legend_width : 0);
    std::ostringstream title;  // only its height matters here
    const double left = 64, top = detail::write_title(title, o.title, left, o.width - left - 12, 6) + 6, bottom = o.height - 44;
    return {r, left, top, std::max(right, left + 40), std::max(bottom, top + 40)};
}

// A join's marker by kind (the legend shows the same): circles for a change of normal, white
// convex (Def 30), black concave (Def 29); a square where an FSD ends; a diamond where two
// divisions cross; a triangle at an axis' limit.
std::string join_marker(const Place& p, double x, double y, const std::string& attributes) {
    std::ostringstream os;
    const std::string at = attributes + " stroke=\"#000000\" stroke-width=\"1\"";
    switch (p.join_kind) {
        case JoinKind::normal_change:
            os << "<circle cx=\"" << px(x) << "\" cy=\"" << px(y) << "\" r=\"3\" fill=\"" << (p.concave.value_or(false) ? "#000000" : "#ffffff")
               << "\"" << at << "/>";
            break;
        case JoinKind::fsd_end:
            os << "<rect x=\"" << px(x - 2.5) << "\" y=\"" << px(y - 2.5) << "\" width=\"5\" height=\"5\" fill=\"#ffffff\"" << at << "/>";
            break;
        case JoinKind::crossing:
            os << "<polygon points=\"" << px(x) << ',' << px(y - 3.5) << ' ' << px(x + 3.5) << ',' << px(y) << ' ' << px(x) << ','
               << px(y + 3.5) << ' ' << px(x - 3.5) << ',' << px(y) << "\" fill=\"#ffffff\"" << at << "/>";
            break;
        case JoinKind::limit:
            os << "<polygon points=\"" << px(x) << ',' << px(y - 3.5) << ' ' << px(x + 3.5) << ',' << px(y + 3) << ' ' << px(x - 3.5) << ','
               << px(y + 3) << "\" fill=\"#ffffff\"" << at << "/>";
            break;
    }
    return os.str();
}

std::vector<detail::LegendRow> legend_rows(const PlaceVocabulary& v) {
    std::vector<detail::LegendRow> rows{{"<rect width=\"24\" height=\"10\" fill=\"" + std::string(blocked_fill) + "\"/>", "blocked"}};
    std::set<QualDirection> normals;
    for (const Place& p : v.places)
        if (p.kind == PlaceKind::cseg && !p.normals.empty()) normals.insert(p.normals.front());
    for (QualDirection d : normals)
        rows.push_back({"<line x1=\"0\" y1=\"5\" x2=\"24\" y2=\"5\" stroke=\"" + std::string(detail::normal_colour(d)) + "\" stroke-width=\"2.5\"/>",
                        "CSEG, normal " + to_string(d)});
    Place j;
    j.kind = PlaceKind::join;
    for (auto [kind, concave, text] : {std::tuple{JoinKind::normal_change, false, "join, convex"},
                                       std::tuple{JoinKind::normal_change, true, "join, concave"},
                                       std::tuple{JoinKind::fsd_end, false, "join, end of a division"},
                                       std::tuple{JoinKind::crossing, false, "join, divisions cross"},
                                       std::tuple{JoinKind::limit, false, "join, axis limit"}}) {
        j.join_kind = kind;
        j.concave = concave;
        rows.push_back({join_marker(j, 12, 5, ""), text});
    }
    rows.push_back({"<line x1=\"0\" y1=\"5\" x2=\"24\" y2=\"5\" " + std::string(fsd_style) + "/>", "free space division"});
    rows.push_back({"<line x1=\"0\" y1=\"5\" x2=\"24\" y2=\"5\" " + std::string(external_style) + "/>", "external division"});
    if (v.count(PlaceKind::stop) > 0)
        rows.push_back({"<line x1=\"0\" y1=\"5\" x2=\"24\" y2=\"5\" " + std::string(stop_style) + "/>", "stop (end of an axis)"});
    rows.push_back({"<text x=\"6\" y=\"9\" font-size=\"9\" fill=\"#006000\">12</text>", "face number"});
    rows.push_back({"<text x=\"6\" y=\"9\" font-size=\"9\" fill=\"#800000\">7</text>", "join number"});
    rows.push_back({"<text x=\"6\" y=\"9\" font-size=\"9\">3</text>", "CSEG or division number"});
    return rows;
}

// Ticks and the axis' name along the bottom (axis 0) or the left (axis 1); their text is
// reserved so that no place number covers it.
void write_axis(std::ostream& os, const Frame& f, int k, const SvgAxis& axis, std::vector<Box>& reserved) {
    const auto& a = f.r.axes[static_cast<std::size_t>(k)];
    const bool degrees = axis.unit == AxisUnit::degrees;
    const double scale = degrees ? 180.0 / std::numbers::pi : 1.0;
    std::string title = axis.name;
    if (axis.unit == AxisUnit::degrees) title += " (degrees, ccw)";
    if (axis.unit == AxisUnit::length) title += " (offset along its axis)";
    if (axis.unit == AxisUnit::fixed) title += " (fixed)";
    os << "<g class=\"axis\" font-size=\"9\" font-family=\"sans-serif\">\n";
    if (axis.unit != AxisUnit::fixed) {
        const double length = k == 0 ? f.right - f.left : f.bottom - f.top;
        for (const auto& t : detail::axis_ticks(a.lo * scale, a.hi * scale, std::max(2, static_cast<int>(length / (k == 0 ? 60 : 32))), degrees)) {
            const double chars = static_cast<double>(t.text.size()) - (degrees ? 1 : 0);  // the degree sign is two bytes
            const double w = detail::label_char_width * chars;
            if (k == 0) {
                const double x = f.X(t.value / scale);
                os << "<line x1=\"" << px(x) << "\" y1=\"" << px(f.bottom) << "\" x2=\"" << px(x) << "\" y2=\"" << px(f.bottom + 4)
                   << "\" stroke=\"#000000\"/>\n<text class=\"tick\" x=\"" << px(x) << "\" y=\"" << px(f.bottom + 14)
                   << "\" text-anchor=\"middle\">" << t.text << "</text>\n";
                reserved.push_back({x - w / 2, f.bottom + 5, x + w / 2, f.bottom + 16});
            } else {
                const double y = f.Y(t.value / scale);
                os << "<line x1=\"" << px(f.left - 4) << "\" y1=\"" << px(y) << "\" x2=\"" << px(f.left) << "\" y2=\"" << px(y)
                   << "\" stroke=\"#000000\"/>\n<text class=\"tick\" x=\"" << px(f.left - 6) << "\" y=\"" << px(y + 3)
                   << "\" text-anchor=\"end\">" << t.text << "</text>\n";
                reserved.push_back({f.left - 6 - w, y - 6, f.left - 5, y + 5});
            }
        }
    }
    const double chars = static_cast<double>(title.size()) * 6;
    if (k == 0) {
        const double x = 0.5 * (f.left + f.right);
        os << "<text class=\"axis-title\" x=\"" << px(x) << "\" y=\"" << px(f.bottom + 32) << "\" font-size=\"11\" text-anchor=\"middle\">"
           << xml_text(title) << "</text>\n";
        reserved.push_back({x - chars / 2, f.bottom + 21, x + chars / 2, f.bottom + 35});
    } else {
        const double y = 0.5 * (f.top + f.bottom);
        os << "<text class=\"axis-title\" x=\"14\" y=\"" << px(y) << "\" font-size=\"11\" text-anchor=\"middle\" transform=\"rotate(-90 14 "
           << px(y) << ")\">" << xml_text(title) << "</text>\n";
        reserved.push_back({3, y - chars / 2, 17, y + chars / 2});
    }
    os << "</g>\n";
}

// The blocked region as one path: its pieces share their sides exactly, and one path is filled
// as a whole, so no seam shows between them.
void write_region(std::ostream& os, const Frame& f, const std::vector<Polygon>& region) {
    os << "<path class=\"blocked\" fill=\"" << blocked_fill << "\" stroke=\"none\" d=\"";
    for (const auto& poly : region) {
        for (std::size_t k = 0; k < poly.size(); ++k) os << (k ? 'L' : 'M') << px(f.X(poly[k].x())) << ',' << px(f.Y(poly[k].y()));
        os << 'Z';
    }
    os << "\"/>\n";
}

// A place's polyline, broken where it wraps around a periodic axis.
void write_polyline(std::ostream& os, const Frame& f, const Place& p, const std::string& style) {
    std::vector<Eigen::Vector2d> run;
    auto flush = [&] {
        if (run.size() >= 2) {
            os << "<polyline data-place=\"" << p.id.value << "\" fill=\"none\" " << style << " points=\"";
            for (const auto& q : run) os << px(f.X(q.x())) << ',' << px(f.Y(q.y())) << ' ';
            os << "\"/>\n";
        }
        run.clear();
    };
    // Consecutive points are less than half a period apart (CSEG points are a cell apart,
    // divisions carry points a quarter period apart), so the short way between them is the way
    // the line goes; where it crosses a seam the line is drawn on past the frame (the clip path
    // cuts it) and starts again from the other side.
    const auto& r = f.r;
    for (const auto& q : p.points) {
        if (!run.empty()) {
            const Eigen::Vector2d d = difference(r, run.back(), q);
            if ((d - (q - run.back())).norm() > 0.25 * std::min(r.axes[0].span(), r.axes[1].span())) {
                run.push_back(run.back() + d);
                flush();
                run.push_back(q - d);
            }
        }
        run.push_back(q);
    }
    flush();
}

void write_places(std::ostream& os, const Frame& f, const PlaceVocabulary& v, std::vector<Box>& markers) {
    for (const Place& p : v.places) {
        if (p.kind == PlaceKind::cseg)
            write_polyline(os, f, p, "stroke=\"" + std::string(detail::normal_colour(p.normals.empty() ? QualDirection{} : p.normals.front())) +
                                         "\" stroke-width=\"2.5\" stroke-linecap=\"round\"");
        if (p.kind == PlaceKind::fsd) write_polyline(os, f, p, fsd_style);
        if (p.kind == PlaceKind::external_division) write_polyline(os, f, p, external_style);
        if (p.kind == PlaceKind::stop) write_polyline(os, f, p, stop_style);
    }
    for (const Place& p : v.places)  // joins on top of the lines
        if (p.kind == PlaceKind::join && !p.points.empty()) {
            const double x = f.X(p.points.front().x()), y = f.Y(p.points.front().y());
            os << join_marker(p, x, y, " class=\"join\" data-place=\"" + std::to_string(p.id.value) + "\"") << '\n';
            markers.push_back({x - 3.5, y - 3.5, x + 3.5, y + 3.5});
        }
}

// Place numbers: joins first (they are points), faces last (they have room).
void write_numbers(std::ostream& os, const Frame& f, const detail::LabelLayout& layout, const std::vector<const Place*>& order) {
    os << "<g class=\"place-numbers\" font-size=\"9\" font-family=\"sans-serif\">\n";
    for (std::size_t k = 0; k < order.size(); ++k) {
        const Place& p = *order[k];
        const auto& l = layout.labels[k];
        const Eigen::Vector2d at = sample_configuration(f.r, p);
        const double ax = f.X(at.x()), ay = f.Y(at.y());
        if (l.moved)
            os << "<line x1=\"" << px(ax) << "\" y1=\"" << px(ay) << "\" x2=\"" << px(std::clamp(ax, l.box.x0, l.box.x1)) << "\" y2=\""
               << px(std::clamp(ay, l.box.y0, l.box.y1)) << "\" stroke=\"#888888\" stroke-width=\"0.5\"/>\n";
        const char* colour = p.kind == PlaceKind::face ? "#006000" : p.kind == PlaceKind::join ? "#800000" : "#000000";
        os << "<text data-place=\"" << p.id.value << "\" x=\"" << px(l.x) << "\" y=\"" << px(l.y) << "\" fill=\"" << colour << "\">"
           << p.id.value << "</text>\n";
    }
    os << "</g>\n";
}

}  // namespace

void write_cspace_svg(std::ostream& os, const PairOracle& oracle, const CSpaceResult& space, const PlaceVocabulary& v, const SvgOptions& o) {
    QM_REQUIRE(space.status == CSpaceStatus::ok, "write_cspace_svg needs a classified space");
    const Frame f = frame_for(space.request, o);
    std::vector<Box> reserved, markers;
    std::ostringstream body;
    if (!o.title.empty()) reserved.push_back({f.left, 6, o.width - 12.0, detail::write_title(body, o.title, f.left, o.width - f.left - 12, 6)});
    // Everything drawn in the configuration space is clipped to its frame: a line crossing a
    // periodic seam is drawn on past it.
    body << "<clipPath id=\"frame\"><rect x=\"" << px(f.left) << "\" y=\"" << px(f.top) << "\" width=\"" << px(f.right - f.left)
         << "\" height=\"" << px(f.bottom - f.top) << "\"/></clipPath>\n<g clip-path=\"url(#frame)\">\n";
    write_region(body, f, blocked_region(oracle, space));
    write_places(body, f, v, markers);
    body << "</g>\n<rect class=\"frame\" x=\"" << px(f.left) << "\" y=\"" << px(f.top) << "\" width=\"" << px(f.right - f.left)
         << "\" height=\"" << px(f.bottom - f.top) << "\" fill=\"none\" stroke=\"#000000\"/>\n";
    for (int k = 0; k < 2; ++k) write_axis(body, f, k, o.axes[static_cast<std::size_t>(k)], reserved);
    double height = o.height;
    if (o.legend) {
        const double x = f.right + 14, bottom = detail::write_legend(body, legend_rows(v), x, f.top, "Legend");
        reserved.push_back({x - 4, f.top, static_cast<double>(o.width), bottom});
        height = std::max(height, bottom + 4);
    }
    std::vector<const Place*> order;
    for (const Place& p : v.places) order.push_back(&p);
    auto rank = [](PlaceKind k) { return k == PlaceKind::join ? 0 : k == PlaceKind::cseg ? 1 : k == PlaceKind::face ? 3 : 2; };
    std::stable_sort(order.begin(), order.end(), [&](const Place* a, const Place* b) { return rank(a->kind) < rank(b->kind); });
    std::vector<detail::LabelRequest> requests;
    for (const Place* p : order) {
        const Eigen::Vector2d at = sample_configuration(space.request, *p);
        requests.push_back({f.X(at.x()), f.Y(at.y()), std::to_string(p->id.value).size()});
    }
    std::vector<Box> obstacles = markers;
    obstacles.insert(obstacles.end(), reserved.begin(), reserved.end());
    const auto layout = o.numbers ? detail::layout_labels(requests, obstacles, o.width, height) : detail::LabelLayout{};
    height += layout.extra_height;
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.width << "\" height=\"" << px(height) << "\" viewBox=\"0 0 " << o.width
       << ' ' << px(height) << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n"
       << body.str();
    if (o.numbers) write_numbers(os, f, layout, order);
    os << "</svg>\n";
}

}  // namespace qm::geometry
