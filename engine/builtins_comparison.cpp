// engine/builtins_comparison.cpp
#include "engine/builtins_comparison.hpp"

namespace qm::engine {

void register_comparison_builtins(BuiltinRegistry& r) {
    r.add("=", BuiltinKind::test, 2, 2, [](ValueTable&, std::span<const ValueId> a) {
        return BuiltinResult::truth(a[0] == a[1]);
    });
    r.add("!=", BuiltinKind::test, 2, 2, [](ValueTable&, std::span<const ValueId> a) {
        return BuiltinResult::truth(a[0] != a[1]);
    });
    r.add("<", BuiltinKind::test, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        return BuiltinResult::truth(v.less(a[0], a[1]));
    });
    r.add("<=", BuiltinKind::test, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        return BuiltinResult::truth(!v.less(a[1], a[0]));
    });
    r.add(">", BuiltinKind::test, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        return BuiltinResult::truth(v.less(a[1], a[0]));
    });
    r.add(">=", BuiltinKind::test, 2, 2, [](ValueTable& v, std::span<const ValueId> a) {
        return BuiltinResult::truth(!v.less(a[0], a[1]));
    });
}

}  // namespace qm::engine
