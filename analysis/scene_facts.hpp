// analysis/scene_facts.hpp
// Provides:   SceneFacts, a Scene asserted into a rule engine in the vocabulary of
//             scene/vocabulary.hpp (docs/ANALYSIS.md): objects, surfaces, corners, frame constraints
//             and linkages as premises; every contact, force and given motion of the situations as an
//             ATMS assumption (a SceneItem), so that labels say which of them a conclusion rests on
//             and a what-if can take some away without re-running the monotonic laws. It also maps
//             engine values and assumptions back to scene names.
// Ownership:  holds references to the Scene and the Engine, which must outlive it.
// Invariants: an item mentioned in several situations is one assumption; a contact is the same
//             item whichever order its two surfaces are written in.
// Knows no law of mechanics: it states the scene, it derives nothing.
#pragma once
#include "analysis/granularity.hpp"
#include "analysis/fwd.hpp"
#include "scene/scene.hpp"
#include "atms/ids.hpp"
#include "engine/engine.hpp"
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace qm::analysis {

// A contact, force or given motion: what a situation asserts and a what-if may take away.
struct SceneItem {
    enum class Kind : std::uint8_t { contact, force, motion } kind = Kind::contact;
    std::string text;                  // thesis notation: "Contact (tb block-b-m)", "Force (block (0 -) (0 0))"
    SourceLocation where;
    std::optional<atms::AssumptionId> assumption;  // Granularity::item only
    std::optional<ObjectId> object;    // force, motion
    SurfaceId first{}, second{};       // contact
    std::optional<CauseId> cause;      // force
};

class SceneFacts {
public:
    // Asserts the scene. `given` motions are added to every situation (--given).
    // Pre: the engine has not run yet (premises cannot be added afterwards).
    SceneFacts(const Scene& scene, engine::Engine& engine, std::span<const Motion> given = {},
               Granularity granularity = Granularity::item);
    [[nodiscard]] Granularity granularity() const noexcept { return granularity_; }

    // The environment of situation s (1-based): its contacts, forces and given motions and the
    // scene-level forces, less every item matched by `without` (Contact a b: that contact; Force o:
    // every force on o). Pre: 1 <= s <= situation count; `without` holds only contacts and forces,
    // and is empty unless the granularity is `item`.
    [[nodiscard]] atms::EnvId context(std::size_t s, std::span<const QueryFact> without = {});
    // The items of situation s (1-based), scene-level forces first.
    [[nodiscard]] std::vector<const SceneItem*> items(std::size_t s) const;
    [[nodiscard]] const SceneItem* item(atms::AssumptionId a) const;  // null if a is no scene item
    [[nodiscard]] const SceneItem* item(engine::FactId f) const;       // null if f is no scene item
    [[nodiscard]] bool matches(const SceneItem& item, const QueryFact& q) const;

    [[nodiscard]] engine::ValueId symbol(ObjectId o) const { return object_symbols_[o.value]; }
    [[nodiscard]] std::optional<ObjectId> object_of(engine::ValueId v) const;
    [[nodiscard]] engine::ValueId predicate(std::string_view name);
    [[nodiscard]] engine::ValueId direction(const Direction& d);
    // The fact (pred args...) if the engine has it.
    [[nodiscard]] std::optional<engine::FactId> find(std::string_view pred, std::span<const engine::ValueId> args);

private:
    void assert_premises();
    std::size_t add_item(SceneItem::Kind kind, std::string text, SourceLocation where, std::string_view pred,
                         std::vector<engine::ValueId> args, std::span<const std::size_t> situations);
    std::size_t add_force(const Force& f, std::span<const std::size_t> situations);
    std::size_t add_motion(const Motion& m, std::span<const std::size_t> situations);
    std::size_t add_contact(const Contact& c, std::span<const std::size_t> situations);

    const Scene& scene_;
    engine::Engine& engine_;
    Granularity granularity_;
    std::vector<engine::FactId> situation_facts_;            // Granularity::situation: (situation N)
    std::vector<atms::AssumptionId> situation_assumptions_;
    std::vector<engine::ValueId> object_symbols_;            // by ObjectId
    std::map<std::uint32_t, ObjectId> object_by_symbol_;     // the inverse (first object of a symbol)
    std::vector<SceneItem> items_;
    std::map<std::vector<engine::ValueId>, std::size_t> item_by_fact_;  // (pred args...) -> item
    std::map<std::uint32_t, std::size_t> item_by_assumption_;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> contact_by_pair_;  // (first, second) surface ids
    std::vector<std::size_t> scene_forces_;                  // items of the Forces section
    std::vector<std::size_t> given_;                         // items of --given
    std::vector<std::vector<std::size_t>> situation_items_;  // by situation (0-based)
};

}  // namespace qm::analysis
