// cli/scene_options.cpp: the command line of `qm-atms SCENE.def` (usage in cli/scene_command.cpp).
#include "scene_options.hpp"
#include <charconv>

namespace qm::cli {

std::optional<std::size_t> positive(const std::string& s) {
    std::size_t v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || p != s.data() + s.size() || v == 0) return std::nullopt;
    return v;
}

std::optional<SceneOptions> parse_scene_options(std::span<const std::string> args, std::ostream& err) {
    SceneOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&](const char* what) -> std::optional<std::string> {
            if (i + 1 >= args.size()) {
                err << "qm-atms: error: " << a << " needs " << what << '\n';
                return std::nullopt;
            }
            return args[++i];
        };
        if (a == "--json") o.json = true;
        else if (a == "-i" || a == "--interactive") o.interactive = true;
        else if (a == "--why") {
            auto v = value("a fact, e.g. --why 'Rotational-Motion (follower (-))'");
            if (!v) return std::nullopt;
            if (o.why) {  // one explanation per run: a second --why would silently replace the first
                err << "qm-atms: error: --why is given twice ('" << *o.why << "', '" << *v << "'); ask one at a time, or use -i\n";
                return std::nullopt;
            }
            o.why = *v;
        } else if (a == "--situation") {
            auto v = value("a situation number (1 is the first)");
            if (!v) return std::nullopt;
            if (o.situation) {
                err << "qm-atms: error: --situation is given twice\n";
                return std::nullopt;
            }
            o.situation = positive(*v);
            if (!o.situation) {
                err << "qm-atms: error: --situation expects a number from 1, not '" << *v << "'\n";
                return std::nullopt;
            }
        } else if (a == "--given") {
            auto v = value("a motion, e.g. --given 'pallet (0 0) (+)'");
            if (!v) return std::nullopt;
            o.given.push_back(*v);
        } else if (a == "--without") {
            auto v = value("a contact or force, e.g. --without 'Contact tb block-b-m', --without 'Force block' or --without 'Force block wind'");
            if (!v) return std::nullopt;
            o.without.push_back(*v);
        } else if (a == "--rules") {
            auto v = value("a folder of .rules files");
            if (!v) return std::nullopt;
            o.rules = *v;
        } else if (a == "--config") {
            auto v = value("a configuration of a metric scene, e.g. --config 'wheel=12, pallets=-3'");
            if (!v) return std::nullopt;
            o.config = *v;
        } else if (a == "--limit") {
            auto v = value("a number of combinations");
            if (!v) return std::nullopt;
            auto n = positive(*v);
            if (!n) {
                err << "qm-atms: error: --limit expects a positive number, not '" << *v << "'\n";
                return std::nullopt;
            }
            o.limit = *n;
        } else if (!a.empty() && a[0] == '-') {
            err << "qm-atms: error: unknown option '" << a << "'\n";
            return std::nullopt;
        } else if (o.scene.empty()) {
            o.scene = a;
        } else {
            err << "qm-atms: error: more than one scene given ('" << o.scene << "', '" << a << "')\n";
            return std::nullopt;
        }
    }
    if (o.scene.empty()) {
        err << "qm-atms: error: no scene given\n";
        return std::nullopt;
    }
    if (o.interactive && o.why) {
        err << "qm-atms: error: -i answers queries itself: give --why or -i, not both\n";
        return std::nullopt;
    }
    return o;
}

}  // namespace qm::cli
