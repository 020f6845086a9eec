// geometry/kinematic_pairs.cpp: which pairs get a configuration space, and how (Def 20, 8.1.6, 8.2.1).
#include "geometry/kinematic_pairs.hpp"

#include "geometry/build_limits.hpp"
#include "geometry/external_force.hpp"
#include "geometry/motion_envelope.hpp"

#include <algorithm>
#include <numbers>

namespace qm::geometry {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

bool envelopes_meet(const Mechanism& m, PartId a, PartId b) {
    const Part& pa = m.parts[a];
    const Part& pb = m.parts[b];
    // The envelopes are built on a coarse tessellation grown by its chordal error, so they stay
    // conservative: false only if the parts can never touch.
    auto env = [](const Part& p) {
        const double chordal = 1e-3 * p.size();
        MotionEnvelope e = envelope_of(tessellated(p, chordal), p.translates() ? p.lo : 0.0, p.translates() ? p.hi : 0.0);
        e.radius += chordal;
        return e;
    };
    return envelopes_intersect(env(pa), env(pb));
}

bool shaft_has_position_dependent_force(const Mechanism& m, PartId p) {
    for (const auto& f : m.forces)
        if (m.same_shaft(f.part, p) && position_dependent(f, m.parts[f.part])) return true;
    return false;
}

CSpaceAxis axis_for(const Mechanism& m, const PairSpec& pair, int k, int samples) {
    const PartId id = k == 0 ? pair.a : pair.b;
    const Part& p = m.parts[id];
    if (p.fixed()) return CSpaceAxis{0.0, 1.0, true, 3};  // a dummy: nothing depends on it
    // A translation's limits are stops (the part meets its frame there); so are a window's
    // ends: the vocabulary does not follow the part out of its window.
    if (p.translates()) return CSpaceAxis{p.lo, p.hi, false, samples, true};
    if (const auto& w = pair.window[static_cast<std::size_t>(k)]) return CSpaceAxis{w->lo, w->hi, false, samples, true};
    const int period = shaft_has_position_dependent_force(m, id) ? 1 : p.symmetry;
    return CSpaceAxis{0.0, two_pi / period, true, samples};
}

}  // namespace

PairSelection kinematic_pairs(const Mechanism& m) {
    PairSelection out;
    auto consider = [&](const PairSpec& spec) {
        if (envelopes_meet(m, spec.a, spec.b)) out.modelled.push_back(spec);
        else out.skipped.push_back({spec.a, spec.b, "their motion envelopes do not intersect, so they never touch (Def 20)", spec.where});
    };
    if (m.pairs_declared) {
        for (const auto& spec : m.pairs) consider(spec);
        return out;
    }
    for (std::uint32_t i = 0; i < m.parts.size(); ++i)
        for (std::uint32_t j = i + 1; j < m.parts.size(); ++j) {
            const PartId a{i}, b{j};
            if (m.same_shaft(a, b) || (m.parts[a].fixed() && m.parts[b].fixed())) continue;
            PairSpec spec;
            spec.a = a;
            spec.b = b;
            spec.where = m.where;
            if (envelopes_meet(m, a, b)) out.modelled.push_back(spec);  // undeclared pairs that never meet are not news
        }
    return out;
}

bool check_grid_limit(const Mechanism& m, const PairSelection& selection, Diagnostics& diags) {
    std::uint64_t total = 0, largest = 0;
    const PairSpec* at = nullptr;
    for (const auto& pair : selection.modelled) {
        const auto r = place_request(m, pair);
        const std::uint64_t n = std::uint64_t(r.cspace.axes[0].samples) * std::uint64_t(r.cspace.axes[1].samples);
        total += n;
        if (!at || n > largest) {
            largest = n;
            at = &pair;
        }
    }
    if (total <= max_grid_samples) return true;
    const auto r = place_request(m, *at);
    m.error(diags, at->where,
            "the grids of the " + std::to_string(selection.modelled.size()) + " kinematic pairs have " + std::to_string(total) +
                " samples together, more than the limit of " + std::to_string(max_grid_samples) + "; this pair's grid is " +
                std::to_string(r.cspace.axes[0].samples) + " x " + std::to_string(r.cspace.axes[1].samples) +
                ": lower the grid setting, or the pair's (grid n0 n1)");
    return false;
}

double pair_chordal_tolerance(const Mechanism& m, const PairSpec& pair) {
    return m.settings.chordal_tolerance * std::min(m.parts[pair.a].size(), m.parts[pair.b].size());
}

std::unique_ptr<FclPairOracle> pair_oracle(const Mechanism& m, const PairSpec& pair) {
    return std::make_unique<FclPairOracle>(m.parts[pair.a], m.parts[pair.b], pair_chordal_tolerance(m, pair));
}

std::string pair_fingerprint(const Mechanism& m, const PairSpec& pair) {
    return FclPairOracle::fingerprint_of(m.parts[pair.a], m.parts[pair.b], pair_chordal_tolerance(m, pair));
}

PlaceRequest place_request(const Mechanism& m, const PairSpec& pair) {
    PlaceRequest r;
    const auto grid = pair.grid.value_or(m.settings.grid);
    for (int k = 0; k < 2; ++k) r.cspace.axes[static_cast<std::size_t>(k)] = axis_for(m, pair, k, grid[static_cast<std::size_t>(k)]);
    // The bracket is in configuration units: radians, or lengths scaled by the sliding part.
    double unit = 1.0;
    for (PartId id : {pair.a, pair.b})
        if (m.parts[id].translates()) unit = std::min(unit, m.parts[id].size());
    r.cspace.boundary_tolerance = m.settings.boundary_tolerance * unit;
    r.cspace.normal_zero_tolerance = m.settings.normal_zero_tolerance;
    r.merge_epsilon = m.settings.merge_epsilon;
    r.gap_epsilon = m.settings.gap_epsilon;
    for (int k = 0; k < 2; ++k) {
        const PartId id = k == 0 ? pair.a : pair.b;
        const auto& axis = r.cspace.axes[static_cast<std::size_t>(k)];
        if (m.parts[id].fixed()) continue;
        for (const auto& f : m.forces) {
            if (!m.same_shaft(f.part, id)) continue;
            for (const auto& change : force_changes(f, m.parts[f.part])) {
                double q = change.q;
                if (axis.periodic) {
                    q = axis.lo + std::fmod(q - axis.lo, axis.span());
                    if (q < axis.lo) q += axis.span();
                } else if (q < axis.lo || q > axis.hi) {
                    // A window on a rotation: the change may lie a turn away.
                    const double up = q + two_pi, down = q - two_pi;
                    if (m.parts[id].rotates() && up >= axis.lo && up <= axis.hi) q = up;
                    else if (m.parts[id].rotates() && down >= axis.lo && down <= axis.hi) q = down;
                    else continue;
                }
                r.external.push_back({k, q, f.cause + ": " + change.what + " on " + m.parts[f.part].name});
            }
        }
    }
    return r;
}

}  // namespace qm::geometry
