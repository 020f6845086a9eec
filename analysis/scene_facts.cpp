// analysis/scene_facts.cpp: the scene as facts (docs/ANALYSIS.md, "What the driver asserts").
#include "analysis/scene_facts.hpp"
#include "scene/direction_text.hpp"
#include "scene/vocabulary.hpp"
#include "scene/what_if.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::analysis {
namespace v = scene::vocabulary;
using engine::ValueId;

SceneFacts::SceneFacts(const Scene& scene, engine::Engine& engine, std::span<const Motion> given,
                       Granularity granularity)
    : scene_(scene), engine_(engine), granularity_(granularity) {
    for (const Object& o : scene_.objects) {
        const ValueId symbol = engine_.values().symbol(o.name);
        object_by_symbol_.emplace(symbol.value, ObjectId{static_cast<std::uint32_t>(object_symbols_.size())});
        object_symbols_.push_back(symbol);
    }
    assert_premises();
    std::vector<std::size_t> all;
    for (std::size_t s = 0; s < scene_.situations.size(); ++s) {
        all.push_back(s);
        if (granularity_ == Granularity::situation) {
            // The driver's own assumption, "situation N holds"; the laws never mention it.
            engine::FactId f = engine_.add_assumption(predicate("situation"), std::vector<ValueId>{engine_.values().integer(
                                                                                   static_cast<std::int64_t>(s + 1))},
                                                      scene_.situations[s].where);
            situation_facts_.push_back(f);
            situation_assumptions_.push_back(*engine_.assumption(f));
        }
    }
    for (const Force& f : scene_.forces) scene_forces_.push_back(add_force(f, all));
    for (const Motion& m : given) given_.push_back(add_motion(m, all));
    for (std::size_t i = 0; i < scene_.situations.size(); ++i) {
        const Situation& s = scene_.situations[i];
        const std::size_t only[] = {i};
        std::vector<std::size_t> mine;
        for (const Contact& c : s.contacts) mine.push_back(add_contact(c, only));
        for (const Force& f : s.forces) mine.push_back(add_force(f, only));
        for (const Motion& m : s.motions) mine.push_back(add_motion(m, only));
        situation_items_.push_back(std::move(mine));
    }
}

ValueId SceneFacts::predicate(std::string_view name) { return engine_.values().symbol(name); }
ValueId SceneFacts::direction(const Direction& d) { return engine_.values().direction(sign_string(d)); }

std::optional<ObjectId> SceneFacts::object_of(ValueId value) const {
    // By a map, not a scan: the driver asks once per choice assumption, so a scan is quadratic.
    auto it = object_by_symbol_.find(value.value);
    if (it == object_by_symbol_.end()) return std::nullopt;
    return it->second;
}

std::optional<engine::FactId> SceneFacts::find(std::string_view pred, std::span<const ValueId> args) {
    return engine_.find(predicate(pred), args);
}

// Figure 6.1's scene description, one premise per statement, each located at its scene line.
void SceneFacts::assert_premises() {
    auto& values = engine_.values();
    auto premise = [&](std::string_view pred, std::vector<ValueId> args, const SourceLocation& where) {
        engine_.add_premise(predicate(pred), args, where);
    };
    premise(v::dimensions, {values.integer(scene_.dimensions)}, scene_.where);
    for (std::uint32_t i = 0; i < scene_.objects.size(); ++i) {
        const Object& o = scene_.objects[ObjectId{i}];
        const ValueId obj = object_symbols_[i];
        premise(v::rigid_body, {obj}, o.described_at.value_or(o.where));
        // A pattern entry stands for every direction it matches (`?x` matches any sign); the premise
        // cites the first entry that matches.
        auto frame = [&](std::string_view pred, const std::vector<DirectionPattern>& patterns,
                         const std::vector<SourceLocation>& at, std::size_t arity) {
            for (const Direction& d : scene::all_directions(arity)) {
                auto p = std::find_if(patterns.begin(), patterns.end(), [&](const DirectionPattern& x) { return scene::matches(x, d); });
                if (p == patterns.end()) continue;
                const auto k = static_cast<std::size_t>(p - patterns.begin());
                premise(pred, {obj, direction(d)}, k < at.size() ? at[k] : o.where);
            }
        };
        frame(v::frame_trans_constraint, o.trans_constraints, o.trans_constraints_at, scene_.translation_arity());
        frame(v::frame_rot_constraint, o.rot_constraints, o.rot_constraints_at, scene_.rotation_arity());
    }
    for (std::uint32_t i = 0; i < scene_.surfaces.size(); ++i) {
        const Surface& s = scene_.surfaces[SurfaceId{i}];
        const ValueId name = values.symbol(s.name);
        premise(v::surface, {object_symbols_[s.object.value], name}, s.where);
        premise(v::origin_dir, {name, direction(s.origin)}, s.where);
        if (s.corner)
            premise(v::corner, {object_symbols_[s.object.value], name, values.symbol(scene_.surfaces[s.corner->first].name),
                                values.symbol(scene_.surfaces[s.corner->second].name)},
                    s.where);
        else
            premise(v::surface_normal, {name, direction(s.normal)}, s.where);
    }
    for (const Linkage& l : scene_.linkages)
        premise(v::linkage, {object_symbols_[l.first.value], object_symbols_[l.second.value]}, l.where);
}

