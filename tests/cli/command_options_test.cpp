// tests/cli/command_options_test.cpp: cli/command_options.hpp end to end through the built qm-atms:
// every command answers --help with its own usage and --version with the project's version,
// reading no file (the scene named does not exist); a misspelt option or command is named with
// the nearest one; a single-valued option given twice, a flag given a value, and an option that
// would change nothing in the combination given are errors (exit 2, nothing on standard output);
// `--` ends the options, so a file whose name begins with '-' can be named.
#include "qm_atms_run.hpp"
#include <doctest/doctest.h>
#include <string>
#include <utility>
#include <vector>

using qm::test::qm_atms;

namespace {
const std::string src = QM_SOURCE_DIR;
const std::string missing = std::string(QM_BINARY_DIR) + "/options_test_no_such.def";
}  // namespace

TEST_CASE("cli/command_options: --help prints the command's own usage, reads no file, exit 0") {
    const std::vector<std::pair<std::string, std::string>> commands = {
        {missing, "usage: qm-atms SCENE.def"},
        {"run " + missing, "usage: qm-atms run PROGRAM.rules"},
        {"check " + missing, "usage: qm-atms check"},
        {"envision " + missing, "usage: qm-atms envision METRIC-SCENE"},
        {"draw " + missing, "usage: qm-atms draw METRIC-SCENE"},
        {"explore " + missing, "usage: qm-atms explore METRIC-SCENE"},
        {"--places " + missing, "usage: qm-atms --emit-def METRIC-SCENE"},
        {"--emit-def " + missing, "usage: qm-atms --emit-def METRIC-SCENE"},
    };
    for (const auto& [command, usage] : commands)
        for (const char* help : {" --help", " -h"}) {
            CAPTURE(command + help);
            const auto r = qm_atms(command + help, "options");
            CHECK(r.status == 0);
            CHECK(r.err.empty());
            CHECK(r.out.rfind(usage, 0) == 0);
        }
    // Before the command's arguments too, and whatever else is wrong with them.
    CHECK(qm_atms("envision --help", "options").out.rfind("usage: qm-atms envision", 0) == 0);
    CHECK(qm_atms("draw " + missing + " --frobnicate --help", "options").status == 0);
    // The top-level --help lists every command, and how to ask one for its own.
    const auto all = qm_atms("--help", "options");
    CHECK(all.status == 0);
    CHECK(all.out.find("COMMAND --help") != std::string::npos);
    CHECK(all.out.find("qm-atms run PROGRAM.rules") != std::string::npos);
}

TEST_CASE("cli/command_options: --version prints the project's version, at the top and per command") {
    for (const std::string command : {"", "run ", "check ", "envision ", "draw ", "explore ", "--places ", "--emit-def ", "scene.def "}) {
        CAPTURE(command);
        const auto r = qm_atms(command + "--version", "options");
        CHECK(r.status == 0);
        CHECK(r.err.empty());
        CHECK(r.out == "qm-atms " QM_TEST_VERSION "\n");
    }
}

TEST_CASE("cli/command_options: a misspelt option or command is named with the nearest one") {
    const std::string arch = src + "/scenarios/alex/arch.def", cam = src + "/scenarios/metric/cam.def";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {arch + " --jsn", "unknown option '--jsn'; did you mean '--json'?"},
        {arch + " --situaton 1", "unknown option '--situaton'; did you mean '--situation'?"},
        {arch + " --kinematics", "unknown option '--kinematics'; did you mean '--kinematic'?"},
        {arch + " --lmit=3", "unknown option '--lmit=3'; did you mean '--limit'?"},
        {"run x.rules --max-fact 3", "unknown option '--max-fact'; did you mean '--max-facts'?"},
        {"check --dimension 2", "unknown option '--dimension'; did you mean '--dimensions'?"},
        {"envision " + cam + " --tabel", "unknown option '--tabel'; did you mean '--table'?"},
        {"envision " + cam + " --why_not '#0 -> #1'", "unknown option '--why_not'; did you mean '--why-not'?"},
        {"draw " + cam + " --svg x.svg --colums 2", "unknown option '--colums'; did you mean '--columns'?"},
        {"explore " + cam + " -o x --no-envison", "unknown option '--no-envison'; did you mean '--no-envision'?"},
        {"--places " + cam + " --no-cahce", "unknown option '--no-cahce'; did you mean '--no-cache'?"},
        {"--place " + cam, "unknown option '--place'; did you mean '--places'?"},  // a command, when first
        {"--emit-dfe " + cam, "unknown option '--emit-dfe'; did you mean '--emit-def'?"},
        {"envison " + cam, "unknown command 'envison'; did you mean 'envision'?"},
        {"chekc", "unknown command 'chekc'; did you mean 'check'?"},
        {arch + " --frobnicate", "unknown option '--frobnicate'"},  // nothing near: no guess
    };
    for (const auto& [args, message] : cases) {
        CAPTURE(args);
        const auto r = qm_atms(args, "options");
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err.rfind("qm-atms: error: " + message + "\n", 0) == 0);
        CHECK(r.err.find("usage: qm-atms") != std::string::npos);  // what was expected
    }
    // Dashes that name no option are an argument, as CLI11 reads them.
    CHECK(qm_atms(arch + " ---", "options").err.rfind("qm-atms: error: more than one scene given ('" + arch + "', '---')\n", 0) == 0);
    // `--place` is only proposed as the command it is: later in a scene's options it is no guess.
    CHECK(qm_atms(arch + " --place", "options").err.rfind("qm-atms: error: unknown option '--place'\n", 0) == 0);
}

