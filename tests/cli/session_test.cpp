// tests/cli/session_test.cpp: the interactive mode (cli/session.hpp, cli/line_editor.hpp) through
// the built executable, driven two ways: from standard input (a pipe: no prompt, only the answers)
// for the messages: "did you mean" for commands and names, the usage of a command given the wrong
// arguments, `with` and `kinematic`; and through a pseudo-terminal, as a person types: the prompt,
// history recalled with the Up arrow (libedit), and a newline written at Ctrl-D so the shell's
// prompt starts on its own line.
#include "qm_atms_run.hpp"
#include <chrono>
#include <csignal>
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <poll.h>
#include <thread>
#include <pty.h>
#include <vector>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

const std::string source_root = QM_SOURCE_DIR;
std::string scene(const std::string& name) { return source_root + "/scenarios/alex/" + name; }

qm::test::Run session(const std::string& args, const std::string& input) { return qm::test::qm_atms(args + " -i", "session", {input, ""}); }

// qm-atms on a pseudo-terminal: what it writes, read until `until` appears (or 20 s pass).
class Terminal {
public:
    explicit Terminal(const std::vector<std::string>& args, const std::string& exe = std::string(QM_BINARY_DIR) + "/cli/qm-atms") {
        pid_ = forkpty(&fd_, nullptr, nullptr, nullptr);
        REQUIRE(pid_ >= 0);
        if (pid_ == 0) {
            setenv("TERM", "xterm", 1);
            std::vector<char*> argv;
            argv.push_back(const_cast<char*>(exe.c_str()));
            for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            execv(exe.c_str(), argv.data());
            _exit(127);
        }
    }
    ~Terminal() {
        if (pid_ > 0 && !exited_) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
        if (fd_ >= 0) close(fd_);
    }
    // Keys are typed a moment after the prompt showed: the line editor sets the terminal's mode
    // after printing its prompt, and keys typed before that may be dropped (seen under load).
    void type(const std::string& keys) {
        std::this_thread::sleep_for(std::chrono::milliseconds(150));
        REQUIRE(write(fd_, keys.data(), keys.size()) == static_cast<ssize_t>(keys.size()));
    }
    // Ctrl-D until the child ends (a key dropped as above is typed again); its exit status.
    int end_input() {
        for (int i = 0; i < 10; ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(150));
            if (write(fd_, "\x04", 1) != 1) break;  // the terminal is closed: the child has ended
            const int status = wait_exit(2);
            if (exited_) return status;
        }
        return wait_exit(20);
    }
    // Everything written since the last call, up to and including `until` (all of it, when `until`
    // does not come within `seconds`).
    std::string read_until(const std::string& until, int seconds = 20) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
        while (seen_.find(until) == std::string::npos && std::chrono::steady_clock::now() < end) {
            pollfd p{fd_, POLLIN, 0};
            if (poll(&p, 1, 100) <= 0) continue;
            char buf[4096];
            const ssize_t n = read(fd_, buf, sizeof buf);
            if (n <= 0) break;
            seen_.append(buf, static_cast<std::size_t>(n));
        }
        const auto at = seen_.find(until);
        std::string out = at == std::string::npos ? seen_ : seen_.substr(0, at + until.size());
        seen_.erase(0, out.size());
        return out;
    }
    int wait_exit(int seconds = 20) {
        int status = 0;
        // Up to 20 s. Once the child has closed the terminal, reading returns at once (EIO) while
        // the child may not be reapable yet: wait a little between tries rather than spin.
        const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
        while (std::chrono::steady_clock::now() < end) {
            keep_ += read_until("\x01never", 1);  // drained, so the child is not blocked writing
            if (waitpid(pid_, &status, WNOHANG) == pid_) {
                exited_ = true;
                keep_ += read_until("\x01never", 0);
                return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return -1;
    }

private:
    int fd_ = -1;
    pid_t pid_ = -1;
    bool exited_ = false;
    std::string seen_;

public:
    std::string keep_;  // what wait_exit() drained
};

}  // namespace

TEST_CASE("cli/session: an unknown command gets 'did you mean', a bad one its usage (from a pipe)") {
    auto r = session(scene("gears.def"), "motoins\nwhatif\nfreedom now\nsituation\njson maybe\nwhy\nwith\nhelp\n");
    CHECK(r.status == 0);
    CHECK(r.err ==
          "unknown command 'motoins'; did you mean 'motions'? (type help)\n"
          "usage: whatif Contact A B | Force OBJ [CAUSE] [; ...], e.g. whatif Contact tb block-b-m; Force block: the situation with contacts or forces taken away\n"
          "usage: freedom: the free directions of every object\n"
          "usage: situation N, e.g. situation 2: ask about situation N from now on (1 is the first)\n"
          "usage: json [on|off], e.g. json on: answer in JSON (docs/OUTPUT.md)\n"
          "usage: why FACT, e.g. why Rotational-Motion (follower (-)): why a motion or freedom holds or was ruled out\n"
          "usage: with Contact A B | Force OBJ DIR ORIGIN [CAUSE] [; ...], e.g. with Force block (+ 0) (0 0) push: the situation with contacts or forces added\n");
    // No prompt on a pipe; help lists every command, kinematic and with among them.
    CHECK(r.out.find("qm-atms[") == std::string::npos);
    CHECK(r.out.find("  kinematic ") != std::string::npos);
    CHECK(r.out.find("  with Contact A B | Force OBJ DIR ORIGIN [CAUSE] [; ...]") != std::string::npos);
}

