// geometry/detail/metric_limits_checker.cpp: a metric scene's parts against the build limits
// (geometry/build_limits.hpp): sizes, precision and chords, checked where
// the scene is read, each error located at the part and naming the setting to change.
#include "geometry/build_limits.hpp"
#include "geometry/detail/metric_checker.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace qm::geometry::detail {
namespace {

// A tolerance to suggest: rounded up to two significant digits.
double round_up(double x) {
    if (!(x > 0) || !std::isfinite(x)) return x;
    const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1);
    return std::ceil(x / unit * (1 - 1e-12)) * unit;
}

// A count, in full while it is a whole number a double holds exactly.
std::string count_text(double x) {
    return x < 1e15 ? std::to_string(static_cast<long long>(x)) : num(x);
}

// The part's size without the underflow of squaring (Part::size() is 0 below about 1e-154).
double unscaled_size(const Part& p) {
    const double big = std::numeric_limits<double>::infinity();
    Eigen::Vector2d lo(big, big), hi(-big, -big);
    for (const auto& profile : p.profiles) extend_bounds(profile, lo, hi);
    return std::hypot(hi.x() - lo.x(), hi.y() - lo.y());
}

struct Partner {
    std::optional<PartId> id;  // the smallest part the part can form a pair with
    double size = std::numeric_limits<double>::infinity();
};

// The smallest part each part forms a kinematic pair with: the declared pairs', or, without a
// Pairs section, any part that is not on its shaft and not fixed with it (envelopes are not
// consulted: the check stays linear in the parts; declaring the pairs makes it exact).
std::vector<Partner> smallest_partners(const Mechanism& m) {
    std::vector<Partner> out(m.parts.size());
    auto offer = [&](PartId p, PartId q) {
        const double s = m.parts[q].size();
        auto& slot = out[p.value];
        if (!slot.id || s < slot.size) slot = {q, s};
    };
    if (m.pairs_declared) {
        for (const auto& pair : m.pairs) {
            offer(pair.a, pair.b);
            offer(pair.b, pair.a);
        }
        return out;
    }
    // Sorted by size: all parts, and the moving ones (a fixed part pairs only with those). A
    // moving part skips at most its shaft's other parts.
    std::vector<PartId> by_size, moving;
    for (std::uint32_t i = 0; i < m.parts.size(); ++i)
        if (!m.parts[PartId{i}].profiles.empty()) by_size.push_back(PartId{i});
    std::sort(by_size.begin(), by_size.end(), [&](PartId a, PartId b) { return m.parts[a].size() < m.parts[b].size(); });
    std::copy_if(by_size.begin(), by_size.end(), std::back_inserter(moving), [&](PartId q) { return !m.parts[q].fixed(); });
    for (PartId p : by_size)
        for (PartId q : m.parts[p].fixed() ? moving : by_size)
            if (!m.same_shaft(p, q)) {
                offer(p, q);
                break;
            }
    return out;
}

}  // namespace

void Checker::limits(const Mechanism& m) {
    const auto partners = smallest_partners(m);
    const auto& s = m.settings;
    auto fail = [&](PartId id, const std::string& message) {
        const SourceLocation& w = m.part_where[id.value];
        diags.error(w, message, src.line_of(w));
        ok = false;
    };
    for (std::uint32_t i = 0; i < m.parts.size(); ++i) {
        const PartId id{i};
        const Part& p = m.parts[id];
        if (p.profiles.empty()) continue;  // a placeholder: its own errors are reported
        const double size = p.size();
        if (!(size >= min_part_size)) {
            fail(id, "part '" + p.name + "' is " + num(unscaled_size(p)) + " across: a part must be at least " + num(min_part_size) +
                         " across, so that its lengths, their squares and the tolerances relative to them stay in double "
                         "precision's range; draw the scene larger (every tolerance is relative to the parts' sizes)");
            continue;
        }
        const Partner& partner = partners[i];
        if (!partner.id || !(partner.size >= min_part_size)) continue;  // no pair, or the partner is refused itself
        const double pair_size = std::min(size, partner.size);
        const std::string smaller =
            partner.size < size ? "'" + m.parts[*partner.id].name + "', " + num(partner.size) + " across, " +
                                      (m.pairs_declared ? "the smaller part of its pair" : "the smallest part it may pair with, as no Pairs section names the pairs")
                                : "its own size, " + num(size);
        // Precision: the tolerances must be lengths that double arithmetic resolves where the
        // part goes; beyond, contacts and chords are decided by rounding.
        const double reach = coordinate_magnitude(p), least = least_resolvable_length(reach);
        bool precise = true;
        for (const auto& [name, relative] : {std::pair<const char*, double>{"chordal-tolerance", s.chordal_tolerance},
                                             std::pair<const char*, double>{"contact-tolerance", s.contact_tolerance}}) {
            if (!precise || relative * pair_size >= least) continue;
            precise = false;
            const double needed = round_up(least / pair_size);
            fail(id, "part '" + p.name + "' reaches " + num(reach) + " from the origin as it moves, where double arithmetic resolves " +
                         "lengths of about " + num(least) + "; its " + name + " (" + num(relative) + " of " + smaller + ") is finer than that: " +
                         (needed < 0.5 ? "raise " + std::string(name) + " to at least " + num(needed) + ", or draw the scene nearer the origin"
                                       : std::string("draw the scene nearer the origin, or its small parts larger")));
        }
        if (!precise) continue;
        // Chords: FCL's model of the part, at its pairs' chordal tolerance.
        const double chords = chords_needed(p, s.chordal_tolerance * pair_size);
        if (chords <= max_chords_per_part) continue;
        const double needed = round_up(chordal_tolerance_for_limit(p, s.chordal_tolerance, pair_size));
        fail(id, "part '" + p.name + "' would be cut into " + count_text(chords) + " chords for its collision model (chordal-tolerance " +
                     num(s.chordal_tolerance) + " of " + smaller + "), more than the limit of " +
                     count_text(max_chords_per_part) + " per part: " +
                     (needed < 0.5 ? "raise chordal-tolerance to at least " + num(needed) + ", or pair parts nearer in size"
                                   : "no chordal-tolerance below 0.5 is coarse enough; pair parts nearer in size"));
    }
}

}  // namespace qm::geometry::detail
