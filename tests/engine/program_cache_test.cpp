// tests/engine/program_cache_test.cpp: the compiled-rules cache (engine/program_cache.hpp) on the
// bundled laws: the on-disk form reads back to the same program; a damaged, truncated, foreign or
// other-key entry is refused; a load through the cache stores, then serves what it stored; an edited
// rule file misses; a corrupt entry or a folder that cannot be written changes nothing; threads
// loading through one folder at once all get the cold load's program.
#include "engine/program_cache.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;
using namespace qm;
using namespace qm::engine;

namespace {

// A scratch copy of the bundled laws, and a cache folder beside it.
struct Scratch {
    fs::path root, rules, cache;
    std::vector<std::string> files;
    explicit Scratch(const std::string& tag) {
        root = fs::path(QM_BINARY_DIR) / ("program_cache_test_" + tag);
        fs::remove_all(root);
        rules = root / "rules";
        cache = root / "cache";
        fs::create_directories(rules);
        for (const auto& e : fs::directory_iterator(fs::path(QM_SOURCE_DIR) / "rules"))
            if (e.path().extension() == ".rules") fs::copy_file(e.path(), rules / e.path().filename());
        for (const auto& e : fs::directory_iterator(rules)) files.push_back(e.path().string());
        std::sort(files.begin(), files.end());
    }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(root, ec);
    }
    [[nodiscard]] std::vector<fs::path> entries() const {
        std::vector<fs::path> out;
        std::error_code ec;
        for (fs::directory_iterator it(cache, ec), end; !ec && it != end; it.increment(ec))
            if (it->path().extension() == ".qmrules") out.push_back(it->path());
        return out;
    }
};

LawCheckOptions laws_2d() {
    LawCheckOptions o;
    o.require_citations = true;
    o.direction_arities = {2, 1};
    o.arity_context = "scene 'test' is 2-D";
    return o;
}

// The program's whole encoded form under one key: equal forms, equal programs.
std::string form(const LoadedProgram& p) { return encode_program("k", {}, p); }

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void spit(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes; }

}  // namespace

TEST_CASE("the encoded laws decode to the same program, and a damaged entry is refused") {
    Scratch s("roundtrip");
    Diagnostics d;
    const auto cold = load_programs(s.files, d, laws_2d());
    REQUIRE(cold);
    REQUIRE(d.items().empty());
    const std::vector<CachedSource> sources{{"a.rules", "text of a"}};
    const std::string bytes = encode_program("key", sources, *cold);
    auto back = decode_program(bytes, "key");
    REQUIRE(back);
    CHECK(form(back->program) == form(*cold));
    CHECK(back->program.citations == cold->citations);
    REQUIRE(back->program.values.size() == cold->values.size());
    for (std::uint32_t i = 0; i < cold->values.size(); ++i) CHECK(back->program.values.print(ValueId{i}) == cold->values.print(ValueId{i}));
    REQUIRE(back->sources.size() == 1);
    CHECK(back->sources[0].file == "a.rules");
    CHECK(back->sources[0].text == "text of a");

    CHECK_FALSE(decode_program(bytes, "another key"));
    CHECK_FALSE(decode_program("", "key"));
    CHECK_FALSE(decode_program("# a rule file, not an entry\n", "key"));
    CHECK_FALSE(decode_program(std::string(bytes.size(), '\0'), "key"));
    // Every truncation, and a byte changed at many places (header and payload).
    for (std::size_t n = 0; n < bytes.size(); n += 1 + n / 3) CHECK_FALSE(decode_program(std::string_view(bytes).substr(0, n), "key"));
    CHECK_FALSE(decode_program(bytes + "x", "key"));
    std::size_t refused = 0, tried = 0;
    for (std::size_t at = 0; at < bytes.size(); at += 1 + at / 50, ++tried) {
        std::string damaged = bytes;
        damaged[at] = static_cast<char>(damaged[at] ^ 0x5a);
        refused += decode_program(damaged, "key") ? 0 : 1;
    }
    CHECK(refused == tried);
}

// An entry can be intact (its checksum matches) and still not describe a program this engine can run:
// indices past what they index, a builtin given more or fewer arguments than it takes. Such an
// entry is refused, not run (builtins and preferences index their arguments unchecked).
TEST_CASE("a sealed entry whose indices or arities are out of range is refused") {
    Scratch s("ranges");
    Diagnostics d;
    const auto cold = load_programs(s.files, d, laws_2d());
    REQUIRE(cold);
    REQUIRE(!cold->program.preferences.empty());
    const auto sealed = [&](const LoadedProgram& p) { return decode_program(encode_program("key", {}, p), "key").has_value(); };
    CHECK(sealed(*cold));

    LoadedProgram key_past = *cold;
    auto& pref = key_past.program.preferences.front();
    REQUIRE(!pref.key.empty());
    pref.key.front() = static_cast<std::uint32_t>(pref.key.size() + 1);  // the rank atom has key.size() + 1 arguments
    CHECK_FALSE(sealed(key_past));

    LoadedProgram rank_past = *cold;
    rank_past.program.preferences.front().rank_at = 1000;
    CHECK_FALSE(sealed(rank_past));

    // A builtin test with its arguments taken away.
    LoadedProgram no_args = *cold;
    bool found = false;
    for (CompiledRule& r : no_args.program.rules)
        for (CompiledCondition& c : r.conditions)
            if (!found && c.kind == CompiledCondition::Kind::test && default_builtins().get(c.test.test).min_arity > 0) {
                c.test.args.clear();
                found = true;
            }
    REQUIRE(found);
    CHECK_FALSE(sealed(no_args));
}

