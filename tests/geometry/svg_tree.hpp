// tests/geometry/svg_tree.hpp: a small reader of the SVG the geometry writes (elements, their
// attributes and text, entities decoded), so that tests check pictures by their structure
// rather than by searching the text; and the pieces of SVG syntax the tests need (path data of
// M/L/A/Z commands, transforms translate/scale/rotate).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <doctest/doctest.h>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace qm::geometry::test {

struct SvgElement {
    std::string name;
    std::map<std::string, std::string> attributes;
    std::string text;  // character data directly inside
    std::vector<std::unique_ptr<SvgElement>> children;
    const SvgElement* parent = nullptr;

    [[nodiscard]] std::string attr(const std::string& key) const {
        auto it = attributes.find(key);
        return it == attributes.end() ? std::string() : it->second;
    }
    [[nodiscard]] double number(const std::string& key) const { return std::stod(attr(key)); }
    [[nodiscard]] bool has_class(const std::string& c) const { return (" " + attr("class") + " ").find(" " + c + " ") != std::string::npos; }
    // Every element below this one (depth first) for which `keep` holds.
    [[nodiscard]] std::vector<const SvgElement*> all(const std::function<bool(const SvgElement&)>& keep) const {
        std::vector<const SvgElement*> out;
        for (const auto& c : children) {
            if (keep(*c)) out.push_back(c.get());
            auto more = c->all(keep);
            out.insert(out.end(), more.begin(), more.end());
        }
        return out;
    }
    [[nodiscard]] std::vector<const SvgElement*> named(const std::string& n) const {
        return all([&](const SvgElement& e) { return e.name == n; });
    }
    [[nodiscard]] const SvgElement* with_class(const std::string& c) const {
        auto v = all([&](const SvgElement& e) { return e.has_class(c); });
        return v.empty() ? nullptr : v.front();
    }
};

inline std::string decode_entities(std::string s) {
    for (auto [from, to] : {std::pair{"&lt;", "<"}, std::pair{"&gt;", ">"}, std::pair{"&quot;", "\""}, std::pair{"&amp;", "&"}})
        for (auto p = s.find(from); p != std::string::npos; p = s.find(from, p + 1)) s.replace(p, std::string(from).size(), to);
    return s;
}

// Pre: well-formed XML as the geometry writes it (no comments, CDATA or processing instructions).
inline std::unique_ptr<SvgElement> parse_svg(const std::string& text) {
    auto root = std::make_unique<SvgElement>();
    SvgElement* at = root.get();
    std::size_t i = 0;
    while (i < text.size()) {
        const auto lt = text.find('<', i);
        if (lt == std::string::npos) break;
        at->text += decode_entities(text.substr(i, lt - i));
        const auto gt = text.find('>', lt);
        REQUIRE(gt != std::string::npos);
        std::string tag = text.substr(lt + 1, gt - lt - 1);
        i = gt + 1;
        if (tag.front() == '/') {
            REQUIRE(at->parent != nullptr);
            CHECK(tag.substr(1) == at->name);
            at = const_cast<SvgElement*>(at->parent);
            continue;
        }
        const bool closed = tag.back() == '/';
        if (closed) tag.pop_back();
        auto e = std::make_unique<SvgElement>();
        std::istringstream in(tag);
        in >> e->name;
        for (std::size_t p = tag.find('='); p != std::string::npos; p = tag.find('=', p + 1)) {
            auto k0 = tag.rfind(' ', p) + 1;
            const auto q1 = tag.find('"', p + 2);
            REQUIRE(q1 != std::string::npos);
            e->attributes[tag.substr(k0, p - k0)] = decode_entities(tag.substr(p + 2, q1 - p - 2));
            p = q1;
        }
        e->parent = at;
        SvgElement* raw = e.get();
        at->children.push_back(std::move(e));
        if (!closed) at = raw;
    }
    CHECK(at == root.get());
    return root;
}

// Path data of M, L, A, Z commands with absolute coordinates: the subpaths' vertices (an arc's
// end point is a vertex; `arcs` receives each arc's radius and end point when given).
struct PathArc {
    double radius;
    Eigen::Vector2d from, to;
    bool large, sweep;
};
inline std::vector<std::vector<Eigen::Vector2d>> path_vertices(const std::string& d, std::vector<PathArc>* arcs = nullptr) {
    std::vector<std::vector<Eigen::Vector2d>> out;
    std::size_t i = 0;
    auto number = [&] {
        while (i < d.size() && (d[i] == ' ' || d[i] == ',')) ++i;
        char* end = nullptr;
        const double v = std::strtod(d.c_str() + i, &end);
        REQUIRE(end != d.c_str() + i);
        i = static_cast<std::size_t>(end - d.c_str());
        return v;
    };
    while (i < d.size()) {
        const char c = d[i++];
        if (c == ' ') continue;
        if (c == 'M') out.emplace_back();
        if (c == 'M' || c == 'L') {
            const double x = number(), y = number();
            out.back().emplace_back(x, y);
        } else if (c == 'A') {
            const double rx = number();
            (void)number();
            (void)number();
            const bool large = number() != 0, sweep = number() != 0;
            const double x = number(), y = number();
            if (arcs) arcs->push_back({rx, out.back().back(), {x, y}, large, sweep});
            out.back().emplace_back(x, y);
        } else {
            REQUIRE(c == 'Z');
        }
    }
    return out;
}

// An SVG transform list of translate(x y), scale(x y), rotate(a [cx cy]) as an affine map.
inline Eigen::Affine2d parse_transform(const std::string& t) {
    Eigen::Affine2d m = Eigen::Affine2d::Identity();
    std::size_t i = 0;
    while ((i = t.find_first_of("trs", i)) != std::string::npos) {
        const auto open = t.find('(', i), close = t.find(')', open);
        const std::string name = t.substr(i, open - i);
        std::istringstream in(t.substr(open + 1, close - open - 1));
        std::vector<double> v;
        for (double x; in >> x;) v.push_back(x);
        if (name == "translate") m = m * Eigen::Translation2d(v.at(0), v.size() > 1 ? v[1] : 0.0);
        else if (name == "scale") m = m * Eigen::Scaling(v.at(0), v.size() > 1 ? v[1] : v[0]);
        else if (name == "rotate") {
            const Eigen::Vector2d c = v.size() > 2 ? Eigen::Vector2d(v[1], v[2]) : Eigen::Vector2d::Zero();
            m = m * Eigen::Translation2d(c) * Eigen::Rotation2Dd(v.at(0) * std::numbers::pi / 180) * Eigen::Translation2d(-c);
        } else FAIL("unknown transform " << name);
        i = close + 1;
    }
    return m;
}

}  // namespace qm::geometry::test
