// engine/builtins_integer.cpp
#include "engine/builtins_integer.hpp"
#include <cstdint>
#include <limits>
#include <string>

namespace qm::engine {
namespace {

constexpr std::int64_t max_range_size = 100000;

bool integers(const ValueTable& v, std::span<const ValueId> a) {
    for (ValueId x : a)
        if (v.value(x).kind != ValueKind::integer) return false;
    return true;
}

BuiltinResult not_integers(const char* name) {
    return BuiltinResult::fail(std::string("'") + name + "' expects integer arguments");
}

}  // namespace

void register_integer_builtins(BuiltinRegistry& r) {
    r.add("+", BuiltinKind::function, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        if (!integers(v, a)) return not_integers("+");
        std::int64_t out = 0;
        if (__builtin_add_overflow(v.value(a[0]).integer, v.value(a[1]).integer, &out))
            return BuiltinResult::fail("integer overflow in '+'");
        return BuiltinResult::of(v.integer(out));
    });
    r.add("-", BuiltinKind::function, 1, 2, [](ValueTable& v, std::span<const ValueId> a) {
        if (!integers(v, a)) return not_integers("-");
        std::int64_t x = a.size() == 1 ? 0 : v.value(a[0]).integer;
        std::int64_t y = v.value(a[a.size() - 1]).integer;
        std::int64_t out = 0;
        if (__builtin_sub_overflow(x, y, &out)) return BuiltinResult::fail("integer overflow in '-'");
        return BuiltinResult::of(v.integer(out));
    });
    r.add("*", BuiltinKind::function, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        if (!integers(v, a)) return not_integers("*");
        std::int64_t out = 0;
        if (__builtin_mul_overflow(v.value(a[0]).integer, v.value(a[1]).integer, &out))
            return BuiltinResult::fail("integer overflow in '*'");
        return BuiltinResult::of(v.integer(out));
    });
    r.add("abs", BuiltinKind::function, 1, 1, [](ValueTable& v, std::span<const ValueId> a) {
        if (!integers(v, a)) return not_integers("abs");
        std::int64_t x = v.value(a[0]).integer;
        if (x == std::numeric_limits<std::int64_t>::min()) return BuiltinResult::fail("integer overflow in 'abs'");
        return BuiltinResult::of(v.integer(x < 0 ? -x : x));
    });
    r.add("min", BuiltinKind::function, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        return BuiltinResult::of(v.less(a[1], a[0]) ? a[1] : a[0]);
    });
    r.add("max", BuiltinKind::function, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        return BuiltinResult::of(v.less(a[0], a[1]) ? a[1] : a[0]);
    });
    r.add("range", BuiltinKind::function, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        if (!integers(v, a)) return not_integers("range");
        std::int64_t lo = v.value(a[0]).integer;
        std::int64_t hi = v.value(a[1]).integer;
        if (hi < lo) return BuiltinResult::of(v.set({}));
        // hi - lo can exceed INT64_MAX (e.g. (range INT64_MIN INT64_MAX)): take the difference in
        // unsigned arithmetic, where it is exact for hi >= lo. Counting elements rather than
        // stepping i up to hi keeps ++i from overflowing at hi = INT64_MAX.
        const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
        if (span >= static_cast<std::uint64_t>(max_range_size))
            return BuiltinResult::fail("'range' would have more than " + std::to_string(max_range_size) + " elements");
        std::vector<ValueId> elements;
        elements.reserve(static_cast<std::size_t>(span) + 1);
        for (std::uint64_t k = 0; k <= span; ++k) elements.push_back(v.integer(lo + static_cast<std::int64_t>(k)));
        return BuiltinResult::of(v.set(std::move(elements)));
    });
}

}  // namespace qm::engine
