// envision/pair_places.cpp: the pairs' place vocabularies, cached (thesis 8.1.3).
#include "envision/pair_places.hpp"
#include "bridge/place_forces.hpp"
#include "geometry/contact_place.hpp"
#include "geometry/kinematic_pairs.hpp"

#include <algorithm>

namespace qm::envision {
namespace g = qm::geometry;

namespace {

// Only the cache key of a pair: its fingerprint, without the FCL meshes (building them costs more
// than reading a cached vocabulary).
class CacheKey final : public g::PairOracle {
public:
    explicit CacheKey(std::string fingerprint) : fingerprint_(std::move(fingerprint)) {}
    [[nodiscard]] bool blocked(const Eigen::Vector2d&) const override { throw InternalError("CacheKey::blocked: only a cache key"); }
    [[nodiscard]] Eigen::Vector2d free_normal(const Eigen::Vector2d&) const override {
        throw InternalError("CacheKey::free_normal: only a cache key");
    }
    [[nodiscard]] std::string fingerprint() const override { return fingerprint_; }

private:
    std::string fingerprint_;
};

std::unique_ptr<g::FclPairOracle>& oracle_for(const g::Mechanism& m, const g::PairSpec& spec, std::unique_ptr<g::FclPairOracle>& oracle) {
    if (!oracle) oracle = g::pair_oracle(m, spec);
    return oracle;
}

g::PlaceVocabulary vocabulary_of(const g::Mechanism& m, const g::PairSpec& spec, const g::PlaceRequest& request,
                                 const g::PlaceCache* cache, std::unique_ptr<g::FclPairOracle>& oracle, bool& from_cache) {
    from_cache = false;
    if (cache) {
        const CacheKey key(g::FclPairOracle::fingerprint_of(m.parts[spec.a], m.parts[spec.b], g::pair_chordal_tolerance(m, spec)));
        if (auto hit = cache->load(g::place_cache_material(key, request)); hit.status == g::CacheStatus::hit) {
            from_cache = true;
            return std::move(hit.vocabulary);
        }
        auto loaded = g::build_or_load(*oracle_for(m, spec, oracle), request, *cache);
        if (loaded.status != g::PlaceStatus::ok) throw InternalError("place vocabulary: " + loaded.message);
        return std::move(loaded.vocabulary);
    }
    auto built = g::build_place_vocabulary(*oracle_for(m, spec, oracle), request);
    if (built.status != g::PlaceStatus::ok) throw InternalError("place vocabulary: " + built.message);
    return std::move(built.vocabulary);
}

bool all_free(const g::PlaceVocabulary& v) {
    return std::all_of(v.places.begin(), v.places.end(), [](const g::Place& p) { return p.kind == g::PlaceKind::face && !p.gap; });
}

}  // namespace

std::optional<std::vector<bridge::PairPlaces>> load_pair_places(const g::Mechanism& m, const g::PlaceCache* cache,
                                                                Diagnostics& diagnostics) {
    const auto selection = g::kinematic_pairs(m);
    bool ok = true;
    for (const auto& s : selection.skipped) {
        m.error(diagnostics, s.where,
                "the parts '" + m.parts[s.a].name + "' and '" + m.parts[s.b].name + "' never touch (" + s.reason +
                    "): a kinematic pair of the envisionment must constrain its parts; remove it from Pairs");
        ok = false;
    }
    if (selection.modelled.empty() && selection.skipped.empty()) {
        m.error(diagnostics, m.where,
                "mechanism '" + m.name + "' has no kinematic pair: nothing to envision (declare Pairs, or draw parts whose motions meet)");
        return std::nullopt;
    }
    std::vector<bridge::PairPlaces> out;
    for (const auto& spec : selection.modelled) {
        std::unique_ptr<g::FclPairOracle> oracle;  // built only when the cache cannot answer
        const auto request = g::place_request(m, spec);
        bridge::PairPlaces pair;
        pair.name = bridge::pair_symbol(m.parts[spec.a].name, m.parts[spec.b].name);
        pair.spec = spec;
        pair.axes = request.cspace.axes;
        pair.vocabulary = vocabulary_of(m, spec, request, cache, oracle, pair.from_cache);
        const std::string names = "'" + m.parts[spec.a].name + "' and '" + m.parts[spec.b].name + "'";
        if (pair.vocabulary.count(g::PlaceKind::face) == 0) {
            const g::ContactRequest touching{m.settings.contact_tolerance, m.settings.normal_zero_tolerance};
            if (auto in_contact = g::contact_place(*oracle_for(m, spec, oracle), request, touching)) {
                pair.vocabulary = std::move(*in_contact);
            } else {
                m.error(diagnostics, spec.where,
                        names + " have no free space on the sampled grid and are not drawn in contact: they overlap everywhere (check the pivots) or their play is below a grid cell");
                ok = false;
                continue;
            }
        }
        if (all_free(pair.vocabulary)) {
            m.error(diagnostics, spec.where,
                    names + " never touch: their configuration space is all free (" + std::to_string(pair.vocabulary.places.size()) +
                        " place" + (pair.vocabulary.places.size() == 1 ? "" : "s") +
                        ", no contact); a kinematic pair of the envisionment must constrain its parts");
            ok = false;
            continue;
        }
        pair.forces = bridge::pair_forces(m, spec, pair.vocabulary);
        out.push_back(std::move(pair));
    }
    if (!ok) return std::nullopt;
    return out;
}

}  // namespace qm::envision
