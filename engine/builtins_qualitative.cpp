// engine/builtins_qualitative.cpp: thesis section 2.3 (Tables 2.2-2.3, Defs 1, 4, 12-14), and
// Table 2.2 with a known comparison of magnitudes (qsum-compared).
#include "engine/builtins_qualitative.hpp"
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace qm::engine {
namespace {

// Table 2.2: + + + = +, + + - = ?, 0 is neutral, ? absorbs.
char sign_sum(char a, char b) {
    if (a == '0') return b;
    if (b == '0') return a;
    if (a == '?' || b == '?') return '?';
    return a == b ? a : '?';
}
// Table 2.3: 0 annihilates (even ?), equal signs give +, opposite give -, ? otherwise.
char sign_product(char a, char b) {
    if (a == '0' || b == '0') return '0';
    if (a == '?' || b == '?') return '?';
    return a == b ? '+' : '-';
}
char sign_neg(char a) { return a == '+' ? '-' : a == '-' ? '+' : a; }

std::string neg(const std::string& v) {
    std::string out = v;
    for (char& c : out) c = sign_neg(c);
    return out;
}
char dot_sign(const std::string& a, const std::string& b) {
    char s = '0';
    for (std::size_t i = 0; i < a.size(); ++i) s = sign_sum(s, sign_product(a[i], b[i]));
    return s;
}
bool is_zero(const std::string& v) { return v.find_first_not_of('0') == std::string::npos; }

// Table 2.2 when the magnitudes are compared: a + b where w is the sign of |a| - |b|. Where a and
// b have opposite signs the larger one's sign is the sum's ((0): they cancel; (?): not known, as
// Table 2.2); elsewhere the comparison does not matter and the sum is Table 2.2's.
char sign_sum_compared(char a, char b, char w) {
    const bool opposite = (a == '+' && b == '-') || (a == '-' && b == '+');
    if (!opposite) return sign_sum(a, b);
    return w == '+' ? a : w == '-' ? b : w == '0' ? '0' : '?';
}

using Args = std::span<const ValueId>;

bool single(const std::vector<std::string>& d) { return d[0].size() == 1 && d[1].size() == 1; }

// Section 2.3 ("we resolve this ambiguity by branching"): the one resolution of v that agrees with
// x wherever v is ambiguous (each `?` of v becomes x's sign there); a definite v is itself.
std::string resolve_as(const std::string& v, const std::string& x) {
    std::string out = v;
    for (std::size_t i = 0; i < out.size(); ++i)
        if (out[i] == '?') out[i] = x[i];
    return out;
}

// Def 14 generalised per axis (Table 2.1): the quarter turn of v about each axis with a non-zero
// sign in r, summed qualitatively. A quarter turn about axis e moves the part of v perpendicular
// to e onto e x v (Table 2.4 at 90 degrees, less the unchanged axial part, which is not
// perpendicular to v); in 2-D this is (x y) -> (-y x) for (+) and (y -x) for (-). A zero rotation
// turns nothing: the zero vector, so no half-plane test on it holds.
std::string rotate_90(const std::string& v, const std::string& r) {
    std::string out(v.size(), '0');
    auto add = [&](std::size_t i, char s) { out[i] = sign_sum(out[i], s); };
    if (v.size() == 2) {
        if (r[0] == '0') return out;
        const char ax = r[0] == '+' ? sign_neg(v[1]) : v[1];
        const char ay = r[0] == '+' ? v[0] : sign_neg(v[0]);
        add(0, ax);
        add(1, ay);
        return out;
    }
    // e_x x v = (0, -vz, vy); e_y x v = (vz, 0, -vx); e_z x v = (-vy, vx, 0), each scaled by r's sign.
    const char x = v[0], y = v[1], z = v[2];
    auto scaled = [](char rs, char s) { return rs == '+' ? s : rs == '-' ? sign_neg(s) : '0'; };
    add(1, scaled(r[0], sign_neg(z)));
    add(2, scaled(r[0], y));
    add(0, scaled(r[1], z));
    add(2, scaled(r[1], sign_neg(x)));
    add(0, scaled(r[2], sign_neg(y)));
    add(1, scaled(r[2], x));
    return out;
}

// The vectors a value stands for: a direction is one vector; a set of directions is several,
// read as their intersection by the half-plane tests (a corner's potential contacts, Def 26).
std::string vectors(const ValueTable& v, ValueId x, const char* name, std::vector<std::string>& out) {
    const Value& val = v.value(x);
    if (val.kind == ValueKind::direction) {
        out.push_back(val.text);
        return {};
    }
    if (val.kind == ValueKind::set && !val.elements.empty()) {
        for (ValueId e : val.elements) {
            if (v.value(e).kind != ValueKind::direction) break;
            out.push_back(v.value(e).text);
        }
        if (out.size() == val.elements.size()) return {};
    }
    return std::string("'") + name + "' expects a direction or a non-empty set of directions, not " + v.print(x);
}

// Applies f to every vector of a direction or set value, giving a value of the same shape.
template <class F>
BuiltinResult map_vectors(ValueTable& v, ValueId x, const char* name, F f) {
    std::vector<std::string> in;
    if (auto e = vectors(v, x, name, in); !e.empty()) return BuiltinResult::fail(e);
    if (v.value(x).kind == ValueKind::direction) return BuiltinResult::of(v.direction(f(in[0])));
    std::vector<ValueId> out;
    for (const auto& s : in) out.push_back(v.direction(f(s)));
    return BuiltinResult::of(v.set(std::move(out)));
}

// A half-plane test over direction-or-set arguments: holds iff it holds for every pair of
// vectors (the intersection of the half planes). `none` inverts each pair: no pair passes.
template <class P>
BuiltinFn half_plane_test(const char* name, P pass, bool none = false) {
    return [name, pass, none](ValueTable& v, Args a) -> BuiltinResult {
        std::vector<std::string> xs, ys;
        if (auto e = vectors(v, a[0], name, xs); !e.empty()) return BuiltinResult::fail(e);
        if (auto e = vectors(v, a[1], name, ys); !e.empty()) return BuiltinResult::fail(e);
        for (const auto& x : xs)
            for (const auto& y : ys) {
                if (x.size() != y.size())
                    return BuiltinResult::fail(std::string("'") + name + "' expects directions of one dimension");
                if (pass(dot_sign(x, y)) == none) return BuiltinResult::truth(false);
            }
        return BuiltinResult::truth(true);
    };
}

// The sign strings of args, all directions of one dimension; else an error text.
std::string directions(const ValueTable& v, Args a, const char* name, std::vector<std::string>& out) {
    for (ValueId x : a) {
        const Value& val = v.value(x);
        if (val.kind != ValueKind::direction) return std::string("'") + name + "' expects directions, not " + v.print(x);
        out.push_back(val.text);
    }
    for (const auto& d : out)
        if (d.size() != out.front().size())
            return std::string("'") + name + "' expects directions of one dimension";
    return {};
}

template <class F>
BuiltinFn on_directions(const char* name, F f) {
    return [name, f](ValueTable& v, Args a) -> BuiltinResult {
        std::vector<std::string> d;
        if (auto e = directions(v, a, name, d); !e.empty()) return BuiltinResult::fail(e);
        return f(v, d);
    };
}

// A 1-based component index of a direction of `size` components, or an error text.
std::string component_index(const ValueTable& v, ValueId x, std::size_t size, const char* name, std::size_t& out) {
    const Value& val = v.value(x);
    if (val.kind != ValueKind::integer || val.integer < 1 || static_cast<std::uint64_t>(val.integer) > size)
        return std::string("'") + name + "' expects a component number from 1 to " + std::to_string(size) + ", not " +
               v.print(x);
    out = static_cast<std::size_t>(val.integer - 1);
    return {};
}

std::vector<std::string> all_directions(std::size_t n) {
    std::vector<std::string> out{""};
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<std::string> next;
        for (const auto& p : out)
            for (char c : {'+', '0', '-'}) next.push_back(p + c);
        out = std::move(next);
    }
    return out;
}

// Translations (Defs 1 and 3) are defined for any number of components; 3^n of them are listed,
// so the dimension is capped. Rotations (Defs 4 and 6) only in the plane (one component, about the
// normal) and in space (three, about x, y and z): the thesis gives them no other form (Table 2.1).
constexpr std::int64_t max_translation_dimension = 8;  // 3^8 = 6561 directions

std::optional<std::size_t> translation_dimension(const ValueTable& v, ValueId x) {
    const Value& val = v.value(x);
    if (val.kind != ValueKind::integer || val.integer < 1 || val.integer > max_translation_dimension) return std::nullopt;
    return static_cast<std::size_t>(val.integer);
}
std::optional<std::size_t> rotation_components(const ValueTable& v, ValueId x) {
    const Value& val = v.value(x);
    if (val.kind != ValueKind::integer || (val.integer != 2 && val.integer != 3)) return std::nullopt;
    return val.integer == 2 ? 1 : 3;
}

// The number of components of the directions `name` produces for dimension x; else an error text.
std::optional<std::size_t> components(const ValueTable& v, ValueId x, const char* name, bool rotation, std::string& error) {
    auto n = rotation ? rotation_components(v, x) : translation_dimension(v, x);
    if (!n)
        error = std::string("'") + name + "' expects " +
                (rotation ? std::string("the dimension 2 or 3 (rotations are defined only in the plane and in space)")
                          : "a dimension from 1 to " + std::to_string(max_translation_dimension)) +
                ", not " + v.print(x);
    return n;
}

BuiltinFn direction_set(const char* name, bool rotations) {
    return [name, rotations](ValueTable& v, Args a) {
        std::string error;
        auto n = components(v, a[0], name, rotations, error);
        if (!n) return BuiltinResult::fail(error);
        std::vector<ValueId> out;
        for (const auto& d : all_directions(*n)) out.push_back(v.direction(d));
        return BuiltinResult::of(v.set(std::move(out)));
    };
}

BuiltinFn zero_direction(const char* name, bool rotation) {
    return [name, rotation](ValueTable& v, Args a) {
        std::string error;
        auto n = components(v, a[0], name, rotation, error);
        if (!n) return BuiltinResult::fail(error);
        return BuiltinResult::of(v.direction(std::string(*n, '0')));
    };
}

}  // namespace

