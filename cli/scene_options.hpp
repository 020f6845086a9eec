// cli/scene_options.hpp
// Provides:   SceneOptions, the options of `qm-atms SCENE.def` (cli/scene_command.hpp, whose usage
//             text lists them), read by parse_scene_options(), which also refuses the combinations
//             in which an option would change nothing (--full with --json, which gives every tree
//             whole; --kinematic with --why, whose answer lists no combinations).
// Errors:     a bad command line is reported on err as `qm-atms: error: ...` with the usage
//             (cli/command_options.hpp); --situation is checked against the scene once it is read.
#pragma once
#include "command_options.hpp"
#include "resource_limits.hpp"
#include <cstddef>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace qm::cli {

struct SceneOptions {
    std::string scene;
    bool json = false;
    bool interactive = false;
    bool full = false;       // --why: every reason and every step (docs/OUTPUT.md)
    bool kinematic = false;  // list the kinematically consistent combinations (docs/OUTPUT.md)
    std::optional<std::string> why;
    std::optional<std::string> situation_text;  // --situation as given
    std::optional<std::size_t> situation;       // --situation once checked against the scene
    std::vector<std::string> given, without, with;  // as written; read and checked by scene/what_if.hpp
    std::optional<std::string> rules;
    std::optional<std::string> config;  // metric scenes: the configuration (cli/metric_command.hpp)
    std::size_t limit = 100000;
    ResourceLimits limits;  // --max-facts, --max-environments, --max-memory
};

// nullopt: `options` read; otherwise the exit status to return (0 after --help or --version, 2 after an error).
[[nodiscard]] std::optional<int> parse_scene_options(std::span<const std::string> args, SceneOptions& options, std::ostream& out,
                                                     std::ostream& err);

}  // namespace qm::cli