TEST_CASE("cli/session: a misspelt name gets 'did you mean'") {
    auto r = session(scene("gears.def"), "why Rotational-Motion (folower (-))\nwhy Rotational-Moton (follower (-))\nwhatif Contact l-1 d-l\n");
    CHECK(r.status == 0);
    CHECK(r.err.find("object 'folower' in the fact is not declared in Individuals; did you mean 'follower'?") != std::string::npos);
    CHECK(r.err.find("unknown predicate 'Rotational-Moton': expected Translational-Motion, Rotational-Motion, "
                     "Translational-Freedom, Rotational-Freedom, Contact or Force; did you mean 'Rotational-Motion'?") !=
          std::string::npos);
    CHECK(r.err.find("unknown surface 'd-l'; did you mean 'd-1'?") != std::string::npos);
}

TEST_CASE("cli/session: with adds, kinematic lists, and each says which set it shows") {
    auto r = session(scene("block.def"), "situation 2\nmotions\nkinematic\nwith Force block (+ 0) (0 0) push\n");
    CHECK(r.status == 0);
    CHECK(r.err == "");
    CHECK(r.out.find("Motions: 1 consistent combination selected by the forces, of ") != std::string::npos);
    CHECK(r.out.find("kinematically consistent combinations (blocking, pushing and given motions alone") != std::string::npos);
    CHECK(r.out.find("Note: what-if: analysed with Force (block (+ 0) (0 0) push) (with)") != std::string::npos);
    CHECK(r.out.find("analysed afresh") != std::string::npos);
}

TEST_CASE("cli/session: on a terminal: prompt, history with the Up arrow, a newline at Ctrl-D") {
    Terminal t({scene("gears.def"), "-i"});
    CHECK(t.read_until("qm-atms[1]> ").find("Type help.") != std::string::npos);
    t.type("motions\r");
    const std::string first = t.read_until("qm-atms[1]> ");
    CHECK(first.find("Motions: 6 consistent combinations") != std::string::npos);
    t.type("\x1b[A\r");  // Up: the previous line, run again
    const std::string again = t.read_until("qm-atms[1]> ");
    CHECK(again.find("Motions: 6 consistent combinations") != std::string::npos);
    CHECK(again.find("unknown command") == std::string::npos);
    CHECK(t.end_input() == 0);  // Ctrl-D on an empty line: the end of the input
    CHECK(t.keep_.find('\n') != std::string::npos);
}

// `with` answers from the labels already computed when what it adds is a contact of
// another situation; the answer must be the one a fresh analysis gives (--with on the command line
// analyses the larger scene afresh), in every part of the situation's JSON.
TEST_CASE("cli/session: with, from the labels already computed, answers as a fresh analysis does") {
    const std::vector<std::string> contacts = {"Contact tb block-b-l", "Contact tb block-b-m", "Contact tb block-b-r"};
    for (std::size_t mask = 1; mask < 8; ++mask) {
        std::string with, options;
        for (std::size_t k = 0; k < 3; ++k)
            if (mask & (1u << k)) {
                with += (with.empty() ? "" : "; ") + contacts[k];
                options += " --with '" + contacts[k] + "'";
            }
        CAPTURE(with);
        auto reused = session(scene("block.def"), "situation 1\njson on\nwith " + with + "\n");
        CHECK(reused.status == 0);
        CHECK(reused.err.find("labels were reused") != std::string::npos);  // JSON notes go to standard error
        const auto at = reused.out.find("{\"index\": 1");
        REQUIRE(at != std::string::npos);
        const std::string answer = reused.out.substr(at, reused.out.find('\n', at) - at);
        auto fresh = qm::test::qm_atms(scene("block.def") + " --json --situation 1" + options, "session");
        REQUIRE(fresh.status == 0);
        const auto from = fresh.out.find("\"situations\": [") + 15;
        CHECK(answer == fresh.out.substr(from, fresh.out.rfind("]}") - from));
    }
}

TEST_CASE("cli/session: --situation N starts the session at situation N") {
    const auto started = session(scene("block.def") + " --situation 2", "motions\nfreedom\n");
    const auto moved = session(scene("block.def"), "situation 2\nmotions\nfreedom\n");
    REQUIRE(started.status == 0);
    CHECK(started.err.empty());
    CHECK(!started.out.empty());
    CHECK(started.out == moved.out);
    CHECK(started.out != session(scene("block.def"), "motions\nfreedom\n").out);  // situation 1 differs
}
