// geometry/vocabulary_signature.cpp: a relabelling-invariant signature of a place vocabulary by
// colour refinement over its adjacency.
#include "geometry/vocabulary_signature.hpp"

#include <algorithm>
#include <cstdint>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace qm::geometry {
namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t x) {
    // FNV-1a over the 8 bytes of x, then a final avalanche (splitmix64's).
    for (int i = 0; i < 8; ++i) {
        h ^= (x >> (8 * i)) & 0xff;
        h *= 1099511628211ull;
    }
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

std::uint64_t hash_text(const std::string& s) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : s) h = mix(h, c);
    return h;
}

std::uint64_t edge_label(const Adjacency& a) {
    return static_cast<std::uint64_t>((a.motion.s[0] + 1) * 3 + (a.motion.s[1] + 1)) * 4 + (a.instantaneous ? 2 : 0) + (a.constrained ? 1 : 0);
}

}  // namespace

std::string place_description(const Place& p) {
    std::ostringstream s;
    s << to_string(p.kind);
    if (p.kind == PlaceKind::join) s << ' ' << to_string(p.join_kind);
    std::vector<std::string> normals;
    for (auto n : p.normals) normals.push_back(to_string(n));
    std::sort(normals.begin(), normals.end());
    for (const auto& n : normals) s << ' ' << n;
    if (p.concave) s << (*p.concave ? " concave" : " convex");
    if (p.kind == PlaceKind::fsd || p.kind == PlaceKind::external_division) s << " q" << p.axis;
    if (!p.label.empty()) s << " '" << p.label << "'";
    if (p.gap) s << " gap";
    return s.str();
}

std::string vocabulary_signature(const PlaceVocabulary& v) {
    const std::size_t n = v.places.size();
    std::vector<std::uint64_t> colour(n);
    for (std::size_t i = 0; i < n; ++i) colour[i] = hash_text(place_description(v.places[i]));
    std::vector<std::vector<std::pair<std::uint64_t, std::size_t>>> out(n), in(n);
    for (const auto& a : v.adjacency) {
        out[a.from.value].push_back({edge_label(a), a.to.value});
        in[a.to.value].push_back({edge_label(a), a.from.value});
    }
    auto classes = [](const std::vector<std::uint64_t>& c) { return std::set<std::uint64_t>(c.begin(), c.end()).size(); };
    std::size_t count = classes(colour);
    for (std::size_t round = 0; round < n; ++round) {
        std::vector<std::uint64_t> next(n);
        for (std::size_t i = 0; i < n; ++i) {
            std::vector<std::uint64_t> o, t;
            for (const auto& [e, j] : out[i]) o.push_back(mix(e, colour[j]));
            for (const auto& [e, j] : in[i]) t.push_back(mix(e + 1000, colour[j]));
            std::sort(o.begin(), o.end());
            std::sort(t.begin(), t.end());
            std::uint64_t h = mix(colour[i], o.size());
            for (auto x : o) h = mix(h, x);
            h = mix(h, t.size());
            for (auto x : t) h = mix(h, x);
            next[i] = h;
        }
        const std::size_t c = classes(next);
        colour = std::move(next);
        if (c == count) break;  // stable: refining further splits nothing
        count = c;
    }
    std::map<std::string, int> kinds;
    for (const auto& p : v.places) ++kinds[to_string(p.kind)];
    std::ostringstream s;
    s << "places " << n;
    for (const auto& [k, c] : kinds) s << ' ' << k << ' ' << c;
    s << " adjacencies " << v.adjacency.size() << '\n';
    std::sort(colour.begin(), colour.end());
    for (auto c : colour) s << std::hex << std::setw(16) << std::setfill('0') << c << '\n';
    return s.str();
}

std::string vocabulary_difference(const std::string& a, const std::string& b) {
    if (a == b) return {};
    auto lines = [](const std::string& s) {
        std::multiset<std::string> out;
        std::istringstream is(s);
        std::string line;
        std::getline(is, line);
        while (std::getline(is, line)) out.insert(line);
        return out;
    };
    const auto la = lines(a), lb = lines(b);
    std::vector<std::string> only_a, only_b;
    std::set_difference(la.begin(), la.end(), lb.begin(), lb.end(), std::back_inserter(only_a));
    std::set_difference(lb.begin(), lb.end(), la.begin(), la.end(), std::back_inserter(only_b));
    return a.substr(0, a.find('\n')) + " / " + b.substr(0, b.find('\n')) + "; " + std::to_string(only_a.size()) + " place colours only in the first, " +
           std::to_string(only_b.size()) + " only in the second";
}

}  // namespace qm::geometry
