// tests/cli/rule_cache_test.cpp: the compiled laws kept between runs (engine/program_cache.hpp,
// cli/rules_location.hpp) through the built qm-atms: every bundled Alex scene prints the same with
// the cache off, storing and hit; an edited law file is read again; a corrupt entry, a cache folder
// that cannot be made and a home that cannot be written change nothing; processes started together
// on one empty cache all print what a cold run prints.
#include "qm_atms_run.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace fs = std::filesystem;
using qm::test::Run;

namespace {

const std::string exe = std::string(QM_BINARY_DIR) + "/cli/qm-atms";

// qm-atms with the cache at `cache` ("off": none), through the shell.
Run with_cache(const std::string& cache, const std::string& args) {
    return qm::test::run_executable("QM_RULE_CACHE=" + cache + " " + exe, args, "rule_cache_cli");
}

std::vector<std::string> alex_scenes() {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(fs::path(QM_SOURCE_DIR) / "scenarios" / "alex"))
        if (e.path().extension() == ".def") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<fs::path> entries(const fs::path& dir) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".qmrules") out.push_back(it->path());
    std::sort(out.begin(), out.end());
    return out;
}

void same(const Run& a, const Run& b) {
    CHECK(a.status == b.status);
    CHECK(a.out == b.out);
    CHECK(a.err == b.err);
}

fs::path fresh(const std::string& tag) {
    const fs::path p = fs::path(QM_BINARY_DIR) / ("rule_cache_cli_" + tag);
    fs::remove_all(p);
    return p;
}

}  // namespace

TEST_CASE("every bundled Alex scene prints the same with the cache off, storing, and hit") {
    const fs::path cache = fresh("scenes");
    const auto scenes = alex_scenes();
    REQUIRE(scenes.size() >= 10);
    for (const std::string& s : scenes) {
        CAPTURE(s);
        const Run cold = with_cache("off", s);
        CHECK(cold.status == 0);
        same(with_cache(cache.string(), s), cold);  // stores (or hits the entry of an earlier scene)
        same(with_cache(cache.string(), s), cold);  // hits
        same(with_cache(cache.string(), s + " --json"), with_cache("off", s + " --json"));
    }
    // One entry per set of direction arities (2-D and 3-D scenes), whatever the scene's name.
    const auto stored = entries(cache);
    CHECK(stored.size() >= 1);
    CHECK(stored.size() <= 2);
    // A hit reads the entry and writes nothing: every entry is still the same file (an entry is
    // only ever replaced by renaming a new file onto it, which would give it another inode).
    std::vector<ino_t> before;
    for (const fs::path& e : stored) {
        struct stat st {};
        REQUIRE(::stat(e.c_str(), &st) == 0);
        before.push_back(st.st_ino);
    }
    for (const std::string& s : scenes) same(with_cache(cache.string(), s), with_cache("off", s));
    const auto after = entries(cache);
    REQUIRE(after.size() == stored.size());
    for (std::size_t i = 0; i < after.size(); ++i) {
        struct stat st {};
        REQUIRE(::stat(after[i].c_str(), &st) == 0);
        CHECK(after[i] == stored[i]);
        CHECK(st.st_ino == before[i]);
    }
    fs::remove_all(cache);
}

TEST_CASE("an edited law file is read again, and a corrupt entry changes nothing") {
    const fs::path root = fresh("edit");
    const fs::path rules = root / "rules", cache = root / "cache";
    fs::create_directories(rules);
    for (const auto& e : fs::directory_iterator(fs::path(QM_SOURCE_DIR) / "rules"))
        if (e.path().extension() == ".rules") fs::copy_file(e.path(), rules / e.path().filename());
    const std::string args = std::string(QM_SOURCE_DIR) + "/scenarios/alex/block.def --rules " + rules.string();
    const Run cold = with_cache("off", args);
    REQUIRE(cold.status == 0);
    same(with_cache(cache.string(), args), cold);
    REQUIRE(entries(cache).size() == 1);

    // Every entry replaced by garbage, then cut short: still the cold output.
    for (const std::string bad : {"garbage", ""}) {
        for (const fs::path& e : entries(cache)) std::ofstream(e, std::ios::binary | std::ios::trunc) << bad;
        same(with_cache(cache.string(), args), cold);
    }

    // A law file broken after the entry was stored: the run must see the break, not the entry.
    { std::ofstream(rules / "contact.rules", std::ios::app) << "\nrule broken-on-purpose:\n  if (p ?x\n"; }
    const Run broken = with_cache(cache.string(), args);
    CHECK(broken.status == 2);
    CHECK(broken.err.find("contact.rules") != std::string::npos);
    same(broken, with_cache("off", args));
    fs::remove_all(root);
}

TEST_CASE("a cache folder that cannot be made, or a home that cannot be written, changes nothing") {
    const std::string block = std::string(QM_SOURCE_DIR) + "/scenarios/alex/block.def";
    const Run cold = with_cache("off", block);
    REQUIRE(cold.status == 0);
    // Nothing can be created below /proc, not even by root.
    same(with_cache("/proc/self/no-such-folder/cache", block), cold);
    same(qm::test::run_executable("env -u QM_RULE_CACHE -u XDG_CACHE_HOME HOME=/proc/self/no-such-home " + exe, block,
                                  "rule_cache_cli"),
         cold);
    same(qm::test::run_executable("env -u QM_RULE_CACHE -u XDG_CACHE_HOME -u HOME " + exe, block, "rule_cache_cli"), cold);
}

TEST_CASE("processes started together on one empty cache all print what a cold run prints") {
    const fs::path root = fresh("concurrent");
    fs::create_directories(root);
    const std::string block = std::string(QM_SOURCE_DIR) + "/scenarios/alex/block.def";
    const Run cold = with_cache("off", block);
    REQUIRE(cold.status == 0);
    constexpr int processes = 8;
    std::string script;
    for (int i = 0; i < processes; ++i)
        script += "QM_RULE_CACHE=" + (root / "cache").string() + " " + exe + " " + block + " >" + (root / std::to_string(i)).string() +
                  ".out 2>&1 & ";
    script += "wait";
    REQUIRE(std::system(script.c_str()) == 0);
    for (int i = 0; i < processes; ++i) CHECK(qm::test::slurp((root / std::to_string(i)).string() + ".out") == cold.out + cold.err);
    CHECK(entries(root / "cache").size() == 1);
    // And the entry they left is whole: a run now hits it and prints the same.
    same(with_cache((root / "cache").string(), block), cold);
    fs::remove_all(root);
}
