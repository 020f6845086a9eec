// geometry/part_generators.cpp: the thesis' parts as profiles of lines and arcs (chapters 7, 9).
#include "geometry/part_generators.hpp"

#include "qm/assert.hpp"
#include "qm/spelling.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace qm::geometry {
namespace {

using V = Eigen::Vector2d;
constexpr double pi = std::numbers::pi;

V polar(double r, double a) { return {r * std::cos(a), r * std::sin(a)}; }
V rotate(const V& x, double a) { return Eigen::Rotation2Dd(a) * x; }

ShapeResult fail(std::string msg, int param = -1) { return {std::nullopt, std::move(msg), param}; }

// The mirror image in the y axis (x -> -x): a reflection reverses the sense of every arc; ok()
// makes the outline counter-clockwise again.
Profile mirrored(const Profile& p) {
    auto flip = [](const V& x) { return V(-x.x(), x.y()); };
    Profile out;
    for (const auto& s : p.segments) {
        Segment m = s;
        m.from = flip(s.from);
        m.to = flip(s.to);
        m.centre = flip(s.centre);
        m.ccw = !s.ccw;
        out.segments.push_back(m);
    }
    return out;
}

// The `mirror` parameter: 0 as drawn, 1 the mirror image; anything else is refused.
std::optional<ShapeResult> bad_mirror(double m, int param) {
    if (m != 0 && m != 1) return fail("mirror must be 0 (as drawn) or 1 (the mirror image)", param);
    return std::nullopt;
}
ShapeResult ok(std::vector<Profile> profiles, int symmetry) {
    for (auto& p : profiles) p = counter_clockwise(p);
    return {Shape{std::move(profiles), symmetry}, {}, -1};
}

std::string decimal(double x) {
    std::ostringstream os;
    os.precision(6);
    os << x;
    return os.str();
}

// Spur gear. Each flank is the circle through three points of the true involute (at the base
// or root circle, the pitch circle and the tip circle), down to the base circle, then a radial
// line to the root (as an involute tooth has below its base circle); tip and root are arcs.
// Lines and arcs only, as the thesis' drawings (8.1.1), and nearly conjugate, so meshing gears
// keep their play. Play is the backlash of this gear on its pitch circle: the tooth is thinner
// than half the circular pitch by that much, so two gears at centre distance R1 + R2 have
// play1 + play2 between their teeth.
ShapeResult spur_gear(const std::vector<double>& v) {
    const int n = static_cast<int>(v[0]);
    const double R = v[1], play = v[2], phi = v[3] * pi / 180, m = 2 * R / n;
    const double Ra = R + v[4] * m, Rf = R - v[5] * m, Rb = R * std::cos(phi);
    const double thickness = pi * m / 2 - play;
    if (thickness <= 0) return fail("the play " + decimal(play) + " leaves no tooth: it must be below half the circular pitch, " + decimal(pi * m / 2), 2);
    if (phi <= 0 || phi >= pi / 3) return fail("the pressure angle must lie between 0 and 60 degrees", 3);
    if (Rf <= 0) return fail("the dedendum reaches the centre; use fewer modules or more teeth", 5);
    // The upper flank's involute: polar angle at radius r >= Rb (the tooth's centre line at 0).
    auto inv = [](double a) { return std::tan(a) - a; };
    auto involute = [&](double r) { return polar(r, thickness / (2 * R) + inv(phi) - inv(std::acos(Rb / r))); };
    const double r_low = std::max(Rf, Rb);
    const V tip = involute(Ra), pitch_point = involute(R), low = involute(r_low);
    const V root = polar(Rf, std::atan2(low.y(), low.x()));
    const double bt = std::atan2(tip.y(), tip.x()), br = std::atan2(root.y(), root.x());
    if (bt <= 1e-9) return fail("the teeth come to a point below the tip circle; use less play or a smaller addendum", 4);
    if (br >= pi / n - 1e-9) return fail("the teeth leave no root between them; use a larger play or a smaller pressure angle", 2);
    // The circle through the three involute points.
    const V a = tip - low, b = pitch_point - low;
    const double det = 2 * (a.x() * b.y() - a.y() * b.x());
    if (std::abs(det) < 1e-15 * R * R) return fail("the flank is too short to draw; use a larger addendum", 4);
    const V T = low + V(b.y() * a.squaredNorm() - a.y() * b.squaredNorm(), a.x() * b.squaredNorm() - b.x() * a.squaredNorm()) / det;
    const bool radial = (low - root).norm() > 1e-12 * R;
    // The upper flank runs from the tip down to the low point about T, the short way.
    const double a0 = std::atan2(tip.y() - T.y(), tip.x() - T.x()), a1 = std::atan2(low.y() - T.y(), low.x() - T.x());
    const bool down_ccw = std::remainder(a1 - a0, 2 * pi) > 0;
    auto mirror = [](V x) { return V(x.x(), -x.y()); };
    Profile p;
    for (int i = 0; i < n; ++i) {
        const double ai = 2 * pi * i / n, bi = 2 * pi * ((i + 1) % n) / n;
        const V c_up = rotate(T, ai), c_lo = rotate(mirror(T), ai);
        if (radial) p.segments.push_back(Segment::line(rotate(mirror(root), ai), rotate(mirror(low), ai)));
        p.segments.push_back(Segment::arc(rotate(mirror(low), ai), rotate(mirror(tip), ai), c_lo, down_ccw));
        p.segments.push_back(Segment::arc(rotate(mirror(tip), ai), rotate(tip, ai), V::Zero(), true));
        p.segments.push_back(Segment::arc(rotate(tip, ai), rotate(low, ai), c_up, down_ccw));
        if (radial) p.segments.push_back(Segment::line(rotate(low, ai), rotate(root, ai)));
        p.segments.push_back(Segment::arc(rotate(root, ai), rotate(mirror(root), bi), V::Zero(), true));
    }
    return ok({p}, n);
}

// Ratchet wheel: sawtooth teeth, each a slope rising counter-clockwise to the tip and a radial
// face back to the root. The radial faces face counter-clockwise, so a pawl resting against one
// stops the wheel turning counter-clockwise and lets it turn clockwise (thesis 9.2). Mirrored,
// the faces face clockwise and stop clockwise turning: the QRG clock's ratchet, which the spring
// turns clockwise while it turns gear 6 counter-clockwise (9.1).
ShapeResult ratchet_wheel(const std::vector<double>& v) {
    const int n = static_cast<int>(v[0]);
    const double Rr = v[1], Rt = v[2];
    if (Rt <= Rr) return fail("the tip radius must be larger than the root radius", 2);
    if (auto bad = bad_mirror(v[3], 3)) return *bad;
    std::vector<V> root(n), tip(n);
    for (int i = 0; i < n; ++i) {
        root[i] = polar(Rr, 2 * pi * i / n);
        tip[i] = polar(Rt, 2 * pi * i / n);
    }
    Profile p;
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        p.segments.push_back(Segment::line(root[i], tip[j]));
        p.segments.push_back(Segment::line(tip[j], root[j]));
    }
    return ok({v[3] == 1 ? mirrored(p) : p}, n);
}