void register_qualitative_builtins(BuiltinRegistry& r) {
    using K = BuiltinKind;
    r.add("sign-sum", K::function, 2, 2, on_directions("sign-sum", [](ValueTable& v, const std::vector<std::string>& d) {
              if (!single(d)) return BuiltinResult::fail("'sign-sum' expects single signs like (+)");
              return BuiltinResult::of(v.direction(std::string(1, sign_sum(d[0][0], d[1][0]))));
          }));
    r.add("sign-product", K::function, 2, 2, on_directions("sign-product", [](ValueTable& v, const std::vector<std::string>& d) {
              if (!single(d)) return BuiltinResult::fail("'sign-product' expects single signs like (+)");
              return BuiltinResult::of(v.direction(std::string(1, sign_product(d[0][0], d[1][0]))));
          }));
    r.add("neg", K::function, 1, 1, [](ValueTable& v, Args a) {
        return map_vectors(v, a[0], "neg", [](const std::string& x) { return neg(x); });
    });
    r.add("dot-sign", K::function, 2, 2, on_directions("dot-sign", [](ValueTable& v, const std::vector<std::string>& d) {
              return BuiltinResult::of(v.direction(std::string(1, dot_sign(d[0], d[1]))));
          }));
    r.add("qsum", K::function, 2, 2, on_directions("qsum", [](ValueTable& v, const std::vector<std::string>& d) {
              std::string out = d[0];
              for (std::size_t i = 0; i < out.size(); ++i) out[i] = sign_sum(d[0][i], d[1][i]);
              return BuiltinResult::of(v.direction(out));
          }));
    r.add("rotate-90", K::function, 2, 2, [](ValueTable& v, Args a) {
        const Value& rot = v.value(a[1]);
        if (rot.kind != ValueKind::direction || rot.text.find('?') != std::string::npos)
            return BuiltinResult::fail("'rotate-90' expects a rotation like (+), (0) or (+ 0 -) as its second argument");
        std::vector<std::string> xs;
        if (auto e = vectors(v, a[0], "rotate-90", xs); !e.empty()) return BuiltinResult::fail(e);
        for (const auto& x : xs)
            if (!((x.size() == 2 && rot.text.size() == 1) || (x.size() == 3 && rot.text.size() == 3)))
                return BuiltinResult::fail("'rotate-90' expects a 2-D direction with a rotation (r), or a 3-D direction "
                                           "with a rotation (rx ry rz)");
        const std::string r = rot.text;
        return map_vectors(v, a[0], "rotate-90", [&r](const std::string& x) { return rotate_90(x, r); });
    });
    r.add("resolve-as", K::function, 2, 2, on_directions("resolve-as", [](ValueTable& v, const std::vector<std::string>& d) {
              return BuiltinResult::of(v.direction(resolve_as(d[0], d[1])));
          }));
    r.add("translations", K::function, 1, 1, direction_set("translations", false));
    r.add("rotations", K::function, 1, 1, direction_set("rotations", true));
    r.add("zero-translation", K::function, 1, 1, zero_direction("zero-translation", false));
    r.add("zero-rotation", K::function, 1, 1, zero_direction("zero-rotation", true));
    r.add("half-plane", K::test, 2, 2, half_plane_test("half-plane", [](char s) { return s == '+' || s == '0'; }));
    r.add("open-half-plane", K::test, 2, 2, half_plane_test("open-half-plane", [](char s) { return s == '+'; }));
    r.add("outside-open-half-plane", K::test, 2, 2,
          half_plane_test("outside-open-half-plane", [](char s) { return s == '+'; }, /*none=*/true));
    r.add("cancel-ambiguous", K::function, 1, 1, on_directions("cancel-ambiguous", [](ValueTable& v, const std::vector<std::string>& d) {
              std::string out = d[0];
              for (char& c : out) c = c == '?' ? '0' : c;
              return BuiltinResult::of(v.direction(out));
          }));
    r.add("qsum-compared", K::function, 3, 3, [](ValueTable& v, Args a) {
        std::vector<std::string> d;
        if (auto e = directions(v, a.first(2), "qsum-compared", d); !e.empty()) return BuiltinResult::fail(e);
        const Value& w = v.value(a[2]);
        if (w.kind != ValueKind::direction || w.text.size() != 1)
            return BuiltinResult::fail("'qsum-compared' expects a single sign like (+) as its third argument, not " +
                                       v.print(a[2]));
        std::string out = d[0];
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = sign_sum_compared(d[0][i], d[1][i], w.text[0]);
        return BuiltinResult::of(v.direction(out));
    });
    r.add("components", K::function, 1, 1, [](ValueTable& v, Args a) {
        const Value& d = v.value(a[0]);
        if (d.kind != ValueKind::direction) return BuiltinResult::fail("'components' expects a direction, not " + v.print(a[0]));
        return BuiltinResult::of(v.integer(static_cast<std::int64_t>(d.text.size())));
    });
    r.add("component", K::function, 2, 2, [](ValueTable& v, Args a) {
        const Value& d = v.value(a[0]);
        if (d.kind != ValueKind::direction) return BuiltinResult::fail("'component' expects a direction, not " + v.print(a[0]));
        std::size_t i = 0;
        if (auto e = component_index(v, a[1], d.text.size(), "component", i); !e.empty()) return BuiltinResult::fail(e);
        return BuiltinResult::of(v.direction(std::string(1, d.text[i])));
    });
    r.add("with-component", K::function, 3, 3, [](ValueTable& v, Args a) {
        const Value& d = v.value(a[0]);
        const Value& s = v.value(a[2]);
        if (d.kind != ValueKind::direction)
            return BuiltinResult::fail("'with-component' expects a direction, not " + v.print(a[0]));
        if (s.kind != ValueKind::direction || s.text.size() != 1)
            return BuiltinResult::fail("'with-component' expects a single sign like (+) as its third argument, not " +
                                       v.print(a[2]));
        std::size_t i = 0;
        if (auto e = component_index(v, a[1], d.text.size(), "with-component", i); !e.empty()) return BuiltinResult::fail(e);
        std::string out = d.text;
        out[i] = s.text[0];
        return BuiltinResult::of(v.direction(out));
    });
    r.add("qsum-of", K::function, 1, 1, [](ValueTable& v, Args a) {
        std::vector<std::string> xs;
        if (auto e = vectors(v, a[0], "qsum-of", xs); !e.empty()) return BuiltinResult::fail(e);
        std::string out(xs[0].size(), '0');
        for (const auto& x : xs) {
            if (x.size() != out.size()) return BuiltinResult::fail("'qsum-of' expects directions of one dimension");
            for (std::size_t i = 0; i < out.size(); ++i) out[i] = sign_sum(out[i], x[i]);
        }
        return BuiltinResult::of(v.direction(out));
    });
    // Section 2.3: "we resolve this ambiguity by branching": every definite direction a `?` of the
    // argument may stand for (each `?` replaced by +, 0 and - in turn); a definite direction is its
    // own only resolution. At most 8 components (3^8 directions), as `translations`.
    r.add("resolutions", K::function, 1, 1, [](ValueTable& v, Args a) {
        const Value& d = v.value(a[0]);
        if (d.kind != ValueKind::direction) return BuiltinResult::fail("'resolutions' expects a direction, not " + v.print(a[0]));
        if (d.text.size() > 8) return BuiltinResult::fail("'resolutions' takes directions of at most 8 components");
        std::vector<std::string> out{""};
        for (char c : d.text) {
            std::vector<std::string> next;
            for (const auto& prefix : out)
                for (char s : c == '?' ? std::string("+0-") : std::string(1, c)) next.push_back(prefix + s);
            out = std::move(next);
        }
        std::vector<ValueId> elements;
        for (const auto& x : out) elements.push_back(v.direction(x));
        return BuiltinResult::of(v.set(std::move(elements)));
    });
    r.add("set-add", K::function, 2, 2, [](ValueTable& v, Args a) {
        const Value& s = v.value(a[0]);
        if (s.kind != ValueKind::set) return BuiltinResult::fail("'set-add' expects a set first, not " + v.print(a[0]));
        std::vector<ValueId> out = s.elements;
        out.push_back(a[1]);
        return BuiltinResult::of(v.set(std::move(out)));
    });
    r.add("zero?", K::test, 1, 1, on_directions("zero?", [](ValueTable&, const std::vector<std::string>& d) {
              return BuiltinResult::truth(is_zero(d[0]));
          }));
    r.add("nonzero?", K::test, 1, 1, on_directions("nonzero?", [](ValueTable&, const std::vector<std::string>& d) {
              return BuiltinResult::truth(!is_zero(d[0]));
          }));
}

}  // namespace qm::engine
