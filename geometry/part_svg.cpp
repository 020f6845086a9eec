// geometry/part_svg.cpp
#include "geometry/part_svg.hpp"

#include "geometry/detail/label_layout.hpp"
#include "geometry/detail/svg_writer.hpp"
#include "geometry/qualitative_sign.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>

namespace qm::geometry {

namespace {

using detail::px;
using detail::xml_text;

constexpr double legend_width = 170;
constexpr double arrow_length = 26;

// A world coordinate: enough digits that the outline is the geometry, not a rounding of it.
std::string wn(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v == 0.0 ? 0.0 : v);  // never "-0"
    return buf;
}

Eigen::Vector2d drawing_centre(const Part& p) {
    const double big = std::numeric_limits<double>::infinity();
    Eigen::Vector2d lo(big, big), hi(-big, -big);
    for (const auto& profile : p.profiles) extend_bounds(profile, lo, hi);
    return 0.5 * (lo + hi);
}

std::string arrow(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const char* colour) {
    const Eigen::Vector2d d = (to - from).normalized(), n(-d.y(), d.x());
    const Eigen::Vector2d a = to - 6 * d + 3 * n, b = to - 6 * d - 3 * n;
    std::ostringstream os;
    os << "<line x1=\"" << px(from.x()) << "\" y1=\"" << px(from.y()) << "\" x2=\"" << px(to.x()) << "\" y2=\"" << px(to.y())
       << "\" stroke=\"" << colour << "\" stroke-width=\"1.5\"/><polygon points=\"" << px(to.x()) << ',' << px(to.y()) << ' ' << px(a.x())
       << ',' << px(a.y()) << ' ' << px(b.x()) << ',' << px(b.y()) << "\" fill=\"" << colour << "\"/>";
    return os.str();
}

std::string pivot_mark(const Eigen::Vector2d& c) {
    std::ostringstream os;
    os << "<g class=\"pivot\"><circle cx=\"" << px(c.x()) << "\" cy=\"" << px(c.y()) << "\" r=\"4\" fill=\"#ffffff\" stroke=\"#000000\"/>"
       << "<line x1=\"" << px(c.x() - 6) << "\" y1=\"" << px(c.y()) << "\" x2=\"" << px(c.x() + 6) << "\" y2=\"" << px(c.y())
       << "\" stroke=\"#000000\"/><line x1=\"" << px(c.x()) << "\" y1=\"" << px(c.y() - 6) << "\" x2=\"" << px(c.x()) << "\" y2=\""
       << px(c.y() + 6) << "\" stroke=\"#000000\"/></g>";
    return os.str();
}

// A translation's axis through the drawing's centre, from its lower to its upper limit.
std::string axis_mark(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d d = (b - a).norm() > 0 ? Eigen::Vector2d((b - a).normalized()) : Eigen::Vector2d(1, 0);
    const Eigen::Vector2d n(-d.y(), d.x());
    std::ostringstream os;
    os << "<g class=\"translation-axis\" stroke=\"#555555\"><line x1=\"" << px(a.x()) << "\" y1=\"" << px(a.y()) << "\" x2=\"" << px(b.x())
       << "\" y2=\"" << px(b.y()) << "\" stroke-dasharray=\"6,3\"/>";
    for (const auto& e : {a, b})
        os << "<line x1=\"" << px(e.x() - 5 * n.x()) << "\" y1=\"" << px(e.y() - 5 * n.y()) << "\" x2=\"" << px(e.x() + 5 * n.x())
           << "\" y2=\"" << px(e.y() + 5 * n.y()) << "\"/>";
    os << "</g>";
    return os.str();
}

// Motion arrows are one colour, apart from the parts' and the normals' colours.
constexpr const char* motion_colour = "#d35400";

std::vector<detail::LegendRow> legend_rows(const std::vector<DrawnPart>& parts) {
    std::vector<detail::LegendRow> rows;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Part& p = *parts[k].part;
        const std::string colour = detail::part_colour(k);
        rows.push_back({"<rect width=\"24\" height=\"10\" fill=\"" + colour + "\" fill-opacity=\"0.3\" stroke=\"" + colour + "\"/>",
                        p.name + (p.rotates() ? " (turns)" : p.translates() ? " (slides)" : " (fixed)")});
    }
    const auto any = [&](bool (Part::*kind)() const noexcept) {
        return std::any_of(parts.begin(), parts.end(), [&](const DrawnPart& d) { return (d.part->*kind)(); });
    };
    if (any(&Part::rotates)) rows.push_back({pivot_mark({12, 5}), "pivot"});
    if (any(&Part::translates)) rows.push_back({axis_mark({1, 5}, {23, 5}), "translation axis, limits"});
    rows.push_back({"<circle cx=\"3\" cy=\"5\" r=\"3\" fill=\"#000000\"/>" + arrow({3, 5}, {24, 5}, "#000000"), "contact, outward normal"});
    if (std::any_of(parts.begin(), parts.end(), [](const DrawnPart& d) { return d.motion != 0; }))
        rows.push_back({arrow({1, 5}, {24, 5}, motion_colour), "motion (+: counter-clockwise, along the axis)"});
    return rows;
}

}  // namespace