// Scape wheel: per pitch, a root arc (root-land of the pitch), a back rising to the tip at
// `lean` of the pitch, and the locking face falling to the next root.
ShapeResult scape_wheel(const std::vector<double>& v) {
    const int n = static_cast<int>(v[0]);
    const double Rr = v[1], Rt = v[2], lean = v[3], land = v[4];
    if (Rt <= Rr) return fail("the tip radius must be larger than the root radius", 2);
    if (lean >= 1) return fail("the lean must be below 1 (a fraction of the pitch)", 3);
    if (land >= lean) return fail("the root land must be smaller than the lean", 4);
    const double pitch = 2 * pi / n;
    std::vector<V> root(n), land_end(n), tip(n);
    for (int i = 0; i < n; ++i) {
        root[i] = polar(Rr, i * pitch);
        land_end[i] = polar(Rr, (i + land) * pitch);
        tip[i] = polar(Rt, (i + lean) * pitch);
    }
    Profile p;
    for (int i = 0; i < n; ++i) {
        if (land > 0) p.segments.push_back(Segment::arc(root[i], land_end[i], V::Zero(), true));
        p.segments.push_back(Segment::line(land > 0 ? land_end[i] : root[i], tip[i]));
        p.segments.push_back(Segment::line(tip[i], root[(i + 1) % n]));
    }
    return ok({p}, n);
}

