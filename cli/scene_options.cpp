// cli/scene_options.cpp: the command line of `qm-atms SCENE.def` (usage in cli/scene_command.cpp).
#include "scene_options.hpp"
#include "scene_command.hpp"

namespace qm::cli {

std::optional<int> parse_scene_options(std::span<const std::string> args, SceneOptions& o, std::ostream& out, std::ostream& err) {
    CommandOptions cl(scene_usage());
    std::vector<std::string> scenes;
    std::optional<std::string> limit;
    cl.positionals(scenes);
    cl.first_may_be({"--places", "--emit-def"});  // the metric-scene commands (cli/main.cpp)
    cl.flag("--json", o.json);
    cl.flag("-i,--interactive", o.interactive);
    cl.flag("--full", o.full);
    cl.flag("--kinematic", o.kinematic);
    // One explanation per run: a second --why would silently replace the first.
    cl.single("--why", "a fact, e.g. --why 'Rotational-Motion (follower (-))'", o.why, "ask one at a time, or use -i");
    // Checked against the scene once it is read (scene_command.cpp), located like any other
    // out-of-range number.
    cl.single("--situation", "a situation number (1 is the first)", o.situation_text);
    cl.repeated("--given", "a motion, e.g. --given 'pallet (0 0) (+)'", o.given);
    cl.repeated("--without", "a contact or force, e.g. --without 'Contact tb block-b-m', --without 'Force block' or --without 'Force block wind'",
                o.without);
    cl.repeated("--with", "a contact or force, e.g. --with 'Contact tb block-b-m' or --with 'Force block (0 -) (0 0)'", o.with);
    cl.single("--rules", "a folder of .rules files", o.rules);
    cl.single("--config", "a configuration of a metric scene, e.g. --config 'wheel=12, pallets=-3'", o.config);
    cl.single("--limit", "a positive number of combinations", limit);
    declare_limit_options(cl, o.limits);
    if (auto status = cl.parse(args, out, err)) return status;
    if (limit) {
        auto n = positive(*limit);
        if (!n) return cl.bad_value(err, "--limit", *limit);
        o.limit = *n;
    }
    if (auto status = read_limit_options(cl, o.limits, err)) return status;
    if (scenes.empty()) return cl.error(err, "no scene given");
    if (scenes.size() > 1) return cl.error(err, "more than one scene given ('" + scenes[0] + "', '" + scenes[1] + "')");
    o.scene = scenes[0];
    if (o.full && !o.why) return cl.error(err, "--full shows a --why answer whole: give it with --why (or `full on` in -i)");
    if (o.interactive && o.why) return cl.error(err, "-i answers queries itself: give --why or -i, not both");
    if (o.full && o.json) return cl.error(err, "--full shows a --why answer whole, which --json always does: give --json alone");
    if (o.kinematic && o.why)
        return cl.error(err, "--kinematic lists combinations of motions, which a --why answer does not show: give --why or --kinematic, not both");
    return std::nullopt;
}

}  // namespace qm::cli
