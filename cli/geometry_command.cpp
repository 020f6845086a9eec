// cli/geometry_command.cpp: the geometry commands, run in qm-atms-geometry (cli/geometry_command.hpp).
#include "geometry_command.hpp"
#include "bridge/scene_at_config.hpp"
#include "draw_command.hpp"
#include "envision_command.hpp"
#include "explore_command.hpp"
#include "metric_command.hpp"
#include "scene_command.hpp"

namespace qm::cli {

int geometry_command(char** argv, std::span<const std::string> args, std::istream& in, std::ostream& out, std::ostream& err,
                     std::string& doing) {
    (void)argv;  // the process is already the one that runs it
    const auto rest = args.subspan(1);
    const std::string what = args.size() > 1 ? args[1] : std::string("a metric scene");
    if (args[0] == "envision") {  // the envisioner (cli/envision_command.hpp)
        doing = "envisioning " + what;
        return envision_command(rest, out, err);
    }
    if (args[0] == "draw" || args[0] == "explore") {  // pictures of metric scenes (cli/draw_command.hpp, explore_command.hpp)
        doing = "drawing " + what;
        return args[0] == "draw" ? draw_command(rest, out, err) : explore_command(rest, out, err);
    }
    if (args[0] == "--emit-def" || args[0] == "--places") {  // metric scenes (cli/metric_command.hpp)
        doing = "reading " + what;
        return args[0] == "--emit-def" ? emit_def_command(rest, out, err) : places_command(rest, out, err);
    }
    // A metric scene analysed at a configuration (--config), as the Alex scene --emit-def writes.
    doing = "analysing " + args[0];
    return scene_command(args, in, out, err, &bridge::read_scene_at_config);
}

int terminal_session(char** argv, std::span<const std::string> args, std::istream& in, std::ostream& out, std::ostream& err,
                     std::string& doing) {
    (void)argv;  // this executable edits lines itself (cli/line_editing_libedit.cpp)
    doing = "analysing " + args[0];
    return scene_command(args, in, out, err);
}

}  // namespace qm::cli
