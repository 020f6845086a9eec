// geometry/place_cache.cpp: a line-based file per vocabulary, doubles in hexfloat so they are exact.
#include "geometry/place_cache.hpp"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace qm::geometry {
namespace {

// /2: divisions on a periodic axis carry intermediate points (their direction); faces a gap flag.
// /3: the builder changed (contradicting normals, joins at needle tips): vocabularies stored by /2
// differ for the same geometry and settings (the escapement: 62 places, now 35).
// /4: normals leading into blocked space are marked too (the escapement at grid 256: 92 places,
// now 49).
// /5: joins are moved onto the boundary along their mean normal itself, not along its
// cell-scaled direction (the ratchet at its own grid 64x64: 100 places, now 90).
// /6: the ends of a translation axis (or a window) are stops, `stop` places (kind 5) with the
// stop's normal on the `limit` joins at their ends (the cam follower could stay moving up for
// ever in the face at the top of its stroke).
constexpr const char* magic = "qm-place-cache/6";

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

}  // namespace

std::string place_cache_material(const PairOracle& oracle, const PlaceRequest& r) {
    std::ostringstream os;
    os << std::hexfloat << magic << '\n' << oracle.fingerprint() << '\n';
    for (const auto& a : r.cspace.axes) os << "axis " << a.lo << ' ' << a.hi << ' ' << a.periodic << ' ' << a.samples << ' ' << a.stops << '\n';
    os << "tol " << r.cspace.boundary_tolerance << ' ' << r.cspace.normal_zero_tolerance << " merge " << r.merge_epsilon << " gap " << r.gap_epsilon << '\n';
    for (const auto& x : r.external) {
        os << "external " << x.coordinate << ' ' << x.value << ' ';
        write_text(os, x.label);
        os << '\n';
    }
    return os.str();
}

std::string place_cache_key(const std::string& material) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : material) {
        h ^= c;
        h *= 1099511628211ull;
    }
    std::ostringstream os;
    os << std::hex << std::setw(16) << std::setfill('0') << h;
    return os.str();
}

std::filesystem::path PlaceCache::path_for(const std::string& material) const {
    return dir_ / (place_cache_key(material) + ".places");
}

bool PlaceCache::store(const std::string& material, const PlaceVocabulary& v) const {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    const auto path = path_for(material);
    const auto tmp = path.string() + ".tmp";
    {
        std::ofstream os(tmp, std::ios::binary);
        if (!os) return false;
        os << std::hexfloat << magic << '\n';
        write_text(os, material);
        os << '\n' << v.places.size() << ' ' << v.adjacency.size() << '\n';
        for (const Place& p : v.places) {
            os << static_cast<int>(p.kind) << ' ' << static_cast<int>(p.join_kind) << ' ' << p.axis << ' '
               << (p.concave ? (*p.concave ? 1 : 0) : -1) << ' ' << p.extent << ' ' << p.gap << ' ' << p.normals.size();
            for (auto n : p.normals) os << ' ' << int{n.s[0]} << ' ' << int{n.s[1]};
            os << ' ' << p.points.size();
            for (const auto& x : p.points) os << ' ' << x.x() << ' ' << x.y();
            os << ' ';
            write_text(os, p.label);
            os << '\n';
        }
        for (const Adjacency& a : v.adjacency)
            os << a.from.value << ' ' << a.to.value << ' ' << int{a.motion.s[0]} << ' ' << int{a.motion.s[1]} << ' '
               << a.instantaneous << ' ' << a.constrained << '\n';
        if (!os) return false;
    }
    std::filesystem::rename(tmp, path, ec);
    return !ec;
}

CacheLoad PlaceCache::load(const std::string& material) const {
    CacheLoad out;
    std::ifstream is(path_for(material), std::ios::binary);
    if (!is) return out;
    out.status = CacheStatus::corrupt;
    std::string head, stored;
    if (!std::getline(is, head) || head != magic || !read_text(is, stored)) return out;
    if (stored != material) {  // a different computation with the same hash
        out.status = CacheStatus::miss;
        return out;
    }
    std::size_t np = 0, na = 0;
    if (!(is >> np >> na) || np > (1u << 24) || na > (1u << 28)) return out;
    PlaceVocabulary v;
    for (std::size_t i = 0; i < np; ++i) {
        Place p;
        p.id = PlaceId{static_cast<std::uint32_t>(i)};
        int kind = 0, jk = 0, concave = 0;
        std::size_t nn = 0, npts = 0;
        if (!(is >> kind >> jk >> p.axis >> concave) || kind < 0 || kind > 5 || jk < 0 || jk > 3) return out;
        if (!read_double(is, p.extent) || !(is >> p.gap >> nn) || nn > 16) return out;
        p.kind = static_cast<PlaceKind>(kind);
        p.join_kind = static_cast<JoinKind>(jk);
        if (concave >= 0) p.concave = concave == 1;
        p.normals.resize(nn);
        for (auto& n : p.normals)
            if (!read_sign(is, n.s[0]) || !read_sign(is, n.s[1])) return out;
        if (!(is >> npts) || npts > (1u << 24)) return out;
        p.points.resize(npts);
        for (auto& x : p.points)
            if (!read_double(is, x.x()) || !read_double(is, x.y())) return out;
        if (is.get() != ' ' || !read_text(is, p.label)) return out;
        v.places.push_back(std::move(p));
    }
    for (std::size_t i = 0; i < na; ++i) {
        Adjacency a;
        bool inst = false, con = false;
        if (!(is >> a.from.value >> a.to.value) || !read_sign(is, a.motion.s[0]) || !read_sign(is, a.motion.s[1]) || !(is >> inst >> con))
            return out;
        if (a.from.value >= np || a.to.value >= np) return out;
        a.instantaneous = inst;
        a.constrained = con;
        v.adjacency.push_back(a);
    }
    out.status = CacheStatus::hit;
    out.vocabulary = std::move(v);
    return out;
}

CachedPlaces build_or_load(const PairOracle& oracle, const PlaceRequest& request, const PlaceCache& cache) {
    CachedPlaces out;
    const std::string material = place_cache_material(oracle, request);
    if (auto hit = cache.load(material); hit.status == CacheStatus::hit) {
        out.vocabulary = std::move(hit.vocabulary);
        out.from_cache = true;
        return out;
    }
    auto built = build_place_vocabulary(oracle, request);
    out.status = built.status;
    out.message = std::move(built.message);
    out.vocabulary = std::move(built.vocabulary);
    if (out.status == PlaceStatus::ok) (void)cache.store(material, out.vocabulary);
    return out;
}

}  // namespace qm::geometry
