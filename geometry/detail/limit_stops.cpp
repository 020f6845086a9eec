// geometry/detail/limit_stops.cpp: the ends of an axis that stops (a translation's limits, a
// window's ends) as places. Where free space reaches such an end the part stands against its
// frame: motion on out is blocked, as at a CSEG (Law 2, 8.1.3), so the free stretches of the end
// become `stop` places between the `limit` joins on it, and each of those joins carries the
// stop's normal. Without them a face touching the limit had no next place under motion out of
// it and stayed itself over an interval: a cam follower could rise for ever at the top of its
// stroke.
#include "geometry/detail/place_builder.hpp"

#include <algorithm>

namespace qm::geometry::detail {
namespace {

QualDirection unit_direction(int axis, int sign) {
    QualDirection d;
    d.s[static_cast<std::size_t>(axis)] = static_cast<std::int8_t>(sign);
    return d;
}

}  // namespace

void Builder::add_stops() {
    for (int k = 0; k < 2; ++k) {
        const auto& ax = r.axes[static_cast<std::size_t>(k)];
        if (ax.periodic || !ax.stops) continue;
        const int o = 1 - k;  // the stop runs along the other axis
        const auto& along = r.axes[static_cast<std::size_t>(o)];
        for (int sign : {1, -1}) {  // the lower end (normal +) and the upper end (normal -)
            const double end = sign > 0 ? ax.lo : ax.hi;
            const QualDirection inward = unit_direction(k, sign);
            Eigen::Vector2d normal = Eigen::Vector2d::Zero();
            normal[k] = sign;
            auto at = [&](double x) {
                Eigen::Vector2d q;
                q[k] = end;
                q[o] = x;
                return q;
            };
            // Free just inside the end (a thousandth of a cell in)?
            auto free_at = [&](double x) {
                Eigen::Vector2d q = at(x);
                q[k] += sign * 1e-3 * ax.step();
                return !blocked(q);
            };
            const double slack = 1e-9 * ax.span();
            std::vector<std::pair<double, PlaceId>> on;
            for (const auto& p : v.places)
                if (p.kind == PlaceKind::join && p.join_kind == JoinKind::limit && std::abs(p.points.front()[k] - end) <= slack)
                    on.push_back({p.points.front()[o], p.id});
            if (!along.periodic)  // the domain's corners end the stop where the other axis ends too
                for (double x : {along.lo, along.hi})
                    if (std::none_of(on.begin(), on.end(), [&](const auto& j) { return std::abs(j.first - x) <= 1e-9 * along.span(); }) &&
                        free_at(x))
                        on.push_back({x, add_join(JoinKind::limit, at(x), {})});
            std::sort(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
            for (const auto& [x, j] : on) {
                auto& ns = v.places[j.value].normals;
                if (std::find(ns.begin(), ns.end(), inward) == ns.end()) ns.push_back(inward);
            }
            auto emit = [&](double from, double to, std::optional<PlaceId> a, std::optional<PlaceId> b) {
                if (!free_at(0.5 * (from + to))) return;
                Place p;
                p.kind = PlaceKind::stop;
                p.axis = o;
                p.normals = {inward};
                const int steps = along.periodic ? std::max(2, static_cast<int>(std::ceil(4 * (to - from) / along.span()))) : 1;
                for (int s = 0; s <= steps; ++s) p.points.push_back(wrap(r, at(from + (to - from) * s / steps)));
                const PlaceId id = add(std::move(p));
                Eigen::Vector2d tangent = Eigen::Vector2d::Zero();
                tangent[o] = 1;
                lines.push_back({id, a, b, wrap(r, at(0.5 * (from + to))), normal, tangent, false});
            };
            if (on.empty()) {
                if (along.periodic) emit(along.lo, along.hi, std::nullopt, std::nullopt);  // a loop, no joins
                continue;
            }
            const std::size_t n = on.size();
            const std::size_t pieces = along.periodic ? n : n - 1;
            for (std::size_t i = 0; i < pieces; ++i) {
                const auto& a = on[i];
                const auto& b = on[(i + 1) % n];
                const double to = i + 1 < n ? b.first : b.first + along.span();
                if (to - a.first > 1e-9 * along.span()) emit(a.first, to, a.second, b.second);
            }
        }
    }
}

}  // namespace qm::geometry::detail
