// cli/scene_options.cpp: the command line of `qm-atms SCENE.def` (usage in cli/scene_command.cpp).
#include "scene_options.hpp"

namespace qm::cli {

std::optional<SceneOptions> parse_scene_options(std::span<const std::string> args, std::ostream& err) {
    SceneOptions o;
    CommandLine cl(args, err);
    std::optional<std::string> limit;
    while (cl.next()) {
        const std::string& a = cl.arg();
        if (a == "--json") {
            o.json = true;
        } else if (a == "-i" || a == "--interactive") {
            o.interactive = true;
        } else if (a == "--full") {
            o.full = true;
        } else if (a == "--kinematic") {
            o.kinematic = true;
        } else if (a == "--why") {
            // One explanation per run: a second --why would silently replace the first.
            if (!cl.single(o.why, "a fact, e.g. --why 'Rotational-Motion (follower (-))'", "ask one at a time, or use -i"))
                return std::nullopt;
        } else if (a == "--situation") {
            // Checked against the scene once it is read (scene_command.cpp), located like any
            // other out-of-range number.
            if (!cl.single(o.situation_text, "a situation number (1 is the first)")) return std::nullopt;
        } else if (a == "--given") {
            auto v = cl.value("a motion, e.g. --given 'pallet (0 0) (+)'");
            if (!v) return std::nullopt;
            o.given.push_back(*v);
        } else if (a == "--without") {
            auto v = cl.value("a contact or force, e.g. --without 'Contact tb block-b-m', --without 'Force block' or --without 'Force block wind'");
            if (!v) return std::nullopt;
            o.without.push_back(*v);
        } else if (a == "--with") {
            auto v = cl.value("a contact or force, e.g. --with 'Contact tb block-b-m' or --with 'Force block (0 -) (0 0)'");
            if (!v) return std::nullopt;
            o.with.push_back(*v);
        } else if (a == "--rules") {
            if (!cl.single(o.rules, "a folder of .rules files")) return std::nullopt;
        } else if (a == "--config") {
            if (!cl.single(o.config, "a configuration of a metric scene, e.g. --config 'wheel=12, pallets=-3'")) return std::nullopt;
        } else if (a == "--limit") {
            if (!cl.single(limit, "a positive number of combinations")) return std::nullopt;
            auto n = positive(*limit);
            if (!n) {
                cl.bad_value("a positive number of combinations", *limit);
                return std::nullopt;
            }
            o.limit = *n;
        } else if (auto read = read_limit_option(cl, o.limits)) {
            if (!*read) return std::nullopt;
        } else if (cl.is_option()) {
            cl.unknown();
            return std::nullopt;
        } else if (o.scene.empty()) {
            o.scene = a;
        } else {
            cl.error("more than one scene given ('" + o.scene + "', '" + a + "')");
            return std::nullopt;
        }
    }
    if (o.scene.empty()) {
        cl.error("no scene given");
        return std::nullopt;
    }
    if (o.full && !o.why) {
        cl.error("--full shows a --why answer whole: give it with --why (or `full on` in -i)");
        return std::nullopt;
    }
    if (o.interactive && o.why) {
        cl.error("-i answers queries itself: give --why or -i, not both");
        return std::nullopt;
    }
    return o;
}

}  // namespace qm::cli
