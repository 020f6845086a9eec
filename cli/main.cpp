// cli/main.cpp: the qm-atms command. The only place that prints diagnostics and picks the exit
// status: 0 success, 2 bad input, 1 internal error (STYLE.md section 6).
// Compiled into both executables of cli/ (cli/geometry_dispatch.hpp): the light qm-atms and
// qm-atms-geometry differ only in geometry_command() (cli/geometry_command.hpp), which runs the
// command lines that need the geometry stack, or hands them to qm-atms-geometry.
#include "qm/assert.hpp"
#include "check_command.hpp"
#include "geometry_command.hpp"
#include "geometry_dispatch.hpp"
#include "geometry_usage.hpp"
#include "executable_prefault.hpp"
#include "heap_setup.hpp"
#include "resource_limits.hpp"
#include "run_command.hpp"
#include "scene_command.hpp"
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>
#include <unistd.h>

namespace {

constexpr const char* usage =
    "usage: qm-atms SCENE.def [options]          analyse a scene (thesis chapters 6-7)\n"
    "       qm-atms run PROGRAM.rules [--why 'FACT'] [--json] [--max-facts N] [--max-environments N] [--max-memory SIZE]\n"
    "       qm-atms envision METRIC-SCENE [options]    the envisionment of a mechanism (thesis chapters 8-9)\n"
    "       qm-atms check [RULES-DIR | FILE.rules]... [--dimensions 2|3]\n"
    "       qm-atms --help\n";

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
        qm::cli::prepare_heap();  // every command below may grow a large heap (cli/heap_setup.hpp)
        qm::cli::prefault_executable();  // and touches much of the code (cli/executable_prefault.hpp)
        if (args[0] == "run") {
            doing = "running " + (args.size() > 1 ? args[1] : std::string("a rule program"));
            return qm::cli::run_command(std::span<const std::string>(args).subspan(1), std::cout, std::cerr);
        }
        if (args[0] == "check") {  // rule files checked like code (cli/check_command.hpp)
            doing = "checking " + (args.size() > 1 ? args[1] : std::string("the laws"));
            return qm::cli::check_command(std::span<const std::string>(args).subspan(1), std::cout, std::cerr);
        }
        // envision, draw, explore, --emit-def, --places, a metric scene (cli/geometry_dispatch.hpp)
        if (qm::cli::needs_geometry(args)) return qm::cli::geometry_command(argv, args, std::cin, std::cout, std::cerr, doing);
        // a session on a terminal: line editing is qm-atms-geometry's (cli/geometry_dispatch.hpp)
        if (qm::cli::interactive_on_terminal(args, isatty(STDIN_FILENO) != 0))
            return qm::cli::terminal_session(argv, args, std::cin, std::cout, std::cerr, doing);
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
