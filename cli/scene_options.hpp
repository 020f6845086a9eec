// cli/scene_options.hpp
// Provides:   SceneOptions, the options of `qm-atms SCENE.def` (cli/scene_command.hpp, whose usage
//             text lists them), read by parse_scene_options(); and positive(), a positive decimal
//             number as --situation, --limit and the interactive `situation N` take it.
// Errors:     a bad command line is reported on err as `qm-atms: error: ...` and gives nullopt.
#pragma once
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
    std::optional<std::string> why;
    std::optional<std::size_t> situation;
    std::vector<std::string> given, without;  // as written; read and checked by scene/what_if.hpp
    std::optional<std::string> rules;
    std::optional<std::string> config;  // metric scenes: the configuration (cli/metric_command.hpp)
    std::size_t limit = 100000;
};

[[nodiscard]] std::optional<SceneOptions> parse_scene_options(std::span<const std::string> args, std::ostream& err);
[[nodiscard]] std::optional<std::size_t> positive(const std::string& s);

}  // namespace qm::cli
