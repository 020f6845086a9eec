// alex/scene_facts.cpp: the scene as facts (docs/ANALYSIS.md, "What the driver asserts").
#include "alex/scene_facts.hpp"
#include "alex/direction_text.hpp"
#include "alex/vocabulary.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::alex {
namespace v = vocabulary;
using engine::ValueId;

SceneFacts::SceneFacts(const Scene& scene, engine::Engine& engine, std::span<const Motion> given)
    : scene_(scene), engine_(engine) {
    for (const Object& o : scene_.objects) object_symbols_.push_back(engine_.values().symbol(o.name));
    assert_premises();
    for (const Force& f : scene_.forces) scene_forces_.push_back(add_force(f));
    for (const Motion& m : given) given_.push_back(add_motion(m));
    for (const Situation& s : scene_.situations) {
        std::vector<std::size_t> mine;
        for (const Contact& c : s.contacts) mine.push_back(add_contact(c));
        for (const Force& f : s.forces) mine.push_back(add_force(f));
        for (const Motion& m : s.motions) mine.push_back(add_motion(m));
        situation_items_.push_back(std::move(mine));
    }
}

ValueId SceneFacts::predicate(std::string_view name) { return engine_.values().symbol(name); }
ValueId SceneFacts::direction(const Direction& d) { return engine_.values().direction(sign_string(d)); }

std::optional<ObjectId> SceneFacts::object_of(ValueId value) const {
    for (std::uint32_t i = 0; i < object_symbols_.size(); ++i)
        if (object_symbols_[i] == value) return ObjectId{i};
    return std::nullopt;
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
        premise(v::rigid_body, {obj}, o.where);
        // A pattern entry stands for every direction it matches (`?x` matches any sign).
        auto frame = [&](std::string_view pred, const std::vector<DirectionPattern>& patterns, std::size_t arity) {
            for (const Direction& d : all_directions(arity))
                if (std::any_of(patterns.begin(), patterns.end(), [&](const DirectionPattern& p) { return alex::matches(p, d); }))
                    premise(pred, {obj, direction(d)}, o.where);
        };
        frame(v::frame_trans_constraint, o.trans_constraints, scene_.translation_arity());
        frame(v::frame_rot_constraint, o.rot_constraints, scene_.rotation_arity());
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
                                 std::vector<ValueId> args) {
    std::vector<ValueId> key{predicate(pred)};
    key.insert(key.end(), args.begin(), args.end());
    if (auto it = item_by_fact_.find(key); it != item_by_fact_.end()) return it->second;
    engine::FactId f = engine_.add_assumption(predicate(pred), args, where);
    auto a = engine_.assumption(f);
    QM_ASSERT(a.has_value(), "an asserted assumption has an assumption id");
    SceneItem item{kind, std::move(text), std::move(where), *a, std::nullopt, {}, {}};
    items_.push_back(std::move(item));
    item_by_fact_[key] = items_.size() - 1;
    item_by_assumption_[a->value] = items_.size() - 1;
    return items_.size() - 1;
}

std::size_t SceneFacts::add_contact(const Contact& c) {
    // One item per pair of surfaces, in whichever order it is first written.
    for (std::size_t i = 0; i < items_.size(); ++i)
        if (items_[i].kind == SceneItem::Kind::contact && items_[i].first == c.second && items_[i].second == c.first)
            return i;
    auto& values = engine_.values();
    const std::string a = scene_.surfaces[c.first].name, b = scene_.surfaces[c.second].name;
    std::size_t i = add_item(SceneItem::Kind::contact, "Contact (" + a + " " + b + ")", c.where, v::contact,
                             {values.symbol(a), values.symbol(b)});
    items_[i].first = c.first;
    items_[i].second = c.second;
    return i;
}

std::size_t SceneFacts::add_force(const Force& f) {
    auto& values = engine_.values();
    const Cause& cause = scene_.causes[f.cause];
    std::string text = "Force (" + scene_.objects[f.object].name + " " + thesis_text(f.direction) + " " +
                       thesis_text(f.origin) + (cause.is_explicit ? " " + cause.name : std::string()) + ")";
    std::size_t i = add_item(SceneItem::Kind::force, std::move(text), f.where, v::external_force,
                             {object_symbols_[f.object.value], direction(f.direction), direction(f.origin),
                              values.symbol(cause.name)});
    items_[i].object = f.object;
    return i;
}

std::size_t SceneFacts::add_motion(const Motion& m) {
    std::string text = "Motion (" + scene_.objects[m.object].name + " " + thesis_text(m.translation) + " " +
                       thesis_text(m.rotation) + ")";
    std::size_t i = add_item(SceneItem::Kind::motion, std::move(text), m.where, v::given_motion,
                             {object_symbols_[m.object.value], direction(m.translation), direction(m.rotation)});
    items_[i].object = m.object;
    return i;
}

bool SceneFacts::matches(const SceneItem& item, const QueryFact& q) const {
    switch (q.kind) {
        case QueryFact::Kind::contact:
            return item.kind == SceneItem::Kind::contact &&
                   ((item.first == *q.first && item.second == *q.second) || (item.first == *q.second && item.second == *q.first));
        case QueryFact::Kind::force:
            return item.kind == SceneItem::Kind::force && item.object == q.object;
        default:
            return false;
    }
}

std::vector<const SceneItem*> SceneFacts::items(std::size_t s) const {
    QM_REQUIRE(s >= 1 && s <= situation_items_.size(), "situation index out of range");
    std::vector<const SceneItem*> out;
    auto add = [&](std::size_t i) {
        if (std::find(out.begin(), out.end(), &items_[i]) == out.end()) out.push_back(&items_[i]);
    };
    for (std::size_t i : scene_forces_) add(i);
    for (std::size_t i : given_) add(i);
    for (std::size_t i : situation_items_[s - 1]) add(i);
    return out;
}

atms::EnvId SceneFacts::context(std::size_t s, std::span<const QueryFact> without) {
    std::vector<atms::AssumptionId> members;
    for (const SceneItem* item : items(s)) {
        bool removed = std::any_of(without.begin(), without.end(), [&](const QueryFact& q) {
            QM_REQUIRE(q.kind == QueryFact::Kind::contact || q.kind == QueryFact::Kind::force,
                       "only contacts and forces can be taken away");
            return matches(*item, q);
        });
        if (!removed) members.push_back(item->assumption);
    }
    return engine_.atms().environment(members);
}

const SceneItem* SceneFacts::item(atms::AssumptionId a) const {
    auto it = item_by_assumption_.find(a.value);
    return it == item_by_assumption_.end() ? nullptr : &items_[it->second];
}

}  // namespace qm::alex