std::size_t SceneFacts::add_item(SceneItem::Kind kind, std::string text, SourceLocation where, std::string_view pred,
                                 std::vector<ValueId> args, std::span<const std::size_t> situations) {
    std::vector<ValueId> key{predicate(pred)};
    key.insert(key.end(), args.begin(), args.end());
    auto it = item_by_fact_.find(key);
    if (granularity_ == Granularity::situation) {
        // The item holds in each situation that mentions it.
        for (std::size_t s : situations)
            engine_.add_fact(predicate(pred), args, std::span<const engine::FactId>(&situation_facts_[s], 1), where);
        if (it != item_by_fact_.end()) return it->second;
        items_.push_back(SceneItem{kind, std::move(text), std::move(where), std::nullopt, std::nullopt, {}, {}, std::nullopt});
        item_by_fact_[key] = items_.size() - 1;
        return items_.size() - 1;
    }
    if (it != item_by_fact_.end()) return it->second;
    engine::FactId f = engine_.add_assumption(predicate(pred), args, where);
    auto a = engine_.assumption(f);
    QM_ASSERT(a.has_value(), "an asserted assumption has an assumption id");
    SceneItem item{kind, std::move(text), std::move(where), *a, std::nullopt, {}, {}, std::nullopt};
    items_.push_back(std::move(item));
    item_by_fact_[key] = items_.size() - 1;
    item_by_assumption_[a->value] = items_.size() - 1;
    return items_.size() - 1;
}

std::size_t SceneFacts::add_contact(const Contact& c, std::span<const std::size_t> situations) {
    auto& values = engine_.values();
    // One item per pair of surfaces, in whichever order it is first written.
    SurfaceId first = c.first, second = c.second;
    if (auto it = contact_by_pair_.find({c.second.value, c.first.value}); it != contact_by_pair_.end())
        std::swap(first, second);
    const std::string a = scene_.surfaces[first].name, b = scene_.surfaces[second].name;
    std::size_t i = add_item(SceneItem::Kind::contact, "Contact (" + a + " " + b + ")", c.where, v::contact,
                             {values.symbol(a), values.symbol(b)}, situations);
    contact_by_pair_[{first.value, second.value}] = i;
    items_[i].first = first;
    items_[i].second = second;
    return i;
}

std::size_t SceneFacts::add_force(const Force& f, std::span<const std::size_t> situations) {
    auto& values = engine_.values();
    const Cause& cause = scene_.causes[f.cause];
    std::string text = "Force (" + scene_.objects[f.object].name + " " + thesis_text(f.direction) + " " +
                       thesis_text(f.origin) + (cause.is_explicit ? " " + cause.name : std::string()) + ")";
    std::size_t i = add_item(SceneItem::Kind::force, std::move(text), f.where, v::external_force,
                             {object_symbols_[f.object.value], direction(f.direction), direction(f.origin),
                              values.symbol(cause.name)},
                             situations);
    items_[i].object = f.object;
    items_[i].cause = f.cause;
    return i;
}

std::size_t SceneFacts::add_motion(const Motion& m, std::span<const std::size_t> situations) {
    std::string text = "Motion (" + scene_.objects[m.object].name + " " + thesis_text(m.translation) + " " +
                       thesis_text(m.rotation) + ")";
    std::size_t i = add_item(SceneItem::Kind::motion, std::move(text), m.where, v::given_motion,
                             {object_symbols_[m.object.value], direction(m.translation), direction(m.rotation)},
                             situations);
    items_[i].object = m.object;
    return i;
}

bool SceneFacts::matches(const SceneItem& item, const QueryFact& q) const {
    switch (q.kind) {
        case QueryFact::Kind::contact:
            return item.kind == SceneItem::Kind::contact && scene::names_contact(q, item.first, item.second);
        case QueryFact::Kind::force:
            return item.kind == SceneItem::Kind::force && scene::names_force(q, *item.object, *item.cause);
        default:
            return false;
    }
}

std::vector<const SceneItem*> SceneFacts::items(std::size_t s) const {
    QM_REQUIRE(s >= 1 && s <= situation_items_.size(), "situation index out of range");
    std::vector<const SceneItem*> out;
    std::vector<bool> added(items_.size(), false);  // a search of `out` per item would be quadratic
    auto add = [&](std::size_t i) {
        if (!added[i]) out.push_back(&items_[i]);
        added[i] = true;
    };
    for (std::size_t i : scene_forces_) add(i);
    for (std::size_t i : given_) add(i);
    for (std::size_t i : situation_items_[s - 1]) add(i);
    return out;
}

atms::EnvId SceneFacts::context(std::size_t s, std::span<const QueryFact> without) {
    if (granularity_ == Granularity::situation) {
        QM_REQUIRE(without.empty(), "taking items away needs Granularity::item");
        QM_REQUIRE(s >= 1 && s <= situation_assumptions_.size(), "situation index out of range");
        return engine_.atms().environment({situation_assumptions_[s - 1]});
    }
    std::vector<atms::AssumptionId> members;
    for (const SceneItem* item : items(s)) {
        bool removed = std::any_of(without.begin(), without.end(), [&](const QueryFact& q) {
            QM_REQUIRE(q.kind == QueryFact::Kind::contact || q.kind == QueryFact::Kind::force,
                       "only contacts and forces can be taken away");
            return matches(*item, q);
        });
        if (!removed) members.push_back(*item->assumption);
    }
    return engine_.atms().environment(members);
}

const SceneItem* SceneFacts::item(engine::FactId f) const {
    const engine::Fact& fact = engine_.facts().fact(f);
    std::vector<ValueId> key{fact.predicate};
    key.insert(key.end(), fact.args.begin(), fact.args.end());
    auto it = item_by_fact_.find(key);
    return it == item_by_fact_.end() ? nullptr : &items_[it->second];
}

const SceneItem* SceneFacts::item(atms::AssumptionId a) const {
    auto it = item_by_assumption_.find(a.value);
    return it == item_by_assumption_.end() ? nullptr : &items_[it->second];
}

}  // namespace qm::analysis
