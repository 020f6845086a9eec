// geometry/place_cache.cpp: a line-based file per vocabulary, doubles in hexfloat so they are exact,
// ending in a checksum of the rest (a well-formed edit is not served either).
#include "geometry/place_cache.hpp"

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>
#include <unistd.h>

namespace qm::geometry {
namespace {

// The format's number changes whenever the builder would give another vocabulary for the same
// geometry and settings, so that a file of an older number is stale and recomputed, never served.
constexpr std::string_view family = "qm-place-cache/";
constexpr const char* magic = "qm-place-cache/18";
constexpr std::uintmax_t largest_file = std::uintmax_t{1} << 30;

void write_text(std::ostream& os, const std::string& s) { os << s.size() << ' ' << s; }

bool read_text(std::istream& is, std::string& s) {
    std::size_t n = 0;
    if (!(is >> n) || is.get() != ' ' || n > (std::size_t{1} << 30)) return false;
    s.resize(n);
    return static_cast<bool>(is.read(s.data(), static_cast<std::streamsize>(n)));
}

bool read_double(std::istream& is, double& x) {
    std::string tok;
    if (!(is >> tok)) return false;
    char* end = nullptr;
    x = std::strtod(tok.c_str(), &end);
    return end != tok.c_str() && *end == '\0';
}

bool read_sign(std::istream& is, std::int8_t& s) {
    int v = 0;
    if (!(is >> v) || v < -1 || v > 1) return false;
    s = static_cast<std::int8_t>(v);
    return true;
}

std::uint64_t fnv1a(std::string_view text) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

std::string hex16(std::uint64_t h) {
    std::ostringstream os;
    os << std::hex << std::setw(16) << std::setfill('0') << h;
    return os.str();
}

void write_body(std::ostream& os, const PlaceVocabulary& v) {
    os << std::hexfloat << v.places.size() << ' ' << v.adjacency.size() << '\n';
    for (const Place& p : v.places) {
        os << static_cast<int>(p.kind) << ' ' << static_cast<int>(p.join_kind) << ' ' << p.axis << ' '
           << (p.concave ? (*p.concave ? 1 : 0) : -1) << ' ' << p.extent << ' ' << p.gap << ' ' << p.normals.size();
        for (auto n : p.normals) os << ' ' << int{n.s[0]} << ' ' << int{n.s[1]};
        os << ' ' << p.points.size();
        for (const auto& x : p.points) os << ' ' << x.x() << ' ' << x.y();
        for (const auto& spans : p.covers) {
            os << ' ' << spans.size();
            for (const auto& c : spans) os << ' ' << c.lo << ' ' << c.hi;
        }
        os << ' ';
        write_text(os, p.label);
        os << '\n';
    }
    for (const Adjacency& a : v.adjacency)
        os << a.from.value << ' ' << a.to.value << ' ' << int{a.motion.s[0]} << ' ' << int{a.motion.s[1]} << ' ' << a.instantaneous
           << ' ' << a.constrained << '\n';
}

// The body after the key: places and adjacencies, all of it. Empty optional: malformed.
std::optional<PlaceVocabulary> read_body(std::istream& is) {
    std::size_t np = 0, na = 0;
    if (!(is >> np >> na) || np > (1u << 24) || na > (1u << 28)) return std::nullopt;
    PlaceVocabulary v;
    for (std::size_t i = 0; i < np; ++i) {
        Place p;
        p.id = PlaceId{static_cast<std::uint32_t>(i)};
        int kind = 0, jk = 0, concave = 0;
        std::size_t nn = 0, npts = 0;
        if (!(is >> kind >> jk >> p.axis >> concave) || kind < 0 || kind > static_cast<int>(PlaceKind::stop) || jk < 0 || jk > static_cast<int>(JoinKind::limit) || concave < -1 || concave > 1)
            return std::nullopt;
        if (!read_double(is, p.extent) || !(is >> p.gap >> nn) || nn > 16) return std::nullopt;
        p.kind = static_cast<PlaceKind>(kind);
        p.join_kind = static_cast<JoinKind>(jk);
        if (concave >= 0) p.concave = concave == 1;
        p.normals.resize(nn);
        for (auto& n : p.normals)
            if (!read_sign(is, n.s[0]) || !read_sign(is, n.s[1])) return std::nullopt;
        if (!(is >> npts) || npts > (1u << 24)) return std::nullopt;
        p.points.resize(npts);
        for (auto& x : p.points)
            if (!read_double(is, x.x()) || !read_double(is, x.y())) return std::nullopt;
        for (auto& spans : p.covers) {
            std::size_t ns = 0;
            if (!(is >> ns) || ns > (1u << 20)) return std::nullopt;
            spans.resize(ns);
            for (auto& c : spans)
                if (!read_double(is, c.lo) || !read_double(is, c.hi)) return std::nullopt;
        }
        if (is.get() != ' ' || !read_text(is, p.label)) return std::nullopt;
        v.places.push_back(std::move(p));
    }
    for (std::size_t i = 0; i < na; ++i) {
        Adjacency a;
        bool inst = false, con = false;
        if (!(is >> a.from.value >> a.to.value) || !read_sign(is, a.motion.s[0]) || !read_sign(is, a.motion.s[1]) || !(is >> inst >> con))
            return std::nullopt;
        if (a.from.value >= np || a.to.value >= np) return std::nullopt;
        a.instantaneous = inst;
        a.constrained = con;
        v.adjacency.push_back(a);
    }
    if (!(is >> std::ws).eof()) return std::nullopt;  // nothing may follow
    return v;
}

CacheLoad refused(CacheStatus status, std::string why) {
    CacheLoad out;
    out.status = status;
    out.why = std::move(why);
    return out;
}

// A name no other writer uses at the same time: this process, a counter, and chance.
std::string private_suffix() {
    static std::atomic<std::uint64_t> counter{0};
    static const std::uint64_t salt = std::random_device{}();
    return "." + std::to_string(::getpid()) + "." + std::to_string(counter++) + "." + hex16(salt).substr(8) + ".tmp";
}

}  // namespace

const char* to_string(CacheStatus s) noexcept {
    switch (s) {
        case CacheStatus::hit: return "hit";
        case CacheStatus::miss: return "miss";
        case CacheStatus::corrupt: return "corrupt";
        case CacheStatus::stale: return "stale";
        case CacheStatus::foreign: return "foreign";
    }
    return "?";
}

std::string place_cache_material(const PairOracle& oracle, const PlaceRequest& r) { return place_cache_material(oracle.fingerprint(), r); }

std::string place_cache_material(std::string_view fingerprint, const PlaceRequest& r) {
    std::ostringstream os;
    os << std::hexfloat << magic << '\n' << fingerprint << '\n';
    for (const auto& a : r.cspace.axes) os << "axis " << a.lo << ' ' << a.hi << ' ' << a.periodic << ' ' << a.samples << ' ' << a.stops << '\n';
    os << "tol " << r.cspace.boundary_tolerance << ' ' << r.cspace.normal_zero_tolerance << " merge " << r.merge_epsilon << " gap " << r.gap_epsilon << '\n';
    for (const auto& x : r.external) {
        os << "external " << x.coordinate << ' ' << x.value << ' ';
        write_text(os, x.label);
        os << '\n';
    }
    return os.str();
}

std::string place_cache_key(const std::string& material) { return hex16(fnv1a(material)); }

std::string place_cache_checksum(std::string_view text) { return hex16(fnv1a(text)); }

std::filesystem::path PlaceCache::path_for(const std::string& material) const {
    return dir_ / (place_cache_key(material) + ".places");
}

CacheStore PlaceCache::store(const std::string& material, const PlaceVocabulary& v) const {
    CacheStore out;
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec) {
        out.why = "cannot create the folder " + dir_.string() + ": " + ec.message();
        return out;
    }
    std::ostringstream text;
    text << magic << '\n';
    write_text(text, material);
    text << '\n';
    write_body(text, v);
    const std::string content = text.str();
    const auto path = path_for(material);
    const std::string tmp = path.string() + private_suffix();
    {
        std::ofstream os(tmp, std::ios::binary);
        if (!os) {
            out.why = "cannot write in " + dir_.string() + ": " + std::strerror(errno);
            return out;
        }
        os << content << "checksum " << place_cache_checksum(content) << '\n';
        os.close();
        if (!os) {
            out.why = "writing " + tmp + " failed: " + std::strerror(errno);
            std::filesystem::remove(tmp, ec);
            return out;
        }
    }
    std::filesystem::rename(tmp, path, ec);  // atomic: readers see the old file or the new one
    if (ec) {
        out.why = "cannot replace " + path.string() + ": " + ec.message();
        std::filesystem::remove(tmp, ec);
        return out;
    }
    out.stored = true;
    return out;
}

