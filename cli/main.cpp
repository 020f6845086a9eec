// cli/main.cpp: the qm-atms command. The only place that prints diagnostics and picks the exit
// status: 0 success, 2 bad input, 1 internal error (STYLE.md section 6).
#include "qm/assert.hpp"
#include "check_command.hpp"
#include "command_options.hpp"
#include "draw_command.hpp"
#include "envision_command.hpp"
#include "explore_command.hpp"
#include "geometry_usage.hpp"
#include "metric_command.hpp"
#include "resource_limits.hpp"
#include "run_command.hpp"
#include "scene_command.hpp"
#include "qm/spelling.hpp"
#include <array>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr const char* usage =
    "usage: qm-atms SCENE.def [options]          analyse a scene (thesis chapters 6-7)\n"
    "       qm-atms run PROGRAM.rules [--why 'FACT'] [--json] [--max-facts N] [--max-environments N] [--max-memory SIZE]\n"
    "       qm-atms envision METRIC-SCENE [options]    the envisionment of a mechanism (thesis chapters 8-9)\n"
    "       qm-atms check [RULES-DIR | FILE.rules]... [--dimensions 2|3]\n"
    "       qm-atms --help | --version    (COMMAND --help: that command's usage alone)\n";

// The commands named by a word (the others are options: --places, --emit-def).
constexpr std::array<std::string_view, 5> commands = {"run", "check", "envision", "draw", "explore"};

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    std::string doing = "starting";
    try {
        if (args.empty()) {
            std::cerr << usage;
            return 2;
        }
        if (args[0] == "--help" || args[0] == "-h") {
            std::cout << usage << '\n' << qm::cli::scene_usage() << '\n' << qm::cli::metric_usage() << qm::cli::draw_usage()
                      << qm::cli::explore_usage() << '\n' << qm::cli::envision_usage() << '\n' << qm::cli::run_usage() << '\n'
                      << qm::cli::check_usage();
            return 0;
        }
        if (args[0] == "--version") {
            std::cout << qm::cli::version_text() << '\n';
            return 0;
        }
        // A misspelt command would be read as a scene file of that name: named instead, unless
        // such a file is there.
        std::error_code ec;
        if (args[0].find_first_of("./") == std::string::npos && !std::filesystem::exists(args[0], ec))
            if (auto near = qm::nearest_spelling(args[0], commands)) {
                std::cerr << "qm-atms: error: unknown command '" << args[0] << "'; did you mean '" << *near << "'?\n" << usage;
                return 2;
            }
        if (args[0] == "run") {
            doing = "running " + (args.size() > 1 ? args[1] : std::string("a rule program"));
            return qm::cli::run_command(std::span<const std::string>(args).subspan(1), std::cout, std::cerr);
        }
        if (args[0] == "check") {  // rule files checked like code (cli/check_command.hpp)
            doing = "checking " + (args.size() > 1 ? args[1] : std::string("the laws"));
            return qm::cli::check_command(std::span<const std::string>(args).subspan(1), std::cout, std::cerr);
        }
        const auto rest = std::span<const std::string>(args).subspan(1);
        const std::string what = args.size() > 1 ? args[1] : std::string("a metric scene");
        if (args[0] == "envision") {  // the envisioner (cli/envision_command.hpp)
            doing = "envisioning " + what;
            return qm::cli::envision_command(rest, std::cout, std::cerr);
        }
        if (args[0] == "draw" || args[0] == "explore") {  // pictures of metric scenes
            doing = "drawing " + what;
            return args[0] == "draw" ? qm::cli::draw_command(rest, std::cout, std::cerr)
                                     : qm::cli::explore_command(rest, std::cout, std::cerr);
        }
        if (args[0] == "--emit-def" || args[0] == "--places") {  // metric scenes (cli/metric_command.hpp)
            doing = "reading " + what;
            return args[0] == "--emit-def" ? qm::cli::emit_def_command(rest, std::cout, std::cerr)
                                           : qm::cli::places_command(rest, std::cout, std::cerr);
        }
        // An Alex scene, or a metric scene analysed at --config as the scene --emit-def writes.
        doing = "analysing " + args[0];
        return qm::cli::scene_command(args, std::cin, std::cout, std::cerr);
    } catch (const qm::LimitReached& e) {  // a resource limit (cli/resource_limits.hpp): bad input at these settings
        std::cerr << qm::cli::limit_message(e, doing);
        return 2;
    } catch (const std::bad_alloc&) {
        if (auto m = qm::cli::memory_limit_message(doing)) {
            std::cerr << *m;
            return 2;
        }
        std::cerr << "qm-atms: internal error: out of memory (while " << doing << ")\n";
        return 1;
    } catch (const qm::InternalError& e) {
        std::cerr << "qm-atms: internal error: " << e.what() << " (while " << doing << ")\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "qm-atms: internal error: " << e.what() << " (while " << doing << ")\n";
        return 1;
    }
}
