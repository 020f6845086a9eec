// cli/explore_command.cpp: `qm-atms explore`, the explorer page (docs/EXPLORER.md).
#include "explore_command.hpp"
#include "command_options.hpp"
#include "geometry_usage.hpp"

#include "explore_assets.hpp"
#include "explore_data.hpp"
#include "state_drawing.hpp"

#include "envision/behaviour_query.hpp"
#include "geometry/metric_scene_parser.hpp"

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace qm::cli {

namespace {

namespace g = qm::geometry;

int usage_error(std::ostream& err, const std::string& what) {
    err << "qm-atms: " << what << "\n" << explore_usage();
    return 2;
}

}  // namespace

int explore_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    CommandOptions cl(explore_usage());
    std::vector<std::string> scenes, path_texts, avoid;
    std::optional<std::string> folder, cache_text;
    bool no_cache = false, no_envision = false;
    cl.positionals(scenes);
    cl.single("-o", "a folder to write the page to", folder);
    cl.flag("--no-envision", no_envision);
    cl.repeated("--path", "a behaviour to play, e.g. --path 'follower=+; follower=-'", path_texts);
    cl.repeated("--avoid", "a state description to avoid, e.g. --avoid 'cam=0'", avoid);
    cl.place_cache(cache_text, no_cache);
    if (auto status = cl.parse(args, out, err)) return *status;
    if (scenes.empty()) return cl.error(err, "explore takes a metric scene");
    if (scenes.size() > 1) return cl.error(err, "explore takes one metric scene, not '" + scenes[0] + "' and '" + scenes[1] + "'");
    if (!folder) return cl.error(err, "explore needs -o DIR");
    if (no_envision && !path_texts.empty()) return cl.error(err, "--path plays a path of the envisionment, which --no-envision leaves out");
    if (!avoid.empty() && path_texts.empty()) return cl.error(err, "--avoid goes with --path");
    const std::optional<std::filesystem::path> dir = *folder;
    std::optional<std::filesystem::path> cache_dir;
    if (cache_text) cache_dir = *cache_text;
    const bool use_cache = !no_cache, envisioned = !no_envision;
    Diagnostics diags;
    const auto m = g::read_mechanism_file(scenes[0], diags);
    if (!m) return bad_input(diags, err);
    const auto cache = bridge::open_place_cache(use_cache, cache_dir);
    const auto selection = g::kinematic_pairs(*m);
    std::vector<ExplorePair> pairs;
    if (!g::check_grid_limit(*m, selection, diags)) return bad_input(diags, err);
    for (const auto& pair : selection.modelled) {
        auto places = bridge::pair_places(*m, pair, {.cache = cache ? &*cache : nullptr, .space = true, .oracle = true}, diags);
        if (!places) return bad_input(diags, err);
        pairs.push_back({pair, std::move(*places)});
    }
    // The envisionment, as `qm-atms envision` computes it (the same ids), and the behaviours asked for.
    std::optional<qm::envision::Envisionment> e;
    std::vector<ExplorePath> paths;
    if (envisioned) {
        e = envision_for_drawing(*m, use_cache, cache_dir, diags);
        if (!e || diags.has_errors()) {
            diags.print(err);
            err << "qm-atms: explore: the envisionment failed (above); --no-envision writes the page without it\n";
            return 2;
        }
        for (const auto& text : path_texts) {
            const auto b = qm::envision::parse_behaviour(*e, text, "--path", avoid, diags);
            if (!b) return bad_input(diags, err);
            const auto answer = qm::envision::find_behaviour(*e, *b);
            if (answer.path.empty()) err << "qm-atms: explore: no path matches '" << text << "' (envision --path says how far one gets)\n";
            paths.push_back({text, b->chain, answer.path});
        }
    }
    diags.print(err);
    std::ostringstream data;
    write_explore_data(data, *m, pairs, selection.skipped, e ? &*e : nullptr, paths);
    std::error_code ec;
    std::filesystem::create_directories(*dir, ec);
    if (ec) return usage_error(err, "cannot create the folder '" + dir->string() + "'");
    for (const auto& asset : explore_assets()) {
        std::string text(asset.text);
        if (asset.name == "index.html") {
            const auto at = text.find("@QM_DATA@");
            if (at != std::string::npos) text.replace(at, 9, data.str());
        }
        std::ofstream file(*dir / std::string(asset.name));
        file << text;
        if (!file) return usage_error(err, "cannot write '" + (*dir / std::string(asset.name)).string() + "'");
    }
    out << "wrote " << (*dir / "index.html").string() << " (" << pairs.size() << " pair" << (pairs.size() == 1 ? "" : "s");
    if (e) {
        std::size_t states = 0;
        for (const auto& c : e->chains) states += c.states.size();
        out << ", " << e->chains.size() << " chain" << (e->chains.size() == 1 ? "" : "s") << ", " << states << " state" << (states == 1 ? "" : "s");
    }
    out << ")\n";
    return 0;
}

}  // namespace qm::cli
