// tests/cli/qm_atms_run.hpp: runs the built qm-atms (or another executable) with arguments (through
// the shell), optionally in another folder and with text on standard input, and returns its exit
// status, standard output and standard error; reads and writes whole files. Every CLI test runs the
// executable through here, so the temporary files are named and removed one way.
#pragma once
#include "../support/golden.hpp"
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace qm::test {

struct Run {
    int status = -1;
    std::string out, err;
};

// How to run: `input`, when set, is written to a file and given as standard input (an interactive
// session's lines); `folder`, when set, is the working folder (so that relative paths in messages
// stay the same wherever the tree is).
struct RunIn {
    std::optional<std::string> input;
    std::string folder;
};

// Runs the executable at `path` (e.g. a copy of qm-atms) with `args`; `tag` keeps
// the temporary files of different test programs apart.
inline Run run_executable(const std::string& path, const std::string& args, const std::string& tag, const RunIn& how = {}) {
    static int counter = 0;
    const std::string base = std::string(QM_BINARY_DIR) + "/" + tag + "_" + std::to_string(++counter);
    std::string cmd = how.folder.empty() ? "" : "cd " + how.folder + " && ";
    cmd += path + " " + args;
    if (how.input) {
        std::ofstream(base + ".in") << *how.input;
        cmd += " <" + base + ".in";
    }
    cmd += " >" + base + ".out 2>" + base + ".err";
    const int raw = std::system(cmd.c_str());
    Run r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(base + ".out"), slurp(base + ".err")};
    for (const char* x : {".in", ".out", ".err"}) std::remove((base + x).c_str());
    return r;
}

// The qm-atms command as users run it.
inline Run qm_atms(const std::string& args, const std::string& tag, const RunIn& how = {}) {
    return run_executable(std::string(QM_BINARY_DIR) + "/cli/qm-atms", args, tag, how);
}

inline std::string metric_scene(const std::string& name) { return std::string(QM_SOURCE_DIR) + "/scenarios/metric/" + name; }

// Writes `text` to the file `name` in the build folder; its path.
inline std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = std::string(QM_BINARY_DIR) + "/" + name;
    std::ofstream(path) << text;
    return path;
}

// A copy of the .rules files of `folder` (relative to the source tree, e.g. "rules") in which `file`
// has `from` replaced by `to` (once; nothing when `file` is empty): laws with one slip; its path.
inline std::string mutated_rules(const std::string& folder, const std::string& tag, const std::string& file,
                                 const std::string& from, const std::string& to) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(QM_BINARY_DIR) / ("mutated_" + tag + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& e : fs::directory_iterator(std::string(QM_SOURCE_DIR) + "/" + folder))
        if (e.path().extension() == ".rules") fs::copy_file(e.path(), dir / e.path().filename());
    if (!file.empty()) {
        std::string text = slurp((dir / file).string());
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
        std::ofstream(dir / file) << text;
    }
    return dir.string();
}

// How often `what` occurs in `text`.
inline std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

}  // namespace qm::test
