// bridge/scene_at_config.cpp: a metric scene's parts at one configuration as the Alex scene model
// (bridge/scene_at_config.hpp): the contacts of every kinematic pair there (Def 19) and the forces
// acting there (8.2.1), converted item by item by detail/alex_scene_builder.
#include "bridge/scene_at_config.hpp"

#include "bridge/detail/alex_scene_builder.hpp"
#include "geometry/fcl_part_model.hpp"
#include "geometry/contact_detection.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "qm/assert.hpp"
#include "qm/printable_text.hpp"

namespace qm::bridge {

namespace g = qm::geometry;

SceneAtConfig::SceneAtConfig(const g::Mechanism& m, std::vector<g::PairSpec> pairs)
    : m_(m), pairs_(pairs.empty() ? g::kinematic_pairs(m).modelled : std::move(pairs)) {
    for (const auto& pair : pairs_) oracles_.push_back(g::pair_oracle(m, pair));
}

std::optional<scene::Scene> SceneAtConfig::at(const g::Configuration& q, Diagnostics& diags, const std::string& config_text) const {
    QM_REQUIRE(q.q.size() == m_.parts.size(), "a configuration needs one coordinate per part");
    detail::AlexSceneBuilder builder(m_, q);
    const g::ContactRequest request{m_.settings.contact_tolerance, m_.settings.normal_zero_tolerance};
    bool ok = true;
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
        const g::PairSpec& pair = pairs_[k];
        const auto r = g::detect_contacts(*oracles_[k], {q.at(pair.a), q.at(pair.b)}, request);
        if (r.status == g::ContactStatus::overlapping) {
            m_.error(diags, pair.where, r.message + (config_text.empty() ? " (as drawn)" : " (CONFIG '" + printable_text(config_text) + "')"));
            ok = false;
            continue;
        }
        builder.add_contacts(pair, r);
    }
    if (!ok) return std::nullopt;
    builder.add_forces();
    return std::move(builder).finish();
}

std::optional<scene::Scene> scene_at_config(const g::Mechanism& m, const g::Configuration& q, Diagnostics& diags) {
    return SceneAtConfig(m).at(q, diags);
}

std::optional<scene::Scene> read_scene_at_config(const std::string& path, const std::string& config, Diagnostics& diags) {
    const auto m = g::read_mechanism_file(path, diags);
    if (!m) return std::nullopt;
    const auto q = g::parse_configuration(*m, config, diags);
    if (!q) return std::nullopt;
    try {
        return SceneAtConfig(*m).at(*q, diags, config);
    } catch (const g::ModelBuildError& e) {  // bad input: a part too finely chorded for FCL
        diags.error({path, 1, 1}, std::string(e.what()) + "; raise chordal-tolerance to build smaller models");
        return std::nullopt;
    }
}

}  // namespace qm::bridge
