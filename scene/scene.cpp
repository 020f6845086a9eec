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
std::optional<K> find_by_name(const IdVector<K, V>& table, std::string_view name) {
    for (std::uint32_t i = 0; i < table.size(); ++i)
        if (table[K{i}].name == name) return K{i};
    return std::nullopt;
}

template <class K, class V>
bool same_table(const IdVector<K, V>& a, const IdVector<K, V>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}
}  // namespace

std::optional<ObjectId> Scene::find_object(std::string_view n) const { return find_by_name(objects, n); }
std::optional<SurfaceId> Scene::find_surface(std::string_view n) const { return find_by_name(surfaces, n); }
std::optional<CauseId> Scene::find_cause(std::string_view n) const { return find_by_name(causes, n); }

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