CacheLoad PlaceCache::load(const std::string& material) const {
    const auto path = path_for(material);
    std::error_code ec;
    // Opened first and sized through the open file: another process may remove or replace the
    // file at any moment (stores rename a whole file into place), and an open file stays the one
    // that was opened. A file gone before it could be opened is a miss, not damage.
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        // Absent when it was opened is a miss, even if another process has stored it again since
        // (asking whether it exists now would take that for damage).
        const int why = errno;
        if (why == ENOENT || !std::filesystem::exists(path, ec)) return {};
        return refused(CacheStatus::corrupt, std::string("it cannot be read: ") + std::strerror(why));
    }
    in.seekg(0, std::ios::end);
    const std::streamoff end = in.tellg();
    in.seekg(0, std::ios::beg);
    if (end < 0 || !in) return refused(CacheStatus::corrupt, "it cannot be examined");
    const auto size = static_cast<std::uintmax_t>(end);
    if (size > largest_file) return refused(CacheStatus::corrupt, "it is larger than any vocabulary the cache writes");
    std::string text(static_cast<std::size_t>(size), '\0');
    if (!in.read(text.data(), static_cast<std::streamsize>(size)))
        return refused(CacheStatus::corrupt, "it could not be read whole (it changed while being read?)");
    const std::size_t head_end = text.find('\n');
    const std::string_view head = std::string_view(text).substr(0, head_end == std::string::npos ? text.size() : head_end);
    if (head.substr(0, family.size()) != family) return refused(CacheStatus::corrupt, "it is not a place cache file");
    if (head_end == std::string::npos) return refused(CacheStatus::corrupt, "it is truncated (in its first line)");
    if (head != magic) return refused(CacheStatus::stale, "it was written in format " + std::string(head.substr(0, 40)) + ", not " + magic);
    // The checksum line closes the file: a truncated file has none, an edited one a wrong one.
    const std::size_t last = text.size() >= 2 ? text.rfind('\n', text.size() - 2) : std::string::npos;
    const std::string_view tail = std::string_view(text).substr(last == std::string::npos ? 0 : last + 1);
    const std::string expected = "checksum " + place_cache_checksum(std::string_view(text).substr(0, last + 1)) + "\n";
    if (last == std::string::npos || tail.substr(0, 9) != "checksum ") return refused(CacheStatus::corrupt, "it is truncated (no checksum line)");
    if (tail != expected) return refused(CacheStatus::corrupt, "its checksum does not match its content (the file was changed or damaged)");
    std::istringstream is(text.substr(head_end + 1, last + 1 - (head_end + 1)));
    std::string stored;
    if (!read_text(is, stored)) return refused(CacheStatus::corrupt, "its key text is malformed");
    if (stored != material) return refused(CacheStatus::foreign, "it holds the vocabulary of another computation with the same key");
    auto v = read_body(is);
    if (!v) return refused(CacheStatus::corrupt, "its places or adjacencies are malformed");
    CacheLoad out;
    out.status = CacheStatus::hit;
    out.vocabulary = std::move(*v);
    return out;
}

