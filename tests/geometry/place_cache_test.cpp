// tests/geometry/place_cache_test.cpp: vocabularies round-trip exactly through the disk cache,
// any change of geometry or setting changes the key, and under faults the cache
// never serves a wrong vocabulary and says what it did: truncated, corrupted, edited (a flipped
// normal, a changed adjacency target), stale and foreign files, a folder it cannot write, and
// processes filling one cache at once.
#include "geometry/closed_form_pairs.hpp"
#include "geometry/place_cache.hpp"

#include <doctest/doctest.h>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace qm::geometry;

namespace {
std::filesystem::path fresh_dir(const char* name) {
    auto d = std::filesystem::path(QM_BINARY_DIR) / "test-place-cache" / name;
    std::filesystem::remove_all(d);
    return d;
}
bool same(const PlaceVocabulary& a, const PlaceVocabulary& b) {
    if (a.places.size() != b.places.size() || a.adjacency != b.adjacency) return false;
    for (std::size_t i = 0; i < a.places.size(); ++i) {
        const auto &p = a.places[i], &q = b.places[i];
        if (p.id != q.id || p.kind != q.kind || p.normals != q.normals || p.concave != q.concave || p.axis != q.axis ||
            p.label != q.label || p.points != q.points || p.extent != q.extent || (p.kind == PlaceKind::join && p.join_kind != q.join_kind))
            return false;
    }
    return true;
}

std::string slurp_cache(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void spit(const std::filesystem::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// The pin in the slot on a small grid: quick, and every kind of place.
struct Fixture {
    ClosedFormPair c = pin_in_slot();
    PlaceRequest req;
    std::string material;
    PlaceVocabulary vocabulary;
    Fixture() {
        req.cspace.axes = c.axes;
        req.cspace.axes[0].samples = req.cspace.axes[1].samples = 24;
        material = place_cache_material(c.exact, req);
        vocabulary = build_place_vocabulary(c.exact, req).vocabulary;
    }
};

// The file with its checksum line made to match again (a deliberate, consistent edit).
std::string resealed(const std::string& text) {
    const std::size_t last = text.rfind('\n', text.size() - 2);
    const std::string body = text.substr(0, last + 1);
    return body + "checksum " + place_cache_checksum(body) + "\n";
}
}  // namespace

TEST_CASE("geometry/place_cache: a stored vocabulary loads back identical and is reused") {
    const auto c = disk_cam_and_follower();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    req.external.push_back({0, 0.5, "label with spaces\nand a newline"});
    const PlaceCache cache(fresh_dir("roundtrip"));
    const auto first = build_or_load(c.exact, req, cache);
    CHECK(!first.from_cache);
    const auto second = build_or_load(c.exact, req, cache);
    CHECK(second.from_cache);
    CHECK(same(first.vocabulary, second.vocabulary));
    CHECK(same(second.vocabulary, build_place_vocabulary(c.exact, req).vocabulary));
}

TEST_CASE("geometry/place_cache: the key covers geometry and every setting") {
    const auto c = two_disks();
    PlaceRequest req;
    req.cspace.axes = c.axes;
    const auto base = place_cache_material(c.exact, req);
    auto changed = [&](auto edit) {
        auto r = req;
        edit(r);
        return place_cache_key(place_cache_material(c.exact, r)) != place_cache_key(base);
    };
    CHECK(changed([](PlaceRequest& r) { r.cspace.boundary_tolerance *= 0.5; }));
    CHECK(changed([](PlaceRequest& r) { r.cspace.axes[1].samples += 1; }));
    CHECK(changed([](PlaceRequest& r) { r.cspace.axes[0].hi = std::nextafter(r.cspace.axes[0].hi, 10.0); }));
    CHECK(changed([](PlaceRequest& r) { r.merge_epsilon = 1e-3; }));
    CHECK(changed([](PlaceRequest& r) { r.cspace.axes[1].stops = !r.cspace.axes[1].stops; }));
    CHECK(changed([](PlaceRequest& r) { r.external.push_back({1, 0.0, "g"}); }));
    CHECK(place_cache_key(place_cache_material(c.tessellated(1e-3), req)) != place_cache_key(place_cache_material(c.tessellated(2e-3), req)));
    CHECK(place_cache_key(base).size() == 16);
    // The material is the oracle's fingerprint and the request: the fingerprint alone gives it.
    CHECK(place_cache_material(c.exact.fingerprint(), req) == base);
}

TEST_CASE("geometry/place_cache: a truncated file is never served, at any length") {
    const Fixture f;
    const PlaceCache cache(fresh_dir("truncated"));
    REQUIRE(cache.store(f.material, f.vocabulary));
    const auto path = cache.path_for(f.material);
    const std::string whole = slurp_cache(path);
    REQUIRE(cache.load(f.material).status == CacheStatus::hit);
    for (std::size_t n = 0; n < whole.size(); n += 1 + n / 40) {
        spit(path, whole.substr(0, n));
        const auto l = cache.load(f.material);
        INFO("length " << n << " of " << whole.size());
        CHECK(l.status == CacheStatus::corrupt);
        CHECK(!l.why.empty());
    }
}

TEST_CASE("geometry/place_cache: a corrupted byte anywhere is never served") {
    const Fixture f;
    const PlaceCache cache(fresh_dir("corrupted"));
    REQUIRE(cache.store(f.material, f.vocabulary));
    const auto path = cache.path_for(f.material);
    const std::string whole = slurp_cache(path);
    for (std::size_t i = 0; i < whole.size(); i += 1 + i / 10) {
        for (char replacement : {'\0', '7', static_cast<char>(whole[i] ^ 0x20)}) {
            if (replacement == whole[i]) continue;
            std::string bad = whole;
            bad[i] = replacement;
            spit(path, bad);
            INFO("byte " << i << " of " << whole.size());
            CHECK(cache.load(f.material).status != CacheStatus::hit);
        }
    }
    spit(path, std::string(whole.size(), '\0'));
    CHECK(cache.load(f.material).status == CacheStatus::corrupt);
}

TEST_CASE("geometry/place_cache: a well-formed edit (a flipped normal, a changed adjacency target) is refused and recomputed") {
    const Fixture f;
    const PlaceCache cache(fresh_dir("edited"));
    REQUIRE(cache.store(f.material, f.vocabulary));
    const auto path = cache.path_for(f.material);
    const std::string whole = slurp_cache(path);
    // After the magic line and the key (its length, a space, the text), the body's lines: "np na",
    // then a line per place, then one per adjacency.
    const std::size_t key_at = whole.find('\n') + 1, space = whole.find(' ', key_at);
    const std::size_t body_at = space + 1 + std::stoul(whole.substr(key_at, space - key_at)) + 1;
    std::vector<std::string> lines;
    std::istringstream in(whole.substr(body_at));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    const std::size_t first_place = 1, first_adjacency = first_place + f.vocabulary.places.size();
    std::size_t cseg = 0;
    while (f.vocabulary.places[cseg].kind != PlaceKind::cseg) ++cseg;
    auto edited = [&](std::size_t line, std::string text) {
        std::string out = whole.substr(0, body_at);
        for (std::size_t k = 0; k < lines.size(); ++k) out += (k == line ? text : lines[k]) + "\n";
        return out;
    };
    // A CSEG's line: kind join-kind axis concave extent gap #normals s0 s1 ...; flip s1.
    std::istringstream cs(lines[first_place + cseg]);
    std::vector<std::string> tok;
    for (std::string t; cs >> t;) tok.push_back(t);
    REQUIRE(tok[6] == "1");
    tok[8] = tok[8] == "1" ? "-1" : "1";
    std::string flipped;
    for (const auto& t : tok) flipped += t + " ";  // a CSEG's label is empty: the line ends "0 "
    // An adjacency: from to s0 s1 inst constrained; point it elsewhere.
    std::istringstream as(lines[first_adjacency]);
    std::uint32_t from = 0, to = 0;
    std::string rest;
    as >> from >> to;
    std::getline(as, rest);
    const std::string retargeted = std::to_string(from) + " " + std::to_string((to + 1) % f.vocabulary.places.size()) + rest;
    for (const std::string& bad : {edited(first_place + cseg, flipped), edited(first_adjacency, retargeted)}) {
        REQUIRE(bad != whole);
        spit(path, bad);
        const auto l = cache.load(f.material);
        CHECK(l.status == CacheStatus::corrupt);
        CHECK(l.why.find("checksum does not match") != std::string::npos);
        const auto again = build_or_load(f.c.exact, f.req, cache);
        CHECK(!again.from_cache);
        CHECK(same(again.vocabulary, f.vocabulary));
        CHECK(again.stored);
        CHECK(again.note.find("was not used: its checksum does not match its content") != std::string::npos);
        CHECK(again.note.find("the file replaced") != std::string::npos);
        CHECK(build_or_load(f.c.exact, f.req, cache).from_cache);
        // The same edit with the checksum made consistent is well formed: it parses (the
        // checksum is the only defence against an edit, and it is verified before anything).
        spit(path, resealed(bad));
        CHECK(cache.load(f.material).status == CacheStatus::hit);
    }
}

TEST_CASE("geometry/place_cache: stale, foreign and alien files are not served, and the note says so") {
    const Fixture f;
    const PlaceCache cache(fresh_dir("foreign"));
    const auto path = cache.path_for(f.material);
    CHECK(cache.load(f.material).status == CacheStatus::miss);
    std::filesystem::create_directories(cache.directory());
    // Another version's file.
    spit(path, "qm-place-cache/6\n5 other\n0 0\n");
    auto l = cache.load(f.material);
    CHECK(l.status == CacheStatus::stale);
    CHECK(l.why == "it was written in format qm-place-cache/6, not qm-place-cache/18");
    // A whole, sound file of another computation under this name (a hash collision, a copy).
    const auto other = bar_and_block();
    PlaceRequest other_req;
    other_req.cspace.axes = other.axes;
    const std::string other_material = place_cache_material(other.exact, other_req);
    REQUIRE(cache.store(other_material, build_place_vocabulary(other.exact, other_req).vocabulary));
    std::filesystem::copy_file(cache.path_for(other_material), path, std::filesystem::copy_options::overwrite_existing);
    l = cache.load(f.material);
    CHECK(l.status == CacheStatus::foreign);
    const auto replaced = build_or_load(f.c.exact, f.req, cache);
    CHECK(!replaced.from_cache);
    CHECK(replaced.cache_status == CacheStatus::foreign);
    CHECK(replaced.note.find("it holds the vocabulary of another computation with the same key") != std::string::npos);
    CHECK(build_or_load(f.c.exact, f.req, cache).from_cache);
    // Not a cache file at all.
    spit(path, "<html>not a vocabulary</html>\n");
    l = cache.load(f.material);
    CHECK(l.status == CacheStatus::corrupt);
    CHECK(l.why == "it is not a place cache file");
}

// Format /6 meant stops without a checksum on one branch and a checksum without stops on the
// other; a whole file of either kind is stale under /7: refused, recomputed, replaced.
TEST_CASE("geometry/place_cache: files of both format /6s are refused as stale and replaced") {
    const Fixture f;
    const PlaceCache cache(fresh_dir("format6"));
    const auto path = cache.path_for(f.material);
    REQUIRE(cache.store(f.material, f.vocabulary));
    const std::string current = slurp_cache(path);
    REQUIRE(current.rfind("qm-place-cache/18\n", 0) == 0);
    const std::string body = current.substr(current.find('\n') + 1);
    const std::string unsealed = body.substr(0, body.rfind('\n', body.size() - 2) + 1);
    const std::string with_stops = "qm-place-cache/6\n" + unsealed;                 // no checksum line
    const std::string with_checksum = resealed("qm-place-cache/6\n" + body);       // checksum, /6 head
    for (const auto& old : {with_stops, with_checksum}) {
        spit(path, old);
        const auto l = cache.load(f.material);
        CHECK(l.status == CacheStatus::stale);
        CHECK(l.why == "it was written in format qm-place-cache/6, not qm-place-cache/18");
        const auto rebuilt = build_or_load(f.c.exact, f.req, cache);
        CHECK(!rebuilt.from_cache);
        CHECK(rebuilt.cache_status == CacheStatus::stale);
        CHECK(rebuilt.note.find("format qm-place-cache/6") != std::string::npos);
        CHECK(same(rebuilt.vocabulary, f.vocabulary));
        CHECK(slurp_cache(path) == current);
        const auto again = build_or_load(f.c.exact, f.req, cache);
        CHECK(again.from_cache);
        CHECK(same(again.vocabulary, f.vocabulary));
    }
}

TEST_CASE("geometry/place_cache: a folder that cannot be written: computed, not stored, and said") {
    const Fixture f;
    // A folder below a plain file cannot be created, whoever runs the test.
    const auto base = fresh_dir("unwritable");
    std::filesystem::create_directories(base);
    spit(base / "file", "x");
    const PlaceCache blocked(base / "file" / "cache");
    const auto r = build_or_load(f.c.exact, f.req, blocked);
    CHECK(r.status == PlaceStatus::ok);
    CHECK(same(r.vocabulary, f.vocabulary));
    CHECK(!r.from_cache);
    CHECK(!r.stored);
    CHECK(r.note.find("the vocabulary was computed but not stored in the place cache: cannot create the folder") == 0);
    // A folder without write permission (meaningless for root, who may write anyway).
    if (::geteuid() != 0) {
        const auto ro = base / "read-only";
        std::filesystem::create_directories(ro);
        ::chmod(ro.c_str(), 0555);
        const auto r2 = build_or_load(f.c.exact, f.req, PlaceCache(ro));
        CHECK(!r2.stored);
        CHECK(r2.note.find("cannot write in") != std::string::npos);
        ::chmod(ro.c_str(), 0755);
    }
}

TEST_CASE("geometry/place_cache: processes filling one cache at once leave one whole file, and never read half of one") {
    const Fixture f;
    const PlaceCache cache(fresh_dir("concurrent"));
    REQUIRE(cache.store(f.material, f.vocabulary));  // the folder exists before the race starts
    std::vector<pid_t> children;
    for (int k = 0; k < 4; ++k) {
        const pid_t pid = ::fork();
        if (pid == 0) {
            int bad = 0;
            for (int round = 0; round < 60; ++round) {
                if (k == 0 && round % 10 == 0) std::filesystem::remove(cache.path_for(f.material));  // a reader then misses
                const auto l = cache.load(f.material);
                // Each failure says why on standard error, for the log of a run that failed.
                const auto fail = [&](const std::string& what) {
                    ++bad;
                    std::fprintf(stderr, "process %d, round %d: %s\n", k, round, what.c_str());
                };
                if (l.status != CacheStatus::hit && l.status != CacheStatus::miss) fail("load refused the file: " + l.why);
                if (l.status == CacheStatus::hit && !same(l.vocabulary, f.vocabulary)) fail("load read another vocabulary");
                if (const auto stored = cache.store(f.material, f.vocabulary); !stored) fail("store failed: " + stored.why);
            }
            ::_exit(bad == 0 ? 0 : 1);
        }
        children.push_back(pid);
    }
    for (const pid_t pid : children) {
        int raw = 0;
        ::waitpid(pid, &raw, 0);
        CHECK(WIFEXITED(raw));
        CHECK(WEXITSTATUS(raw) == 0);
    }
    const auto l = cache.load(f.material);
    REQUIRE(l.status == CacheStatus::hit);
    CHECK(same(l.vocabulary, f.vocabulary));
    int files = 0;
    for (const auto& e : std::filesystem::directory_iterator(cache.directory())) files += e.path().extension() == ".places" ? 1 : 100;
    CHECK(files == 1);  // no private files left behind
}
