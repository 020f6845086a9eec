// cli/geometry_delegate.cpp: the light qm-atms hands a geometry command line to qm-atms-geometry
// (cli/geometry_command.hpp), and so an interactive session on a terminal (terminal_session). An exec, not a child process: no second process to wait for, and the
// exit status, signals and standard streams (a terminal for `-i`, a progress bar) are the full
// executable's own.
#include "geometry_command.hpp"
#include <cerrno>
#include <cstring>
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

// Replaces the process with qm-atms-geometry, same argv; returns 1 with a message if it cannot.
int exec_full_executable(char** argv, std::span<const std::string> args, std::ostream& out, std::ostream& err, std::string& doing) {
    doing = "starting qm-atms-geometry";
    const std::string folder = own_folder();
    const std::string full = folder + "qm-atms-geometry";
    out.flush();  // nothing is written before, but a buffered byte would be lost by the exec
    err.flush();
    int why = ENOENT;
    if (!folder.empty()) {
        ::execv(full.c_str(), argv);  // returns only on failure
        why = errno;
    }
    err << "qm-atms: internal error: cannot run '" << (folder.empty() ? std::string("qm-atms-geometry") : full)
        << "': " << std::strerror(why) << "\n"
        << "  '" << args[0] << "' needs the geometry stack, which is in the executable qm-atms-geometry, built and\n"
        << "  installed beside qm-atms (cmake --build BUILD --target qm-atms-geometry; cmake --install BUILD)\n";
    return 1;
}

}  // namespace

int geometry_command(char** argv, std::span<const std::string> args, std::istream& in, std::ostream& out, std::ostream& err,
                     std::string& doing) {
    (void)in;
    return exec_full_executable(argv, args, out, err, doing);
}

int terminal_session(char** argv, std::span<const std::string> args, std::istream& in, std::ostream& out, std::ostream& err,
                     std::string& doing) {
    (void)in;  // the terminal is inherited through the exec
    return exec_full_executable(argv, args, out, err, doing);
}

}  // namespace qm::cli
