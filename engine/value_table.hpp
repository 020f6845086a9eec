// engine/value_table.hpp
// Provides:   ValueTable, which interns Values (equal values get the same ValueId), gives them a
//             total order and prints them in the rule language's own notation.
// Ownership:  owns every Value; ids stay valid for the table's lifetime; nothing is removed.
// Invariants: print() is injective on values, so the printed text is the interning key.
// Knows nothing of the ATMS or of rules.
#pragma once
#include "engine/value.hpp"
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>

namespace qm::engine {
class ValueTable {
public:
    ValueId symbol(std::string_view name);
    ValueId integer(std::int64_t v);
    // Pre: signs holds only + 0 - ? and is not empty.
    ValueId direction(std::string_view signs);
    // Elements may be in any order and repeat; the stored set is sorted and distinct.
    ValueId set(std::vector<ValueId> elements);

    // Pre (all queries): id issued by this table.
    [[nodiscard]] const Value& value(ValueId id) const;
    [[nodiscard]] const std::string& print(ValueId id) const { return printed_[id]; }
    // Total order: integers (numerically) < symbols < directions < sets, then by content.
    [[nodiscard]] bool less(ValueId a, ValueId b) const;
    [[nodiscard]] std::size_t size() const noexcept { return values_.size(); }

private:
    ValueId intern(Value v);
    [[nodiscard]] std::string render(const Value& v) const;

    IdVector<ValueId, Value> values_;
    IdVector<ValueId, std::string> printed_;
    std::unordered_map<std::string, ValueId> by_text_;
};
}  // namespace qm::engine