// Anchor pallets, pivot at the origin, straddling a scape wheel below: two arms ending in
// pallets `span` either side and `reach` below the pivot, joined by a bridge whose top is an arc
// about the pivot. With `hub` 0 the arc runs through (+-span, top) (the first drawing, whose
// top reaches sqrt(span^2 + top^2) from the pivot: turned upside down it swept into the wheel).
// With `hub` > 0 the arms' outer edges rise to a hub, an arc of that radius about the pivot
// with its ends at height `top`; nothing of the anchor is then further than `hub` from the pivot
// above the arms, so with hub below (pivot distance - wheel tip radius) the pallets can turn all
// the way round and clear the wheel when inverted (thesis 9.1, Figures 9.2, 9.22-9.24).
ShapeResult anchor(const std::vector<double>& v) {
    const double s = v[0], r = v[1], w = v[2], t = v[3], h = v[4];
    if (s <= 2.5 * w) return fail("the span must exceed 2.5 arm widths", 0);
    if (r <= w) return fail("the reach must exceed the arm width", 1);
    double top_x = s;  // where the top arc ends, either side of the centre line
    if (h > 0) {
        if (h <= std::abs(t)) return fail("the hub must be larger than the height of its ends (top)", 4);
        top_x = std::sqrt(h * h - t * t);
        if (top_x <= s - 2.5 * w + 0.25 * w) return fail("the hub must reach beyond the arms' inner edges (span - 2.25 widths)", 4);
    }
    const std::vector<V> pts = {{-top_x, t}, {-s + 0.5 * w, -r}, {-s + 1.5 * w, -r + 0.5 * w}, {-s + 2.5 * w, -0.5 * w},
                                {s - 2.5 * w, -0.5 * w}, {s - 1.5 * w, -r + 0.5 * w}, {s - 0.5 * w, -r}, {top_x, t}};
    Profile p;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) p.segments.push_back(Segment::line(pts[i], pts[i + 1]));
    p.segments.push_back(Segment::arc(pts.back(), pts.front(), V::Zero(), true));
    return ok({p}, 1);
}

// Pawl, pivot at the origin: a round hub of radius `width` and an arm hanging straight down to
// a slanted tip at `length` (turn the part to point it elsewhere); its lowest point is on the -x
// side of the arm, or on the +x side when mirrored (the pawl of a mirrored ratchet wheel).
ShapeResult pawl(const std::vector<double>& v) {
    const double L = v[0], w = v[1];
    if (L <= 2 * w) return fail("the length must exceed two widths", 0);
    if (auto bad = bad_mirror(v[2], 2)) return *bad;
    const double h = std::sqrt(3.0) / 2 * w;
    const V a(-w / 2, -h), b(-w / 2, -L), c(w / 2, -L + w), d(w / 2, -h);
    Profile p{{Segment::line(a, b), Segment::line(b, c), Segment::line(c, d), Segment::arc(d, a, V::Zero(), true)}};
    return ok({v[2] == 1 ? mirrored(p) : p}, 1);
}

// Scotch-yoke crank: the pin that runs in the yoke's slot, at `crank-radius` along x.
ShapeResult crank(const std::vector<double>& v) { return ok({circle_profile(V(v[0], 0), v[1])}, 1); }

// Scotch-yoke yoke: a slot along y of `slot-width` between two bars of `bar-width`, `length` long.
ShapeResult yoke(const std::vector<double>& v) {
    const double w = v[0], b = v[1], L = v[2];
    auto rect = [](double x0, double y0, double x1, double y1) { return polygon_profile({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}); };
    return ok({rect(-w / 2 - b, -L / 2, -w / 2, L / 2), rect(w / 2, -L / 2, w / 2 + b, L / 2)}, 1);
}

// Disk cam: a circle of `radius` whose centre is `eccentricity` along x from the pivot.
ShapeResult disk_cam(const std::vector<double>& v) { return ok({circle_profile(V(v[1], 0), v[0])}, 1); }

// Flat-faced follower: a rectangle whose lower face lies on y = 0, centred on x = 0.
ShapeResult follower(const std::vector<double>& v) {
    const double w = v[0], h = v[1];
    return ok({polygon_profile({{-w / 2, 0}, {w / 2, 0}, {w / 2, h}, {-w / 2, h}})}, 1);
}

ShapeResult block(const std::vector<double>& v) {
    const double w = v[0], h = v[1];
    return ok({polygon_profile({{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}})}, 1);
}

}  // namespace