std::string cache_note(const PlaceCache& cache, const std::string& material, const CacheLoad& load, const CacheStore& store) {
    std::string note;
    if (load.status == CacheStatus::corrupt || load.status == CacheStatus::stale || load.status == CacheStatus::foreign)
        note = "place cache file " + cache.path_for(material).string() + " was not used: " + load.why + "; the vocabulary was computed" +
               (store ? " and the file replaced" : "");
    if (!store) note += (note.empty() ? "the vocabulary was computed but not stored in the place cache: " : "; not stored: ") + store.why;
    return note;
}

CachedPlaces build_or_load(const PairOracle& oracle, const PlaceRequest& request, const PlaceCache& cache) {
    CachedPlaces out;
    const std::string material = place_cache_material(oracle, request);
    auto loaded = cache.load(material);
    out.cache_status = loaded.status;
    if (loaded.status == CacheStatus::hit) {
        out.vocabulary = std::move(loaded.vocabulary);
        out.from_cache = true;
        return out;
    }
    auto built = build_place_vocabulary(oracle, request);
    out.status = built.status;
    out.message = std::move(built.message);
    out.vocabulary = std::move(built.vocabulary);
    if (out.status != PlaceStatus::ok) return out;
    const CacheStore stored = cache.store(material, out.vocabulary);
    out.stored = stored.stored;
    out.note = cache_note(cache, material, loaded, stored);
    return out;
}

}  // namespace qm::geometry
