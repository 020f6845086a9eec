// geometry/cspace_svg.cpp
#include "geometry/cspace_svg.hpp"

#include "qm/assert.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace qm::geometry {

namespace {

// A title comes from part names, which the metric format lets hold XML's special characters.
std::string xml_text(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
}

// A label's box in pixels: 9 px sans-serif digits are at most about 5.5 px wide and 9 px tall.
struct LabelBox {
    double x0, y0, x1, y1;
    [[nodiscard]] bool overlaps(const LabelBox& b) const { return x0 < b.x1 && b.x0 < x1 && y0 < b.y1 && b.y0 < y1; }
};

LabelBox box_at(double x, double y, std::size_t digits) {  // (x, y): the text's baseline start
    return {x, y - 8.5, x + 5.5 * static_cast<double>(digits), y + 1};
}

// Place numbers where a reader can tell them apart (the thesis' figures number every place; in a
// dense region, near a needle or a cluster of joins, numbers drawn at their places overprint
// each other). Each number goes at its place if it fits there, else at the nearest free spot on
// rings around it, with a thin leader back to the place; joins are placed first (they are points),
// faces last (they have room). Where no spot within the rings is free it is drawn at its place.
template <class ToX, class ToY>
void write_place_numbers(std::ostream& os, const PlaceVocabulary& v, const SvgOptions& o, const ToX& X, const ToY& Y) {
    std::vector<LabelBox> circles, taken;
    for (const Place& p : v.places)
        if (p.kind == PlaceKind::join && !p.points.empty())
            circles.push_back({X(p.points.front().x()) - 3, Y(p.points.front().y()) - 3, X(p.points.front().x()) + 3,
                             Y(p.points.front().y()) + 3});
    auto order = [](PlaceKind k) {
        return k == PlaceKind::join ? 0 : k == PlaceKind::cseg ? 1 : k == PlaceKind::face ? 3 : 2;
    };
    std::vector<const Place*> places;
    for (const Place& p : v.places) places.push_back(&p);
    std::stable_sort(places.begin(), places.end(), [&](const Place* a, const Place* b) { return order(a->kind) < order(b->kind); });
    os << "<g font-size=\"9\" font-family=\"sans-serif\">\n";
    for (const Place* p : places) {
        Eigen::Vector2d at = p->points.empty() ? Eigen::Vector2d::Zero() : p->points[p->points.size() / 2];
        if ((p->kind == PlaceKind::fsd || p->kind == PlaceKind::external_division) && p->points.size() == 2)
            at = 0.5 * (p->points[0] + p->points[1]);  // not periodic along it: a straight piece
        const double ax = X(at.x()), ay = Y(at.y());
        const std::size_t digits = std::to_string(p->id.value).size();
        auto fits = [&](const LabelBox& b) {
            // Two pixels' gap between numbers, so that neighbours do not read as one ("35" "16":
            // "3516"); none needed from the joins' circles.
            const LabelBox padded{b.x0 - 2, b.y0 - 1, b.x1 + 2, b.y1 + 1};
            return b.x0 >= 0 && b.y0 >= 0 && b.x1 <= o.width && b.y1 <= o.height &&
                   std::none_of(taken.begin(), taken.end(), [&](const LabelBox& t) { return t.overlaps(padded); }) &&
                   std::none_of(circles.begin(), circles.end(), [&](const LabelBox& t) { return t.overlaps(b); });
        };
        double tx = ax + 3, ty = ay - 3;
        bool moved = false;
        if (!fits(box_at(tx, ty, digits))) {
            bool found = false;
            for (double radius : {8.0, 13.0, 19.0, 26.0, 34.0, 44.0}) {
                for (int k = 0; k < 12 && !found; ++k) {
                    const double angle = k * 3.14159265358979 / 6;
                    const double cx = ax + radius * std::cos(angle), cy = ay - radius * std::sin(angle);
                    // the box centred on (cx, cy)
                    const double x = cx - 2.75 * static_cast<double>(digits), y = cy + 4;
                    if (fits(box_at(x, y, digits))) {
                        tx = x;
                        ty = y;
                        found = moved = true;
                    }
                }
                if (found) break;
            }
        }
        const LabelBox b = box_at(tx, ty, digits);
        taken.push_back(b);
        if (moved)
            os << "<line x1=\"" << ax << "\" y1=\"" << ay << "\" x2=\"" << std::clamp(ax, b.x0, b.x1) << "\" y2=\""
               << std::clamp(ay, b.y0, b.y1) << "\" stroke=\"#888888\" stroke-width=\"0.5\"/>\n";
        const char* colour = p->kind == PlaceKind::face ? "#006000" : p->kind == PlaceKind::join ? "#800000" : "black";
        os << "<text x=\"" << tx << "\" y=\"" << ty << "\" fill=\"" << colour << "\">" << p->id.value << "</text>\n";
    }
    os << "</g>\n";
}

}  // namespace