const std::vector<Generator>& generators() {
    static const std::vector<Generator> table = {
        {"spur-gear", "spur gear: flanks as arcs through three points of the involute, tip and root arcs",
         {{"teeth", 12, 6, false, true, "number of teeth"},
          {"pitch-radius", 1, 0, true, false, "radius of the pitch circle"},
          {"play", 0, 0, false, false, "backlash on the pitch circle (length)"},
          {"pressure-angle", 20, 0, true, false, "pressure angle, degrees (below 60)"},
          {"addendum", 1, 0, true, false, "tip above the pitch circle, in modules (module = 2 pitch-radius / teeth)"},
          {"dedendum", 1.25, 0, true, false, "root below the pitch circle, in modules"}},
         spur_gear},
        {"ratchet-wheel", "sawtooth wheel whose radial faces stop counter-clockwise turning",
         {{"teeth", 12, 3, false, true, "number of teeth"},
          {"root-radius", 0.8, 0, true, false, "radius at the tooth roots"},
          {"tip-radius", 1, 0, true, false, "radius at the tooth tips"},
          {"mirror", 0, 0, false, true, "1: the mirror image (x -> -x), whose radial faces stop clockwise turning"}},
         ratchet_wheel},
        {"scape-wheel", "escape wheel: root lands, leaning teeth",
         {{"teeth", 15, 3, false, true, "number of teeth"},
          {"root-radius", 0.85, 0, true, false, "radius of the root lands"},
          {"tip-radius", 1, 0, true, false, "radius at the tooth tips"},
          {"lean", 0.8, 0, true, false, "where the tip lies, as a fraction of the pitch"},
          {"root-land", 0.2, 0, false, false, "length of the root arc, as a fraction of the pitch"}},
         scape_wheel},
        {"anchor", "anchor pallets about the origin, straddling a wheel below",
         {{"span", 0.45, 0, true, false, "distance of each pallet from the centre line"},
          {"reach", 0.5, 0, true, false, "depth of the pallet tips below the pivot"},
          {"width", 0.1, 0, true, false, "width of the arms"},
          {"top", 0.1, 0, true, false, "height of the bridge's ends above the pivot"},
          {"hub", 0, 0, false, false, "0: the bridge's top is an arc through (+-span, top); > 0: the arms rise to a hub of this radius about the pivot"}},
         anchor},
        {"pawl", "pawl about the origin: a hub and an arm hanging down to a slanted tip",
         {{"length", 1, 0, true, false, "pivot to tip"}, {"width", 0.15, 0, true, false, "arm width (and hub radius)"},
          {"mirror", 0, 0, false, true, "1: the mirror image (x -> -x), its tip slanted the other way"}},
         pawl},
        {"crank", "Scotch-yoke crank: its pin",
         {{"crank-radius", 0.6, 0, false, false, "pivot to pin centre"}, {"pin-radius", 0.1, 0, true, false, "radius of the pin"}},
         crank},
        {"yoke", "Scotch-yoke yoke: a slot along y between two bars",
         {{"slot-width", 0.3, 0, true, false, "width of the slot"},
          {"bar-width", 0.3, 0, true, false, "width of each bar"},
          {"length", 4, 0, true, false, "length of the bars"}},
         yoke},
        {"disk-cam", "eccentric circular disk cam",
         {{"radius", 0.5, 0, true, false, "radius of the disk"}, {"eccentricity", 0.2, 0, false, false, "pivot to disk centre, along x"}},
         disk_cam},
        {"follower", "flat-faced follower: a rectangle standing on y = 0",
         {{"width", 2, 0, true, false, "width of the face"}, {"height", 0.5, 0, true, false, "height"}},
         follower},
        {"block", "rectangle centred on the origin",
         {{"width", 1, 0, true, false, "width"}, {"height", 1, 0, true, false, "height"}},
         block},
    };
    return table;
}

const Generator* find_generator(std::string_view name) {
    for (const auto& g : generators())
        if (name == g.name) return &g;
    return nullptr;
}

ShapeResult make_shape(const Generator& g, const std::vector<std::pair<std::string, double>>& settings) {
    std::vector<double> values;
    for (const auto& p : g.params) values.push_back(p.default_value);
    for (const auto& [name, value] : settings) {
        int k = -1;
        for (std::size_t i = 0; i < g.params.size(); ++i)
            if (name == g.params[i].name) k = static_cast<int>(i);
        if (k < 0) {
            std::vector<std::string_view> names;
            for (const auto& p : g.params) names.emplace_back(p.name);
            return fail("'" + name + "' is not a parameter of " + g.name + did_you_mean(name, names));
        }
        values[static_cast<std::size_t>(k)] = value;
    }
    for (std::size_t i = 0; i < g.params.size(); ++i) {
        const auto& p = g.params[i];
        const double x = values[i];
        if (!std::isfinite(x)) return fail(std::string(p.name) + " must be a finite number", static_cast<int>(i));
        if (p.integer && x != std::floor(x)) return fail(std::string(p.name) + " must be a whole number", static_cast<int>(i));
        if (p.min_exclusive ? !(x > p.min) : !(x >= p.min))
            return fail(std::string(p.name) + " must be " + (p.min_exclusive ? "greater than " : "at least ") + decimal(p.min), static_cast<int>(i));
        if (p.integer && x > 10000) return fail(std::string(p.name) + " must be at most 10000", static_cast<int>(i));
    }
    return g.make(values);
}

ShapeResult make_shape(std::string_view name, const std::vector<std::pair<std::string, double>>& settings) {
    const Generator* g = find_generator(name);
    QM_REQUIRE(g != nullptr, "no generator of that name");
    return make_shape(*g, settings);
}

}  // namespace qm::geometry
