// tests/cli/executable_prefault_test.cpp: prefault_executable() (cli/executable_prefault.hpp), seen
// in a running qm-atms: a session reading a pipe is paused between two commands, and every page of
// the executable's code mapping is then in its page tables (/proc/PID/smaps: Rss equal to Size),
// where faulting them in one by one leaves most of them out (the analysis of a scene touches some
// of the code). Skipped on a kernel without MADV_POPULATE_READ (before Linux 5.14), where the
// function leaves the pages alone.
#include <cstdio>
#include <doctest/doctest.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

struct Mapping {
    bool found = false;
    std::size_t size_kb = 0, rss_kb = 0;
};

// The executable mapping (r-xp) of the file `exe` in process `pid`.
Mapping code_mapping(pid_t pid, const std::string& exe) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/smaps");
    Mapping m;
    bool in_code = false;
    for (std::string line; std::getline(in, line);) {
        const auto space = line.find(' ');
        if (space != std::string::npos && line.find('-') < space) {  // an entry's header
            if (m.found) break;
            in_code = line.find(" r-xp ") != std::string::npos && line.ends_with(exe);
            m.found = in_code;
            continue;
        }
        if (!in_code) continue;
        std::istringstream fields(line);
        std::string name;
        std::size_t kb = 0;
        fields >> name >> kb;
        if (name == "Size:") m.size_kb = kb;
        if (name == "Rss:") m.rss_kb = kb;
    }
    return m;
}

bool kernel_has_populate() {
    utsname u{};
    if (uname(&u) != 0) return false;
    int major = 0, minor = 0;
    std::sscanf(u.release, "%d.%d", &major, &minor);
    return major > 5 || (major == 5 && minor >= 14);
}

}  // namespace

TEST_CASE("cli/executable_prefault: a running qm-atms has all its code mapped") {
    if (!kernel_has_populate()) {
        MESSAGE("skipped: the kernel has no MADV_POPULATE_READ");
        return;
    }
    const std::string exe = std::string(QM_BINARY_DIR) + "/cli/qm-atms";
    const std::string scene = std::string(QM_SOURCE_DIR) + "/scenarios/alex/gears.def";
    int to_child[2], from_child[2];
    REQUIRE(pipe(to_child) == 0);
    REQUIRE(pipe(from_child) == 0);
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        dup2(to_child[0], 0);
        dup2(from_child[1], 1);
        close(to_child[1]);
        close(from_child[0]);
        execl(exe.c_str(), exe.c_str(), scene.c_str(), "-i", static_cast<char*>(nullptr));
        _exit(127);
    }
    close(to_child[0]);
    close(from_child[1]);
    // One command answered: the analysis is done and the session waits for the next line.
    const std::string command = "motions\n";
    REQUIRE(write(to_child[1], command.data(), command.size()) == static_cast<ssize_t>(command.size()));
    std::string answer;
    char buf[4096];
    while (answer.find("consistent combination") == std::string::npos) {
        const ssize_t n = read(from_child[0], buf, sizeof buf);
        if (n <= 0) break;
        answer.append(buf, static_cast<std::size_t>(n));
    }
    CHECK(answer.find("consistent combination") != std::string::npos);
    const Mapping m = code_mapping(pid, "/cli/qm-atms");
    close(to_child[1]);  // the end of the session's input
    while (read(from_child[0], buf, sizeof buf) > 0) {
    }
    close(from_child[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
    REQUIRE(m.found);
    CHECK(m.size_kb > 1024);  // the light executable's code, linked statically: megabytes
    CHECK(m.rss_kb == m.size_kb);
}
