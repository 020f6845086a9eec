// cli/pair_places.cpp
#include "pair_places.hpp"

#include "geometry/contact_place.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "qm/assert.hpp"

#include <cstdlib>

namespace qm::cli {

namespace g = qm::geometry;

std::filesystem::path default_place_cache() {
    if (const char* p = std::getenv("QM_PLACE_CACHE"); p && *p) return p;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "qm-atms" / "places";
    if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache" / "qm-atms" / "places";
    return {};
}

std::optional<g::PlaceCache> open_place_cache(bool use, const std::optional<std::filesystem::path>& dir) {
    if (!use) return std::nullopt;
    const std::filesystem::path at = dir ? *dir : default_place_cache();
    if (at.empty()) return std::nullopt;
    return g::PlaceCache(at);
}

std::unique_ptr<g::FclPairOracle> pair_oracle_or_error(const g::Mechanism& m, const g::PairSpec& pair, Diagnostics& diags) {
    try {
        return g::pair_oracle(m, pair);
    } catch (const g::ModelBuildError& e) {
        m.error(diags, pair.where, std::string(e.what()) + "; raise chordal-tolerance to build smaller models");
        return nullptr;
    }
}

std::optional<PairPlaces> pair_places(const g::Mechanism& m, const g::PairSpec& pair, const std::optional<g::PlaceCache>& cache, bool need_space,
                                      Diagnostics& diags) {
    PairPlaces out;
    out.oracle = pair_oracle_or_error(m, pair, diags);
    if (!out.oracle) return std::nullopt;
    out.request = g::place_request(m, pair);
    std::string note;  // what the cache did, when it is not a plain hit or store
    if (need_space || !cache) {
        auto built = g::build_place_vocabulary(*out.oracle, out.request);
        QM_REQUIRE(built.status == g::PlaceStatus::ok, built.message);
        if (cache) {
            const std::string material = g::place_cache_material(*out.oracle, out.request);
            note = g::cache_note(*cache, material, {}, cache->store(material, built.vocabulary));
        }
        out.vocabulary = std::move(built.vocabulary);
        out.space = std::move(built.space);
    } else {
        auto loaded = g::build_or_load(*out.oracle, out.request, *cache);
        QM_REQUIRE(loaded.status == g::PlaceStatus::ok, loaded.message);
        out.vocabulary = std::move(loaded.vocabulary);
        out.from_cache = loaded.from_cache;
        note = std::move(loaded.note);
    }
    if (!note.empty()) diags.add(Severity::warning, pair.where, std::move(note), m.source ? m.source->line_of(pair.where) : std::string_view());
    if (out.vocabulary.count(g::PlaceKind::face) == 0) {
        // No free area: parts drawn in contact with zero play move only in contact (8.1.6's gap
        // place in the limit); parts drawn overlapping have no place at all.
        const g::ContactRequest touching{m.settings.contact_tolerance, m.settings.normal_zero_tolerance};
        if (auto in_contact = g::contact_place(*out.oracle, out.request, touching)) out.vocabulary = std::move(*in_contact);
        else out.no_place = true;
    }
    return out;
}

g::SvgOptions cspace_svg_options(const g::Mechanism& m, const g::PairSpec& pair, int width, int height) {
    g::SvgOptions o;
    o.width = width;
    o.height = height;
    o.title = m.name + ": " + m.parts[pair.a].name + " (across) x " + m.parts[pair.b].name + " (up)";
    for (int k = 0; k < 2; ++k) {
        const g::Part& p = m.parts[k == 0 ? pair.a : pair.b];
        o.axes[static_cast<std::size_t>(k)] = {p.name, p.rotates() ? g::AxisUnit::degrees : p.translates() ? g::AxisUnit::length : g::AxisUnit::fixed};
    }
    return o;
}

std::optional<g::PairSpec> find_pair(const g::Mechanism& m, std::string_view text) {
    for (const auto& pair : g::kinematic_pairs(m).modelled)
        if (text == m.parts[pair.a].name + "--" + m.parts[pair.b].name) return pair;
    return std::nullopt;
}

}  // namespace qm::cli