Eigen::Vector2d DrawingFrame::pixel(const Eigen::Vector2d& w) const {
    return {pixel_centre.x() + scale * (w.x() - centre.x()), pixel_centre.y() - scale * (w.y() - centre.y())};
}

std::string DrawingFrame::world_transform() const {
    const Eigen::Vector2d o = pixel(Eigen::Vector2d::Zero());
    return "translate(" + wn(o.x()) + ' ' + wn(o.y()) + ") scale(" + wn(scale) + ' ' + wn(-scale) + ')';
}

void extend_motion_bounds(const Part& p, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
    if (p.rotates()) {
        const Eigen::Vector2d r = Eigen::Vector2d::Constant(p.reach());
        lo = lo.cwiseMin(p.dof.pivot - r);
        hi = hi.cwiseMax(p.dof.pivot + r);
        return;
    }
    for (double q : p.translates() ? std::vector<double>{p.lo, p.hi} : std::vector<double>{0.0})
        for (const auto& profile : p.profiles) extend_bounds(transformed(profile, p.pose(q)), lo, hi);
}

std::string part_transform(const Part& p, double q) {
    if (p.rotates()) return "rotate(" + wn(q * 180.0 / std::numbers::pi) + ' ' + wn(p.dof.pivot.x()) + ' ' + wn(p.dof.pivot.y()) + ')';
    if (p.translates()) return "translate(" + wn(q * p.dof.axis.x()) + ' ' + wn(q * p.dof.axis.y()) + ')';
    return "";
}