void write_cspace_svg(std::ostream& os, const CSpaceResult& space, const PlaceVocabulary& v, const SvgOptions& o) {
    QM_REQUIRE(space.status == CSpaceStatus::ok, "write_cspace_svg needs a classified space");
    const auto& r = space.request;
    const double margin = 40;
    const double w = o.width - 2 * margin, h = o.height - 2 * margin;
    auto X = [&](double q0) { return margin + w * (q0 - r.axes[0].lo) / r.axes[0].span(); };
    auto Y = [&](double q1) { return o.height - margin - h * (q1 - r.axes[1].lo) / r.axes[1].span(); };
    const auto precision = os.precision(6);
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.width << "\" height=\"" << o.height << "\">\n"
       << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    if (!o.title.empty()) os << "<text x=\"" << margin << "\" y=\"20\" font-size=\"14\">" << xml_text(o.title) << "</text>\n";
    // Blocked space: one shaded cell per blocked sample, centred on it.
    const double cw = w * r.axes[0].step() / r.axes[0].span(), ch = h * r.axes[1].step() / r.axes[1].span();
    // Everything drawn in the configuration space is clipped to its frame: a blocked cell at the
    // edge is centred on it, and a line crossing a periodic seam is drawn on past it.
    os << "<clipPath id=\"frame\"><rect x=\"" << margin << "\" y=\"" << margin << "\" width=\"" << w << "\" height=\"" << h
       << "\"/></clipPath>\n<g fill=\"#bbbbbb\" stroke=\"none\" clip-path=\"url(#frame)\">\n";
    for (int j = 0; j < r.axes[1].samples; ++j)
        for (int i = 0; i < r.axes[0].samples; ++i)
            if (space.is_blocked(i, j))
                os << "<rect x=\"" << X(r.axes[0].sample(i)) - cw / 2 << "\" y=\"" << Y(r.axes[1].sample(j)) - ch / 2 << "\" width=\""
                   << cw << "\" height=\"" << ch << "\"/>\n";
    os << "</g>\n<rect x=\"" << margin << "\" y=\"" << margin << "\" width=\"" << w << "\" height=\"" << h
       << "\" fill=\"none\" stroke=\"black\"/>\n<g clip-path=\"url(#frame)\">\n";
    // Polylines, broken where they wrap around a periodic axis.
    auto polyline = [&](const std::vector<Eigen::Vector2d>& pts, const char* style) {
        std::vector<Eigen::Vector2d> run;
        auto flush = [&] {
            if (run.size() >= 2) {
                os << "<polyline fill=\"none\" " << style << " points=\"";
                for (const auto& p : run) os << X(p.x()) << ',' << Y(p.y()) << ' ';
                os << "\"/>\n";
            }
            run.clear();
        };
        // Consecutive points are less than half a period apart (CSEG points are a cell apart,
        // divisions carry points a quarter period apart), so the short way between them is the
        // way the line goes; where it crosses a seam the line is drawn on past the frame (the
        // clip path cuts it) and starts again from the other side.
        for (std::size_t k = 0; k < pts.size(); ++k) {
            if (!run.empty()) {
                const Eigen::Vector2d d = difference(r, run.back(), pts[k]);
                const Eigen::Vector2d raw = pts[k] - run.back();
                if ((d - raw).norm() > 0.25 * std::min(r.axes[0].span(), r.axes[1].span())) {
                    run.push_back(run.back() + d);
                    flush();
                    run.push_back(pts[k] - d);
                }
            }
            run.push_back(pts[k]);
        }
        flush();
    };
    for (const Place& p : v.places) {
        if (p.kind == PlaceKind::cseg) polyline(p.points, "stroke=\"black\" stroke-width=\"2\"");
        // A division on a periodic axis carries points a quarter period apart at most
        // (place_vocabulary.hpp), so the seam test above breaks it where it wraps.
        if (p.kind == PlaceKind::fsd) polyline(p.points, "stroke=\"#3050c0\" stroke-dasharray=\"5,3\"");
        if (p.kind == PlaceKind::stop) polyline(p.points, "stroke=\"black\" stroke-width=\"4\"");
        if (p.kind == PlaceKind::external_division) polyline(p.points, "stroke=\"#c03030\" stroke-dasharray=\"2,2\"");
        if (p.kind == PlaceKind::join)
            os << "<circle cx=\"" << X(p.points.front().x()) << "\" cy=\"" << Y(p.points.front().y())
               << "\" r=\"3\" fill=\"white\" stroke=\"black\"/>\n";
    }
    os << "</g>\n";
    if (o.numbers) write_place_numbers(os, v, o, X, Y);
    os << "<text x=\"" << o.width / 2 << "\" y=\"" << o.height - 10 << "\" font-size=\"11\">q0</text>\n"
       << "<text x=\"8\" y=\"" << o.height / 2 << "\" font-size=\"11\">q1</text>\n</svg>\n";
    os.precision(precision);
}

}  // namespace qm::geometry
