// bridge/place_facts.cpp: a pair's place vocabulary, the chain's parts and the current state as
// facts (the table in place_facts.hpp).
#include "bridge/place_facts.hpp"
#include "bridge/clock_vocabulary.hpp"
#include "bridge/place_correlation.hpp"
#include "geometry/external_force.hpp"

#include <algorithm>
#include <set>

namespace qm::bridge {
namespace g = qm::geometry;
using engine::ValueId;

namespace {

class Facts {
public:
    explicit Facts(engine::Engine& e) : e_(e) {}
    ValueId sym(std::string_view s) { return e_.values().symbol(s); }
    ValueId num(std::int64_t n) { return e_.values().integer(n); }
    ValueId dir(std::string_view signs) { return e_.values().direction(signs); }
    ValueId set(std::vector<ValueId> xs) { return e_.values().set(std::move(xs)); }
    void premise(const char* predicate, std::vector<ValueId> args, const SourceLocation& where = {"<bridge>", 1, 1}) {
        e_.add_premise(sym(predicate), args, where);
    }
    engine::FactId assumption(const char* predicate, std::vector<ValueId> args, const SourceLocation& where) {
        return e_.add_assumption(sym(predicate), args, where);
    }

private:
    engine::Engine& e_;
};

const char* kind_word(g::PlaceKind k) { return g::to_string(k); }

char sign_char(int s) { return s > 0 ? '+' : s < 0 ? '-' : '0'; }

void place_facts(Facts& f, const PairPlaces& pair, const g::Place& place, bool kinds) {
    const ValueId p = f.sym(pair.name), id = f.num(place.id.value);
    if (kinds) f.premise(clock::place_kind, {p, id, f.sym(kind_word(place.kind))});
    if (kinds && place.kind == g::PlaceKind::join) f.premise(clock::join_kind, {p, id, f.sym(g::to_string(place.join_kind))});
    if (!place.normals.empty()) {
        std::vector<ValueId> normals;
        for (const auto n : place.normals) {
            normals.push_back(f.dir(direction_text(n)));
            f.premise(clock::place_normal, {p, id, normals.back()});
        }
        f.premise(clock::place_normals, {p, id, f.set(normals)});
    }
    if (place.kind == g::PlaceKind::join && place.concave)
        f.premise(*place.concave ? clock::join_concave : clock::join_convex, {p, id});
    if (place.gap) f.premise(clock::gap_place, {p, id});
}

}  // namespace

std::string sign_text(int sign) { return std::string(1, sign_char(sign)); }
std::string direction_text(g::QualDirection d) { return std::string{sign_char(d.s[0]), sign_char(d.s[1])}; }

void assert_pair(engine::Engine& e, const g::Mechanism& m, const PairPlaces& pair, const PlaceFactOptions& options) {
    Facts f(e);
    const ValueId p = f.sym(pair.name);
    f.premise(clock::pair, {p, f.sym(m.parts[pair.spec.a].name), f.sym(m.parts[pair.spec.b].name)}, pair.spec.where);
    for (int k = 0; k < 2; ++k)
        f.premise(clock::axis, {p, f.num(k + 1), f.sym(pair.request.cspace.axes[static_cast<std::size_t>(k)].periodic ? "periodic" : "bounded")});
    if (options.choice) {
        std::vector<ValueId> ids;
        for (const auto& place : pair.vocabulary.places) ids.push_back(f.num(place.id.value));
        f.premise(clock::pair_places, {p, f.set(ids)}, pair.spec.where);
    }
    auto wanted = [&](g::PlaceId id) { return !options.only || *options.only == id; };
    for (const auto& place : pair.vocabulary.places) {
        if (!wanted(place.id)) continue;
        place_facts(f, pair, place, options.kinds);
        for (const auto& force : pair.forces.by_place[place.id.value])
            f.premise(clock::force_sign_at, {p, f.num(place.id.value), f.sym(m.parts[force.part].name), f.dir(sign_text(force.sign)),
                                             f.sym(force.cause)});
    }
    for (const auto& a : pair.vocabulary.adjacency) {
        if (!wanted(a.from) || (options.motion && a.motion != *options.motion)) continue;
        if (!options.motion && !options.motions.empty() && !options.motions.count(a.motion)) continue;
        const char* duration = a.constrained ? "constrained" : a.instantaneous ? "instant" : "interval";
        f.premise(clock::adjacent, {p, f.num(a.from.value), f.num(a.to.value), f.dir(direction_text(a.motion)), f.sym(duration)});
    }
}

void assert_correlation(engine::Engine& e, const g::Mechanism& m, const PairPlaces& p, const PairPlaces& q) {
    Facts f(e);
    const g::PartId pp[2] = {p.spec.a, p.spec.b}, qq[2] = {q.spec.a, q.spec.b};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            if (!m.same_shaft(pp[i], qq[j]) || m.parts[pp[i]].fixed()) continue;
            for (const auto& [x, y] : places_apart(p.vocabulary, i, p.request.cspace.axes[static_cast<std::size_t>(i)], q.vocabulary, j,
                                                   q.request.cspace.axes[static_cast<std::size_t>(j)]))
                f.premise(clock::places_apart, {f.sym(p.name), f.num(x.value), f.sym(q.name), f.num(y.value)});
        }
}