std::string outline_path(const Part& p) {
    std::string d;
    for (const auto& profile : p.profiles) {
        if (profile.segments.empty()) continue;
        d += 'M' + wn(profile.segments.front().from.x()) + ',' + wn(profile.segments.front().from.y());
        for (const auto& s : profile.segments) {
            if (!s.is_arc()) {
                d += 'L' + wn(s.to.x()) + ',' + wn(s.to.y());
                continue;
            }
            // In world coordinates (y up) SVG's positive-angle sweep is counter-clockwise; an arc of
            // a whole turn is drawn as two halves (SVG draws nothing between equal ends).
            const double sweep = s.sweep(), r = s.radius();
            const int halves = std::abs(sweep) > 1.5 * std::numbers::pi ? 2 : 1;
            for (int h = 1; h <= halves; ++h) {
                const double a = s.start_angle() + sweep * h / halves;
                const Eigen::Vector2d to = h == halves ? s.to : Eigen::Vector2d(s.centre + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
                d += 'A' + wn(r) + ',' + wn(r) + " 0 " + (std::abs(sweep) / halves > std::numbers::pi ? '1' : '0') + ' ' +
                     (s.ccw ? '1' : '0') + ' ' + wn(to.x()) + ',' + wn(to.y());
            }
        }
        d += 'Z';
    }
    return d;
}

std::string motion_arrow(const Part& p, double q, int sign, double scale) {
    if (sign == 0 || p.fixed()) return "";
    sign = sign > 0 ? 1 : -1;
    const double head = 10 / scale, half = 4.5 / scale;  // the head in pixels
    Eigen::Vector2d tip, along;
    std::string line;
    if (p.rotates()) {
        // An arc of 90 degrees about the pivot, inside the part's reach, ending in the direction
        // of turning (world coordinates: y up, so sweep flag 1 is counter-clockwise).
        const double r = 0.6 * p.reach(), from = std::numbers::pi / 6, to = from + sign * std::numbers::pi / 2;
        const Eigen::Vector2d c = p.dof.pivot, a = c + r * Eigen::Vector2d(std::cos(from), std::sin(from));
        tip = c + r * Eigen::Vector2d(std::cos(to), std::sin(to));
        along = sign * Eigen::Vector2d(-std::sin(to), std::cos(to));
        line = "<path d=\"M" + wn(a.x()) + ',' + wn(a.y()) + 'A' + wn(r) + ',' + wn(r) + " 0 0 " + (sign > 0 ? '1' : '0') + ' ' + wn(tip.x()) +
               ',' + wn(tip.y()) + "\"";
    } else {
        const Eigen::Vector2d c = drawing_centre(p);
        along = sign * p.dof.axis.normalized();
        const double length = 44 / scale;
        tip = c + 0.5 * length * along;
        const Eigen::Vector2d a = c - 0.5 * length * along;
        line = "<path d=\"M" + wn(a.x()) + ',' + wn(a.y()) + 'L' + wn(tip.x()) + ',' + wn(tip.y()) + "\"";
    }
    const Eigen::Vector2d n(-along.y(), along.x()), base = tip - head * along, l = base + half * n, r = base - half * n;
    std::ostringstream os;
    os << "<g class=\"motion\" data-part=\"" << xml_text(p.name) << "\" data-motion=\"" << (sign > 0 ? '+' : '-') << "\" transform=\""
       << part_transform(p, q) << "\">" << line << " fill=\"none\" stroke=\"" << motion_colour
       << "\" stroke-width=\"2.5\" vector-effect=\"non-scaling-stroke\"/><polygon points=\"" << wn(tip.x()) << ',' << wn(tip.y()) << ' '
       << wn(l.x()) << ',' << wn(l.y()) << ' ' << wn(r.x()) << ',' << wn(r.y()) << "\" fill=\"" << motion_colour << "\"/></g>";
    return os.str();
}

DrawingFrame parts_frame(const std::vector<DrawnPart>& parts, const DrawingOptions& o) {
    const double big = std::numeric_limits<double>::infinity();
    Eigen::Vector2d lo(big, big), hi(-big, -big);
    for (const auto& d : parts) extend_motion_bounds(*d.part, lo, hi);
    if (!(lo.x() <= hi.x())) lo = hi = Eigen::Vector2d::Zero();
    std::ostringstream title;  // only its height matters here
    const double left = 12, top = detail::write_title(title, o.title, 12, o.width - 24, 4) + 8, right = o.width - 12 - (o.legend ? legend_width : 0), bottom = o.height - 12;
    const Eigen::Vector2d size = (hi - lo).cwiseMax(1e-300);
    DrawingFrame f;
    f.centre = 0.5 * (lo + hi);
    f.pixel_centre = {0.5 * (left + right), 0.5 * (top + bottom)};
    f.scale = std::max(1e-300, std::min(std::max(right - left, 10.0) / size.x(), std::max(bottom - top, 10.0) / size.y()));
    return f;
}

void write_contact_marks(std::ostream& os, const DrawingFrame& f, const std::vector<DrawnPart>& parts, const std::vector<ContactMark>& contacts,
                         const DrawingOptions& o) {
    std::vector<detail::LabelRequest> requests;
    std::vector<std::pair<std::string, const char*>> texts;
    std::ostringstream marks;
    for (const auto& c : contacts) {
        const Eigen::Vector2d at = f.pixel(c.point);
        marks << "<g class=\"contact\"><title>" << xml_text(c.note) << "</title><circle cx=\"" << px(at.x()) << "\" cy=\"" << px(at.y())
              << "\" r=\"3\" fill=\"#000000\"/>";
        for (int k = 0; k < 2; ++k) {
            const auto& n = c.normals[static_cast<std::size_t>(k)];
            if (!n) continue;
            QM_REQUIRE(c.parts[static_cast<std::size_t>(k)] < parts.size(), "a contact mark names a drawn part");
            const char* colour = detail::part_colour(c.parts[static_cast<std::size_t>(k)]);
            const Eigen::Vector2d d = Eigen::Vector2d(n->x(), -n->y()).normalized(), tip = at + arrow_length * d;
            marks << arrow(at, tip, colour);
            const std::string text = to_string(qualitative(*n, o.normal_zero_tolerance));
            requests.push_back({tip.x() + 4 * d.x(), tip.y() + 4 * d.y(), text.size()});
            texts.emplace_back(text, colour);
        }
        marks << "</g>\n";
    }
    const auto layout = detail::layout_labels(requests, {}, o.width, o.height);
    os << "<g class=\"contacts\">\n" << marks.str() << "<g font-size=\"9\" font-family=\"sans-serif\">\n";
    for (std::size_t k = 0; k < texts.size(); ++k)
        os << "<text x=\"" << px(layout.labels[k].x) << "\" y=\"" << px(layout.labels[k].y) << "\" fill=\"" << texts[k].second << "\">"
           << texts[k].first << "</text>\n";
    os << "</g></g>\n";
}

void write_parts_svg(std::ostream& os, const std::vector<DrawnPart>& parts, const std::vector<ContactMark>& contacts, const DrawingOptions& o) {
    const DrawingFrame f = parts_frame(parts, o);
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.width << "\" height=\"" << o.height << "\" viewBox=\"0 0 " << o.width << ' '
       << o.height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    const double below_title = detail::write_title(os, o.title, 12, o.width - 24, 4) + 8;
    os << "<g class=\"world\" transform=\"" << f.world_transform() << "\">\n";
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const Part& p = *parts[k].part;
        QM_REQUIRE(!p.profiles.empty(), "a drawn part has outlines");
        const char* colour = detail::part_colour(k);
        os << "<g class=\"part\" data-part=\"" << xml_text(p.name) << "\" transform=\"" << part_transform(p, parts[k].q) << "\"><path d=\""
           << outline_path(p) << "\" fill=\"" << colour << "\" fill-opacity=\"0.3\" stroke=\"" << colour
           << "\" stroke-width=\"1.5\" vector-effect=\"non-scaling-stroke\" stroke-linejoin=\"round\"/>";
        if (p.translates()) {  // the reference point that moves along the axis mark
            const Eigen::Vector2d c = drawing_centre(p);
            os << "<circle cx=\"" << wn(c.x()) << "\" cy=\"" << wn(c.y()) << "\" r=\"" << wn(3 / f.scale) << "\" fill=\"#555555\"/>";
        }
        os << "</g>\n";
    }
    os << "</g>\n";
    if (std::any_of(parts.begin(), parts.end(), [](const DrawnPart& d) { return d.motion != 0; })) {
        os << "<g class=\"motions\" transform=\"" << f.world_transform() << "\">";
        for (const auto& d : parts) os << motion_arrow(*d.part, d.q, d.motion, f.scale);
        os << "</g>\n";
    }
    os << "<g class=\"marks\">\n";
    for (const auto& d : parts) {
        const Part& p = *d.part;
        if (p.rotates()) os << pivot_mark(f.pixel(p.dof.pivot)) << '\n';
        if (p.translates()) {
            const Eigen::Vector2d c = drawing_centre(p);
            os << axis_mark(f.pixel(c + p.lo * p.dof.axis), f.pixel(c + p.hi * p.dof.axis)) << '\n';
        }
    }
    os << "</g>\n";
    write_contact_marks(os, f, parts, contacts, o);
    if (o.legend) (void)detail::write_legend(os, legend_rows(parts), o.width - legend_width, below_title, "Legend");
    os << "</svg>\n";
}

}  // namespace qm::geometry