TEST_CASE("cli/command_options: an option given twice, a flag given a value, and options that change nothing are errors") {
    const std::string arch = src + "/scenarios/alex/arch.def", cam = src + "/scenarios/metric/cam.def";
    const std::string why = " --why 'Rotational-Motion (cross-bar (+))'";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"envision " + cam + " --max-states 5 --max-states 6", "--max-states is given twice ('5', '6'): give it once"},
        {"envision " + cam + " --next '#1' --next '#2'", "--next is given twice ('#1', '#2'): ask one at a time"},
        {"envision " + cam + " --rules a --rules b --rules c", "--rules is given 3 times ('a', 'b', 'c'): give it once"},
        {"draw " + cam + " --svg a.svg --svg b.svg", "--svg is given twice ('a.svg', 'b.svg'): give it once"},
        {"explore " + cam + " -o a -o b", "-o is given twice ('a', 'b'): give it once"},
        {"--places " + cam + " --cache a --cache b", "--cache is given twice ('a', 'b'): give it once"},
        {"check --dimensions 2 --dimensions 3", "--dimensions is given twice ('2', '3'): give it once"},
        {arch + " --json=yes", "--json takes no value, but is given 'yes'"},
        {"envision " + cam + " --max-states", "--max-states expects a positive whole number, but nothing follows it"},
        {"check --dimensions 4", "--dimensions expects 2 or 3, not '4'"},
        // Combinations in which an option would change nothing.
        {arch + why + " --full --json", "--full shows a --why answer whole, which --json always does: give --json alone"},
        {arch + why + " --kinematic", "--kinematic lists combinations of motions, which a --why answer does not show"},
        {"envision " + cam + " --next '#1' --json", "--next answers a question in text, and --json shapes only the envisionment printed"},
        {"envision " + cam + " --path 'cam=+' --table", "--path answers a question in text, and --table shapes only"},
        {"envision " + cam + " --why-not '#0 -> #1' --from '#0'", "--why-not answers a question in text, and --from shapes only"},
        {"envision " + cam + " --previous '#1' --dot x.dot", "--previous answers a question in text, and --dot shapes only"},
        {"envision " + cam + " --cache a --no-cache", "--cache DIR and --no-cache contradict each other: give one"},
        {"explore " + cam + " -o x --cache a --no-cache", "--cache DIR and --no-cache contradict each other: give one"},
        {"--places " + cam + " --cache a --no-cache", "--cache DIR and --no-cache contradict each other: give one"},
        {"draw " + cam + " --svg x.svg --config 'cam=3' --no-cache", "--no-cache chooses where the place vocabularies of --place or --history come from"},
        {"draw " + cam + " --svg x.svg --columns 2", "--columns lays out the drawings of a --history: give it with --history"},
    };
    for (const auto& [args, message] : cases) {
        CAPTURE(args);
        const auto r = qm_atms(args, "options");
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err.rfind("qm-atms: error: " + message, 0) == 0);
    }
}

TEST_CASE("cli/command_options: -- ends the options, so a file named like one can be given") {
    const auto r = qm_atms("envision -- --help", "options");
    CHECK(r.status == 2);
    CHECK(r.err.find("cannot read metric scene file '--help'") != std::string::npos);
    // A value is taken as given, even one that looks like an option.
    const auto v = qm_atms("run x.rules --max-environments -5", "options");
    CHECK(v.err.rfind("qm-atms: error: --max-environments expects a positive number, not '-5'\n", 0) == 0);
}

TEST_CASE("cli/command_options: --stats applies to the questions of envision too") {
    const auto r = qm_atms("envision " + src + "/scenarios/clock/ratchet.def --next '#0' --stats", "options");
    CHECK(r.status == 0);
    CHECK(r.err.rfind("places: ", 0) == 0);
    CHECK(r.err.find("chain 1: states ") != std::string::npos);
}
