// scene/scene.cpp: lookups and equality of the checked scene model (scene/scene.hpp).
#include "scene/scene.hpp"

#include <algorithm>

namespace qm::scene {

bool matches(const DirectionPattern& pattern, const Direction& d) {
    QM_ASSERT(pattern.size() == d.size(), "pattern and direction differ in arity");
    for (std::size_t i = 0; i < pattern.size(); ++i)
        if (pattern[i].sign && *pattern[i].sign != d[i]) return false;
    return true;
}

namespace {
template <class K, class V>
std::optional<K> find_by_name(const IdVector<K, V>& table, Scene::NameIndex& index, std::string_view name) {
    if (index.seen > table.size()) index = {};  // entries were taken away: start afresh
    for (; index.seen < table.size(); ++index.seen) {
        const auto i = static_cast<std::uint32_t>(index.seen);
        index.ids.emplace(table[K{i}].name, i);  // the first of a name stays
    }
    const auto it = index.ids.find(std::string(name));
    if (it == index.ids.end()) return std::nullopt;
    QM_ASSERT(table[K{it->second}].name == name, "a scene entry was renamed after it was looked up");
    return K{it->second};
}

template <class K, class V>
bool same_table(const IdVector<K, V>& a, const IdVector<K, V>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}
}  // namespace

std::optional<ObjectId> Scene::find_object(std::string_view n) const { return find_by_name(objects, object_index_, n); }
std::optional<SurfaceId> Scene::find_surface(std::string_view n) const { return find_by_name(surfaces, surface_index_, n); }
std::optional<CauseId> Scene::find_cause(std::string_view n) const { return find_by_name(causes, cause_index_, n); }

ObjectId Scene::owner(SurfaceId s) const {
    QM_REQUIRE(surfaces.contains(s), "surface id out of range");
    return surfaces[s].object;
}

bool operator==(const Scene& a, const Scene& b) {
    return a.name == b.name && a.dimensions == b.dimensions && same_table(a.objects, b.objects) &&
           same_table(a.surfaces, b.surfaces) && same_table(a.causes, b.causes) && a.forces == b.forces &&
           a.linkages == b.linkages &&
           a.situations == b.situations;
}

char sign_char(Sign s) noexcept {
    switch (s) {
        case Sign::minus: return '-';
        case Sign::zero: return '0';
        case Sign::plus: return '+';
    }
    return '?';
}

}  // namespace qm::scene
