// geometry/cspace_svg.cpp
#include "geometry/cspace_svg.hpp"

#include "qm/assert.hpp"

#include <cmath>

namespace qm::geometry {

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
    if (!o.title.empty()) os << "<text x=\"" << margin << "\" y=\"20\" font-size=\"14\">" << o.title << "</text>\n";
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
        if (p.kind == PlaceKind::external_division) polyline(p.points, "stroke=\"#c03030\" stroke-dasharray=\"2,2\"");
        if (p.kind == PlaceKind::join)
            os << "<circle cx=\"" << X(p.points.front().x()) << "\" cy=\"" << Y(p.points.front().y())
               << "\" r=\"3\" fill=\"white\" stroke=\"black\"/>\n";
    }
    os << "</g>\n";
    if (o.numbers) {
        os << "<g font-size=\"9\" font-family=\"sans-serif\">\n";
        for (const Place& p : v.places) {
            Eigen::Vector2d at = p.points.empty() ? Eigen::Vector2d::Zero() : p.points[p.points.size() / 2];
            if ((p.kind == PlaceKind::fsd || p.kind == PlaceKind::external_division) && p.points.size() == 2)
                at = 0.5 * (p.points[0] + p.points[1]);  // not periodic along it: a straight piece
            const char* colour = p.kind == PlaceKind::face ? "#006000" : p.kind == PlaceKind::join ? "#800000" : "black";
            os << "<text x=\"" << X(at.x()) + 3 << "\" y=\"" << Y(at.y()) - 3 << "\" fill=\"" << colour << "\">" << p.id.value
               << "</text>\n";
        }
        os << "</g>\n";
    }
    os << "<text x=\"" << o.width / 2 << "\" y=\"" << o.height - 10 << "\" font-size=\"11\">q0</text>\n"
       << "<text x=\"8\" y=\"" << o.height / 2 << "\" font-size=\"11\">q1</text>\n</svg>\n";
    os.precision(precision);
}

}  // namespace qm::geometry
