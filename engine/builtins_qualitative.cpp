// engine/builtins_qualitative.cpp: thesis section 2.3 (Tables 2.2-2.3, Defs 1, 4, 12-14, 38).
#include "engine/builtins_qualitative.hpp"

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
bool open_half_plane(const std::string& a, const std::string& b) { return dot_sign(a, b) == '+'; }
bool is_zero(const std::string& v) { return v.find_first_not_of('0') == std::string::npos; }

// Def 38: 0 x = v; 1 Open-Half-Plane(v, x); 2 x zero; 3 x = Rotate-90(v, +/-) (and, our reading,
// any other direction with no definite dot product); 4 Open-Half-Plane(-v, x); 5 x = -v.
int nearness(const std::string& v, const std::string& x) {
    if (x == v) return 0;
    if (x == neg(v)) return 5;
    if (is_zero(x)) return 2;
    if (open_half_plane(v, x)) return 1;
    if (open_half_plane(neg(v), x)) return 4;
    return 3;
}

using Args = std::span<const ValueId>;

bool single(const std::vector<std::string>& d) { return d[0].size() == 1 && d[1].size() == 1; }

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

// n must be the integer 2 or 3.
std::optional<std::int64_t> dimension(const ValueTable& v, ValueId x) {
    const Value& val = v.value(x);
    if (val.kind != ValueKind::integer || (val.integer != 2 && val.integer != 3)) return std::nullopt;
    return val.integer;
}

BuiltinFn direction_set(const char* name, bool rotations) {
    return [name, rotations](ValueTable& v, Args a) {
        auto n = dimension(v, a[0]);
        if (!n) return BuiltinResult::fail(std::string("'") + name + "' expects the dimension 2 or 3");
        std::size_t components = rotations && *n == 2 ? 1 : static_cast<std::size_t>(*n);
        std::vector<ValueId> out;
        for (const auto& d : all_directions(components)) out.push_back(v.direction(d));
        return BuiltinResult::of(v.set(std::move(out)));
    };
}

BuiltinFn zero_direction(const char* name, bool rotation) {
    return [name, rotation](ValueTable& v, Args a) {
        auto n = dimension(v, a[0]);
        if (!n) return BuiltinResult::fail(std::string("'") + name + "' expects the dimension 2 or 3");
        return BuiltinResult::of(v.direction(std::string(rotation && *n == 2 ? 1 : static_cast<std::size_t>(*n), '0')));
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
    r.add("neg", K::function, 1, 1, on_directions("neg", [](ValueTable& v, const std::vector<std::string>& d) {
              return BuiltinResult::of(v.direction(neg(d[0])));
          }));
    r.add("dot-sign", K::function, 2, 2, on_directions("dot-sign", [](ValueTable& v, const std::vector<std::string>& d) {
              return BuiltinResult::of(v.direction(std::string(1, dot_sign(d[0], d[1]))));
          }));
    r.add("qsum", K::function, 2, 2, on_directions("qsum", [](ValueTable& v, const std::vector<std::string>& d) {
              std::string out = d[0];
              for (std::size_t i = 0; i < out.size(); ++i) out[i] = sign_sum(d[0][i], d[1][i]);
              return BuiltinResult::of(v.direction(out));
          }));
    r.add("qsum-cancel", K::function, 2, 2, on_directions("qsum-cancel", [](ValueTable& v, const std::vector<std::string>& d) {
              std::string out = d[0];
              for (std::size_t i = 0; i < out.size(); ++i) {
                  char a = d[0][i], b = d[1][i];
                  out[i] = (a == '+' && b == '-') || (a == '-' && b == '+') ? '0' : sign_sum(a, b);
              }
              return BuiltinResult::of(v.direction(out));
          }));
    r.add("rotate-90", K::function, 2, 2, [](ValueTable& v, Args a) {
        const Value& x = v.value(a[0]);
        const Value& rot = v.value(a[1]);
        if (x.kind != ValueKind::direction || rot.kind != ValueKind::direction || x.text.size() != 2 || rot.text.size() != 1)
            return BuiltinResult::fail("'rotate-90' expects a 2-D direction and a rotation (+) or (-); 3-D is not supported");
        if (rot.text[0] != '+' && rot.text[0] != '-')
            return BuiltinResult::fail("'rotate-90' needs the rotation (+) or (-)");
        std::string out = rot.text[0] == '+' ? std::string{sign_neg(x.text[1]), x.text[0]}
                                             : std::string{x.text[1], sign_neg(x.text[0])};
        return BuiltinResult::of(v.direction(out));
    });
    r.add("nearness", K::function, 2, 2, on_directions("nearness", [](ValueTable& v, const std::vector<std::string>& d) {
              return BuiltinResult::of(v.integer(nearness(d[0], d[1])));
          }));
    r.add("translations", K::function, 1, 1, direction_set("translations", false));
    r.add("rotations", K::function, 1, 1, direction_set("rotations", true));
    r.add("zero-translation", K::function, 1, 1, zero_direction("zero-translation", false));
    r.add("zero-rotation", K::function, 1, 1, zero_direction("zero-rotation", true));
    r.add("half-plane", K::test, 2, 2, on_directions("half-plane", [](ValueTable&, const std::vector<std::string>& d) {
              char s = dot_sign(d[0], d[1]);
              return BuiltinResult::truth(s == '+' || s == '0');
          }));
    r.add("open-half-plane", K::test, 2, 2, on_directions("open-half-plane", [](ValueTable&, const std::vector<std::string>& d) {
              return BuiltinResult::truth(open_half_plane(d[0], d[1]));
          }));
    r.add("zero?", K::test, 1, 1, on_directions("zero?", [](ValueTable&, const std::vector<std::string>& d) {
              return BuiltinResult::truth(is_zero(d[0]));
          }));
    r.add("nonzero?", K::test, 1, 1, on_directions("nonzero?", [](ValueTable&, const std::vector<std::string>& d) {
              return BuiltinResult::truth(!is_zero(d[0]));
          }));
}

}  // namespace qm::engine
