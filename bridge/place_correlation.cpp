// bridge/place_correlation.cpp: Def 34 from the places' coordinates.
#include "bridge/place_correlation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace qm::bridge {
namespace g = qm::geometry;

namespace {

// An interval of the coordinate; on a periodic axis [lo, hi] with lo <= hi < lo + period, taken
// modulo the period.
struct Interval {
    double lo, hi;
};

// The values a line or join covers: the union of its consecutive points' spans (the short way
// round a periodic axis); a face, those it spans (geometry's Place::covers). Nothing for a
// place without them.
std::optional<std::vector<Interval>> covered(const g::Place& p, int axis, const g::CSpaceAxis& range) {
    std::vector<Interval> out;
    if (p.kind == g::PlaceKind::face) {
        const auto& spans = p.covers[static_cast<std::size_t>(axis)];
        if (spans.empty()) return std::nullopt;
        for (const auto& s : spans) out.push_back({s.lo, s.hi});
        return out;
    }
    if (p.points.empty()) return std::nullopt;
    const double period = range.span();
    for (std::size_t i = 0; i < p.points.size(); ++i) {
        const double x = p.points[i][axis];
        if (i + 1 == p.points.size()) {
            if (p.points.size() == 1) out.push_back({x, x});
            break;
        }
        double y = p.points[i + 1][axis];
        if (range.periodic) {
            // the short way round
            while (y - x > period / 2) y -= period;
            while (x - y > period / 2) y += period;
        }
        out.push_back({std::min(x, y), std::max(x, y)});
    }
    // Merged: few intervals per place, whatever its number of points.
    if (range.periodic)
        for (auto& i : out) {
            const double shift = std::floor((i.lo - range.lo) / period) * period;
            i.lo -= shift;
            i.hi -= shift;
        }
    std::sort(out.begin(), out.end(), [](const Interval& x, const Interval& y) { return x.lo < y.lo; });
    std::vector<Interval> merged;
    for (const auto& i : out) {
        if (!merged.empty() && i.lo <= merged.back().hi) merged.back().hi = std::max(merged.back().hi, i.hi);
        else merged.push_back(i);
    }
    return merged;
}

bool meet(const Interval& a, const Interval& b, const g::CSpaceAxis& range, double slack) {
    if (!range.periodic) return a.lo <= b.hi + slack && b.lo <= a.hi + slack;
    const double period = range.span();
    // Shift b by whole periods next to a.
    for (int k = -2; k <= 2; ++k) {
        const double lo = b.lo + k * period, hi = b.hi + k * period;
        if (a.lo <= hi + slack && lo <= a.hi + slack) return true;
    }
    return false;
}

bool same_axis(const g::CSpaceAxis& a, const g::CSpaceAxis& b) {
    const double tol = 1e-12 * std::max(1.0, std::abs(a.span()));
    return a.periodic == b.periodic && std::abs(a.lo - b.lo) <= tol && std::abs(a.hi - b.hi) <= tol;
}

}  // namespace

bool places_go_round(const g::PlaceVocabulary& v, std::span<const g::PlaceId> places, int axis, const g::CSpaceAxis& range) {
    if (!range.periodic) return false;
    const double period = range.span(), slack = 1e-6 * period;
    std::vector<Interval> all;
    for (const auto id : places) {
        const auto c = covered(v.at(id), axis, range);
        if (!c) return true;  // a place whose values are not known may cover them all
        for (auto i : *c) {
            if (i.hi - i.lo >= period - slack) return true;
            const double shift = std::floor((i.lo - range.lo) / period) * period;
            i.lo -= shift;
            i.hi -= shift;
            all.push_back(i);
            if (i.hi > range.hi) all.push_back({i.lo - period, i.hi - period});
        }
    }
    std::sort(all.begin(), all.end(), [](const Interval& x, const Interval& y) { return x.lo < y.lo; });
    double reached = range.lo;
    for (const auto& i : all) {
        if (i.lo > reached + slack) return false;
        reached = std::max(reached, i.hi);
    }
    return reached >= range.hi - slack;
}

std::vector<std::pair<g::PlaceId, g::PlaceId>> places_apart(const g::PlaceVocabulary& a, int axis_a, const g::CSpaceAxis& range_a,
                                                            const g::PlaceVocabulary& b, int axis_b, const g::CSpaceAxis& range_b) {
    std::vector<std::pair<g::PlaceId, g::PlaceId>> out;
    if (!same_axis(range_a, range_b)) return out;
    const double slack = 1e-6 * range_a.span();
    std::vector<std::optional<std::vector<Interval>>> cover_b;
    for (const auto& q : b.places) cover_b.push_back(covered(q, axis_b, range_b));
    for (const auto& p : a.places) {
        const auto cp = covered(p, axis_a, range_a);
        if (!cp) continue;
        for (const auto& q : b.places) {
            const auto& cq = cover_b[q.id.value];
            if (!cq) continue;
            bool any = false;
            for (const auto& x : *cp)
                for (const auto& y : *cq) any = any || meet(x, y, range_a, slack);
            if (!any) out.emplace_back(p.id, q.id);
        }
    }
    return out;
}

}  // namespace qm::bridge