TEST_CASE("a load through the cache stores, serves what it stored, and misses once a rule file changes") {
    Scratch s("hit");
    Diagnostics d0;
    const auto cold = load_programs(s.files, d0, laws_2d());
    REQUIRE(cold);

    Diagnostics d1;
    const auto first = load_programs_cached(s.files, d1, laws_2d(), s.cache);
    REQUIRE(first);
    CHECK(d1.items().empty());
    CHECK(form(*first) == form(*cold));
    const auto entries = s.entries();
    REQUIRE(entries.size() == 1);

    Diagnostics d2;
    const auto second = load_programs_cached(s.files, d2, laws_2d(), s.cache);
    REQUIRE(second);
    CHECK(d2.items().empty());
    CHECK(form(*second) == form(*cold));

    // The scene's name (only in messages) does not matter; the dimensions do.
    LawCheckOptions renamed = laws_2d();
    renamed.arity_context = "scene 'other' is 2-D";
    Diagnostics d3;
    REQUIRE(load_programs_cached(s.files, d3, renamed, s.cache));
    CHECK(s.entries().size() == 1);
    LawCheckOptions space = laws_2d();
    space.direction_arities = {3, 3};
    Diagnostics d4;
    REQUIRE(load_programs_cached(s.files, d4, space, s.cache));
    CHECK(s.entries().size() == 2);
    fs::remove(s.entries()[0] == entries[0] ? s.entries()[1] : s.entries()[0]);

    // A hit serves the entry: an entry whose program was altered (and sealed again) is what comes back.
    const std::string bytes = slurp(entries[0]);
    CHECK_FALSE(decode_program(bytes, "not the key"));
    // Read the key as the entry holds it (after the 28-byte header: a length, then the bytes).
    std::uint32_t key_length = 0;
    std::memcpy(&key_length, bytes.data() + 28, 4);
    const std::string key = bytes.substr(32, key_length);
    auto stored = decode_program(bytes, key);
    REQUIRE(stored);
    REQUIRE(!stored->program.program.rules.empty());
    stored->program.program.rules[RuleId{0}].name = "altered-by-the-test";
    spit(entries[0], encode_program(key, stored->sources, stored->program));
    Diagnostics d5;
    const auto altered = load_programs_cached(s.files, d5, laws_2d(), s.cache);
    REQUIRE(altered);
    CHECK(altered->program.rules[RuleId{0}].name == "altered-by-the-test");

    // An edited rule file misses: the load reads the files again and stores anew.
    { std::ofstream(s.files.back(), std::ios::app) << "\n# edited\n"; }
    Diagnostics d6;
    const auto edited = load_programs_cached(s.files, d6, laws_2d(), s.cache);
    REQUIRE(edited);
    CHECK(edited->program.rules[RuleId{0}].name == cold->program.rules[RuleId{0}].name);
    Diagnostics d7;
    const auto cold_edited = load_programs(s.files, d7, laws_2d());
    REQUIRE(cold_edited);
    CHECK(form(*edited) == form(*cold_edited));
}

TEST_CASE("a corrupt entry or a folder that cannot be written changes nothing") {
    Scratch s("corrupt");
    Diagnostics d0;
    const auto cold = load_programs(s.files, d0, laws_2d());
    REQUIRE(cold);
    Diagnostics d1;
    REQUIRE(load_programs_cached(s.files, d1, laws_2d(), s.cache));
    const auto entries = s.entries();
    REQUIRE(entries.size() == 1);
    std::string bytes = slurp(entries[0]);
    for (const std::string& bad : {bytes.substr(0, bytes.size() / 2), std::string("garbage"), std::string(),
                                   bytes.substr(0, bytes.size() - 1) + static_cast<char>(bytes.back() ^ 1)}) {
        spit(entries[0], bad);
        Diagnostics d;
        const auto p = load_programs_cached(s.files, d, laws_2d(), s.cache);
        REQUIRE(p);
        CHECK(d.items().empty());
        CHECK(form(*p) == form(*cold));
        CHECK(slurp(entries[0]) == bytes);  // stored again, whole
    }
    // A cache folder below a regular file cannot be made: the load goes on without it.
    spit(s.root / "a-file", "x");
    Diagnostics d2;
    const auto p = load_programs_cached(s.files, d2, laws_2d(), s.root / "a-file" / "cache");
    REQUIRE(p);
    CHECK(d2.items().empty());
    CHECK(form(*p) == form(*cold));
}

TEST_CASE("a load with diagnostics is not stored, and gives its diagnostics every time") {
    Scratch s("warned");
    { std::ofstream(s.rules / "zz_bad.rules") << "rule broken:\n  if (p ?x\n  then (q ?x)\n"; }
    s.files.push_back((s.rules / "zz_bad.rules").string());
    for (int i = 0; i < 2; ++i) {
        Diagnostics d;
        CHECK_FALSE(load_programs_cached(s.files, d, laws_2d(), s.cache));
        CHECK(d.has_errors());
    }
    CHECK(s.entries().empty());
}

TEST_CASE("threads loading through one cache folder at once all get the cold load's program") {
    Scratch s("concurrent");
    Diagnostics d0;
    const auto cold = load_programs(s.files, d0, laws_2d());
    REQUIRE(cold);
    const std::string expected = form(*cold);
    std::vector<std::string> got(6);
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < got.size(); ++t)
        threads.emplace_back([&, t] {
            for (int round = 0; round < 3; ++round) {
                Diagnostics d;
                const auto p = load_programs_cached(s.files, d, laws_2d(), s.cache);
                got[t] += p && d.items().empty() && form(*p) == expected ? "y" : "n";
            }
        });
    for (auto& th : threads) th.join();
    for (const std::string& g : got) CHECK(g == "yyy");
    CHECK(s.entries().size() == 1);
}
