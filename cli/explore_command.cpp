// cli/explore_command.cpp: `qm-atms explore`, the explorer page (docs/EXPLORER.md).
#include "explore_command.hpp"
#include "geometry_usage.hpp"

#include "explore_assets.hpp"
#include "explore_data.hpp"

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
    if (args.empty()) return usage_error(err, "explore takes a metric scene");
    std::optional<std::filesystem::path> dir, cache_dir;
    bool use_cache = true;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (args[i] == "--no-cache") use_cache = false;
        else if ((args[i] == "-o" || args[i] == "--cache") && i + 1 < args.size()) (args[i] == "-o" ? dir : cache_dir) = args[i + 1], ++i;
        else return usage_error(err, "unknown or incomplete option '" + args[i] + "' for explore");
    }
    if (!dir) return usage_error(err, "explore needs -o DIR");
    Diagnostics diags;
    const auto m = g::read_mechanism_file(args[0], diags);
    if (!m) {
        diags.print(err);
        return 2;
    }
    const auto cache = open_place_cache(use_cache, cache_dir);
    const auto selection = g::kinematic_pairs(*m);
    std::vector<ExplorePair> pairs;
    if (!g::check_grid_limit(*m, selection, diags)) {
        diags.print(err);
        return 2;
    }
    for (const auto& pair : selection.modelled) {
        auto places = pair_places(*m, pair, cache, true, diags);
        if (!places) {
            diags.print(err);
            return 2;
        }
        pairs.push_back({pair, std::move(*places)});
    }
    diags.print(err);
    std::ostringstream data;
    write_explore_data(data, *m, pairs, selection.skipped);
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
    out << "wrote " << (*dir / "index.html").string() << " (" << pairs.size() << " pair" << (pairs.size() == 1 ? "" : "s") << ")\n";
    return 0;
}

}  // namespace qm::cli
