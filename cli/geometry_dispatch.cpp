// cli/geometry_dispatch.cpp: which executable runs a command line (cli/geometry_dispatch.hpp).
#include "geometry_dispatch.hpp"
#include "scene_options.hpp"
#include "qm/file_text.hpp"
#include "qm/source_text.hpp"
#include <array>
#include <cctype>
#include <sstream>

namespace qm::cli {

bool is_metric_scene(std::string_view text) {
    std::size_t i = text.starts_with(SourceText::byte_order_mark) ? SourceText::byte_order_mark.size() : 0;
    for (;;) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i >= text.size() || text[i] != ';') break;
        while (i < text.size() && text[i] != '\n') ++i;
    }
    if (i >= text.size() || text[i] != '(') return false;
    for (++i; i < text.size() && std::isspace(static_cast<unsigned char>(text[i]));) ++i;
    std::string word;
    for (; i < text.size() && std::isalnum(static_cast<unsigned char>(text[i])) && word.size() < 12; ++i)
        word += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
    return word == "defmechanism";
}

bool needs_geometry(std::span<const std::string> args) {
    if (args.empty()) return false;
    constexpr std::array<std::string_view, 5> geometry_commands = {"envision", "draw", "explore", "--emit-def", "--places"};
    for (std::string_view c : geometry_commands)
        if (args[0] == c) return true;
    constexpr std::array<std::string_view, 4> light_commands = {"run", "check", "--help", "-h"};
    for (std::string_view c : light_commands)
        if (args[0] == c) return false;
    // A scene analysis: the scene is found as the scene command finds it (cli/scene_options.hpp);
    // a command line it rejects is rejected here too, with the message left to the command.
    std::ostringstream ignored;
    const auto options = parse_scene_options(args, ignored);
    if (!options) return false;
    const FileText file = read_file_text(options->scene);
    return file.text && is_metric_scene(*file.text);
}

bool interactive_on_terminal(std::span<const std::string> args, bool input_is_terminal) {
    if (!input_is_terminal || args.empty()) return false;
    constexpr std::array<std::string_view, 4> other_commands = {"run", "check", "--help", "-h"};
    for (std::string_view c : other_commands)
        if (args[0] == c) return false;
    std::ostringstream ignored;  // a command line the scene command rejects is left to it
    const auto options = parse_scene_options(args, ignored);
    return options && options->interactive;
}

}  // namespace qm::cli
