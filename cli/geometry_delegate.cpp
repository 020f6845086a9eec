// cli/geometry_delegate.cpp: the light qm-atms hands a geometry command line to qm-atms-geometry
// (cli/geometry_command.hpp), and so an interactive session on a terminal (terminal_session). An exec, not a child process: no second process to wait for, and the
// exit status, signals and standard streams (a terminal for `-i`, a progress bar) are the full
// executable's own.
#include "geometry_command.hpp"
#include "scene_command.hpp"
#include <cerrno>
#include <cstring>
#include <utility>
#include <unistd.h>

namespace qm::cli {
namespace {

// The folder of the running executable, with a trailing '/', or empty if it cannot be known.
std::string own_folder() {
    std::string path(4096, '\0');
    const ssize_t n = ::readlink("/proc/self/exe", path.data(), path.size());
    if (n <= 0 || static_cast<std::size_t>(n) >= path.size()) return {};
    path.resize(static_cast<std::size_t>(n));
    return path.substr(0, path.rfind('/') + 1);
}

// Replaces the process with qm-atms-geometry, same argv; returns only if it cannot, with the path
// tried and why.
std::pair<std::string, int> exec_full_executable(char** argv, std::ostream& out, std::ostream& err, std::string& doing) {
    doing = "starting qm-atms-geometry";
    const std::string folder = own_folder();
    out.flush();  // nothing is written before, but a buffered byte would be lost by the exec
    err.flush();
    if (folder.empty()) return {"qm-atms-geometry", ENOENT};
    const std::string full = folder + "qm-atms-geometry";
    ::execv(full.c_str(), argv);  // returns only on failure
    return {full, errno};
}

}  // namespace

int geometry_command(char** argv, std::span<const std::string> args, std::istream& in, std::ostream& out, std::ostream& err,
                     std::string& doing) {
    (void)in;
    const auto [full, why] = exec_full_executable(argv, out, err, doing);
    err << "qm-atms: internal error: cannot run '" << full << "': " << std::strerror(why) << "\n"
        << "  '" << args[0] << "' needs the geometry stack, which is in the executable qm-atms-geometry, built and\n"
        << "  installed beside qm-atms (cmake --build BUILD --target qm-atms-geometry; cmake --install BUILD)\n";
    return 1;
}

int terminal_session(char** argv, std::span<const std::string> args, std::istream& in, std::ostream& out, std::ostream& err,
                     std::string& doing) {
    // The terminal is inherited through the exec. Without qm-atms-geometry the session still runs,
    // here, reading whole lines as from a pipe: only the editing and the history are missing.
    const auto [full, why] = exec_full_executable(argv, out, err, doing);
    err << "qm-atms: note: cannot run '" << full << "' (" << std::strerror(why)
        << "), which edits the lines of a session; this one reads them without editing or history\n";
    doing = "analysing " + args[0];
    return scene_command(args, in, out, err);
}

}  // namespace qm::cli
