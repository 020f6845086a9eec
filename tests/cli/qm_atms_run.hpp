// tests/cli/qm_atms_run.hpp: runs the built qm-atms (or another executable) with arguments (through
// the shell) and returns its exit status, standard output and standard error; and reads a whole file.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace qm::test {

struct Run {
    int status = -1;
    std::string out, err;
};

inline std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Runs the executable at `path` (e.g. QM_BINARY_DIR/cli/qm-atms-geometry) with `args`; `tag` keeps
// the temporary files of different test programs apart.
inline Run run_executable(const std::string& path, const std::string& args, const std::string& tag) {
    static int counter = 0;
    const std::string base = std::string(QM_BINARY_DIR) + "/" + tag + "_" + std::to_string(++counter);
    const std::string cmd = path + " " + args + " >" + base + ".out 2>" + base + ".err";
    const int raw = std::system(cmd.c_str());
    Run r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(base + ".out"), slurp(base + ".err")};
    std::remove((base + ".out").c_str());
    std::remove((base + ".err").c_str());
    return r;
}

// The qm-atms command as users run it: the light executable, which hands geometry commands to
// qm-atms-geometry beside it (cli/geometry_dispatch.hpp).
inline Run qm_atms(const std::string& args, const std::string& tag) {
    return run_executable(std::string(QM_BINARY_DIR) + "/cli/qm-atms", args, tag);
}

inline std::string metric_scene(const std::string& name) { return std::string(QM_SOURCE_DIR) + "/scenarios/metric/" + name; }

}  // namespace qm::test
