// bridge/pair_places.cpp: a pair's place vocabulary, cached (thesis 8.1.3), for every command.
#include "bridge/pair_places.hpp"

#include "geometry/contact_detection.hpp"
#include "geometry/contact_place.hpp"
#include "geometry/fcl_pair_oracle.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <cstdlib>

namespace qm::bridge {

namespace g = qm::geometry;

namespace {

// The pair's FCL oracle, built on first use: a cached vocabulary needs no meshes, and building
// them costs more than reading it.
class LazyOracle {
public:
    LazyOracle(const g::Mechanism& m, const g::PairSpec& pair, Diagnostics& diags) : m_(m), pair_(pair), diags_(diags) {}
    // Null, with a located error, when FCL cannot build a part's model.
    const g::FclPairOracle* get() {
        if (oracle_ || failed_) return oracle_.get();
        try {
            oracle_ = g::pair_oracle(m_, pair_);
        } catch (const g::ModelBuildError& e) {
            m_.error(diags_, pair_.where, std::string(e.what()) + "; raise chordal-tolerance to build smaller models");
            failed_ = true;
        }
        return oracle_.get();
    }
    [[nodiscard]] std::shared_ptr<const g::FclPairOracle> shared() const { return oracle_; }

private:
    const g::Mechanism& m_;
    const g::PairSpec& pair_;
    Diagnostics& diags_;
    std::shared_ptr<g::FclPairOracle> oracle_;
    bool failed_ = false;
};

// Parts that overlap as drawn are refused as `--emit-def` refuses them (bridge/scene_at_config.cpp):
// by the same test, so the two commands agree. Parts clearly apart need no FCL model to say so.
// True, with the error in diags, when the pair is refused (or its model cannot be built).
bool refused_as_drawn(const g::Mechanism& m, const g::PairSpec& pair, LazyOracle& oracle, Diagnostics& diags) {
    const g::ContactRequest request{m.settings.contact_tolerance, m.settings.normal_zero_tolerance};
    const Eigen::Vector2d drawn = Eigen::Vector2d::Zero();
    if (g::apart_beyond_contact(m.parts[pair.a], m.parts[pair.b], drawn, request, g::pair_chordal_tolerance(m, pair))) return false;
    const g::FclPairOracle* fcl = oracle.get();
    if (!fcl) return true;
    const auto r = g::detect_contacts(*fcl, drawn, request);
    if (r.status != g::ContactStatus::overlapping) return false;
    m.error(diags, pair.where, r.message + " (as drawn)");
    return true;
}

bool all_free(const g::PlaceVocabulary& v) {
    return std::all_of(v.places.begin(), v.places.end(), [](const g::Place& p) { return p.kind == g::PlaceKind::face && !p.gap; });
}

}  // namespace

std::string pair_symbol(std::string_view a, std::string_view b) { return std::string(a) + "/" + std::string(b); }

std::optional<PairPlaces> pair_places(const g::Mechanism& m, const g::PairSpec& pair, const PlaceOptions& options, Diagnostics& diags) {
    LazyOracle oracle(m, pair, diags);
    if (options.oracle && !oracle.get()) return std::nullopt;
    if (refused_as_drawn(m, pair, oracle, diags)) return std::nullopt;
    PairPlaces out;
    out.name = pair_symbol(m.parts[pair.a].name, m.parts[pair.b].name);
    out.spec = pair;
    out.request = g::place_request(m, pair);
    const g::PlaceCache* cache = options.cache;
    const std::string material = g::place_cache_material(g::pair_fingerprint(m, pair), out.request);
    // The sampled space is not cached: wanted, the vocabulary is computed (and the file replaced).
    g::CacheLoad loaded;
    if (cache && !options.space) loaded = cache->load(material);
    std::string note;  // what the cache did, when it is not a plain hit or store
    if (loaded.status == g::CacheStatus::hit) {
        out.vocabulary = std::move(loaded.vocabulary);
        out.from_cache = true;
    } else {
        const g::FclPairOracle* fcl = oracle.get();
        if (!fcl) return std::nullopt;
        auto built = g::build_place_vocabulary(*fcl, out.request);
        if (built.status != g::PlaceStatus::ok) throw InternalError("place vocabulary of pair " + out.name + ": " + built.message);
        if (cache) note = g::cache_note(*cache, material, loaded, cache->store(material, built.vocabulary));
        out.vocabulary = std::move(built.vocabulary);
        if (options.space) out.space = std::move(built.space);
    }
    if (!note.empty()) diags.add(Severity::warning, pair.where, std::move(note), m.source ? m.source->line_of(pair.where) : std::string_view());
    if (out.vocabulary.count(g::PlaceKind::face) == 0) {
        // No free area: parts drawn in contact with zero play move only in contact (8.1.6's gap
        // place in the limit); parts drawn overlapping have no place at all.
        const g::FclPairOracle* fcl = oracle.get();
        if (!fcl) return std::nullopt;
        const g::ContactRequest touching{m.settings.contact_tolerance, m.settings.normal_zero_tolerance};
        if (auto in_contact = g::contact_place(*fcl, out.request, touching)) out.vocabulary = std::move(*in_contact);
        else out.no_place = true;
    }
    if (options.forces && !out.no_place) out.forces = pair_forces(m, pair, out.vocabulary);
    if (options.oracle) out.oracle = oracle.shared();
    return out;
}

std::optional<std::vector<PairPlaces>> mechanism_places(const g::Mechanism& m, const PlaceOptions& options, Diagnostics& diags) {
    const auto selection = g::kinematic_pairs(m);
    bool ok = true;
    for (const auto& s : selection.skipped) {
        m.error(diags, s.where,
                "the parts '" + m.parts[s.a].name + "' and '" + m.parts[s.b].name + "' never touch (" + s.reason +
                    "): a kinematic pair of the envisionment must constrain its parts; remove it from Pairs");
        ok = false;
    }
    if (selection.modelled.empty() && selection.skipped.empty()) {
        m.error(diags, m.where,
                "mechanism '" + m.name + "' has no kinematic pair: nothing to envision (declare Pairs, or draw parts whose motions meet)");
        return std::nullopt;
    }
    PlaceOptions each = options;
    each.forces = false;  // only for a pair that passes the checks below
    std::vector<PairPlaces> out;
    for (const auto& spec : selection.modelled) {
        auto pair = pair_places(m, spec, each, diags);
        if (!pair) {
            ok = false;
            continue;
        }
        const std::string names = "'" + m.parts[spec.a].name + "' and '" + m.parts[spec.b].name + "'";
        if (pair->no_place) {
            m.error(diags, spec.where,
                    names + " have no free space on the sampled grid and are not drawn in contact: they overlap everywhere (check the pivots) or their play is below a grid cell");
            ok = false;
            continue;
        }
        if (all_free(pair->vocabulary)) {
            m.error(diags, spec.where,
                    names + " never touch: their configuration space is all free (" + std::to_string(pair->vocabulary.places.size()) +
                        " place" + (pair->vocabulary.places.size() == 1 ? "" : "s") +
                        ", no contact); a kinematic pair of the envisionment must constrain its parts");
            ok = false;
            continue;
        }
        if (options.forces) pair->forces = pair_forces(m, spec, pair->vocabulary);
        out.push_back(std::move(*pair));
    }
    if (!ok) return std::nullopt;
    return out;
}

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

std::optional<g::PairSpec> find_pair(const g::Mechanism& m, std::string_view text) {
    for (const auto& pair : g::kinematic_pairs(m).modelled)
        if (text == m.parts[pair.a].name + "--" + m.parts[pair.b].name) return pair;
    return std::nullopt;
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

}  // namespace qm::bridge