void assert_parts(engine::Engine& e, const g::Mechanism& m, std::span<const g::PartId> parts, bool choices) {
    Facts f(e);
    for (const g::PartId part : parts) {
        const ValueId o = f.sym(m.parts[part].name);
        const SourceLocation& where = m.part_where[part.value];
        f.premise(clock::clock_object, {o}, where);
        if (m.parts[part].fixed()) f.premise(clock::fixed_part, {o}, where);
        if (choices) f.premise(clock::possible_motions, {o, f.set({f.dir("+"), f.dir("0"), f.dir("-")})}, where);
    }
}

void assert_linkages(engine::Engine& e, const g::Mechanism& m, std::span<const g::PartId> parts) {
    Facts f(e);
    auto in_chain = [&](g::PartId p) { return std::find(parts.begin(), parts.end(), p) != parts.end(); };
    for (const auto& l : m.linkages) {
        std::optional<g::PartId> previous;
        for (const g::PartId p : l.parts) {
            if (!in_chain(p)) continue;
            if (previous) f.premise(clock::linkage, {f.sym(m.parts[*previous].name), f.sym(m.parts[p].name)}, l.where);
            previous = p;
        }
    }
}

std::vector<engine::FactId> assert_forces(engine::Engine& e, const g::Mechanism& m, std::span<const g::PartId> parts,
                                          ForceFacts how, std::span<const ForceRef> without) {
    Facts f(e);
    auto in_chain = [&](g::PartId p) { return std::find(parts.begin(), parts.end(), p) != parts.end(); };
    std::set<std::string> causes;
    for (const auto& force : m.forces)
        if (in_chain(force.part)) causes.insert(force.cause);
    for (const auto& c : causes) f.premise(clock::cause, {f.sym(c)});
    for (const auto& force : constant_forces(m))
        if (in_chain(force.part))
            f.premise(clock::constant_force, {f.sym(m.parts[force.part].name), f.dir(sign_text(force.sign)), f.sym(force.cause)});
    std::vector<engine::FactId> assumed;
    if (how == ForceFacts::none) return assumed;
    std::set<std::pair<std::uint32_t, std::string>> done;
    for (const auto& force : m.forces) {
        if (!in_chain(force.part) || !done.insert({force.part.value, force.cause}).second) continue;
        const bool removed = std::any_of(without.begin(), without.end(), [&](const ForceRef& w) {
            return w.part == force.part && (!w.cause || *w.cause == force.cause);
        });
        if (removed) continue;
        const std::vector<ValueId> args{f.sym(m.parts[force.part].name), f.sym(force.cause)};
        if (how == ForceFacts::assumptions) assumed.push_back(f.assumption(clock::external_force, args, force.where));
        else assumed.push_back(e.add_premise(f.sym(clock::external_force), args, force.where));
    }
    return assumed;
}

void assert_current_place(engine::Engine& e, const PairPlaces& pair, g::PlaceId place) {
    Facts f(e);
    f.premise(clock::current_place, {f.sym(pair.name), f.num(place.value)});
}

void assert_current_motion(engine::Engine& e, const g::Mechanism& m, g::PartId part, int sign) {
    Facts f(e);
    f.premise(clock::current_motion, {f.sym(m.parts[part].name), f.dir(sign_text(sign))});
}

engine::FactId assume_current_motion(engine::Engine& e, const g::Mechanism& m, g::PartId part, int sign) {
    Facts f(e);
    return f.assumption(clock::current_motion, {f.sym(m.parts[part].name), f.dir(sign_text(sign))}, m.part_where[part.value]);
}

}  // namespace qm::bridge
