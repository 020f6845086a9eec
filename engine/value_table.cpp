// engine/value_table.cpp: interning and ordering of ground values.
#include "engine/value_table.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::engine {

ValueId ValueTable::symbol(std::string_view name) {
    QM_REQUIRE(!name.empty(), "a symbol has a name");
    Value v;
    v.kind = ValueKind::symbol;
    v.text = std::string(name);
    return intern(std::move(v));
}

ValueId ValueTable::integer(std::int64_t i) {
    Value v;
    v.kind = ValueKind::integer;
    v.integer = i;
    return intern(std::move(v));
}

ValueId ValueTable::direction(std::string_view signs) {
    QM_REQUIRE(!signs.empty(), "a direction has at least one component");
    QM_REQUIRE(signs.find_first_not_of("+0-?") == std::string_view::npos, "a direction holds only signs");
    Value v;
    v.kind = ValueKind::direction;
    v.text = std::string(signs);
    return intern(std::move(v));
}

ValueId ValueTable::set(std::vector<ValueId> elements) {
    for (ValueId e : elements) QM_REQUIRE(e.value < size(), "set element id out of range");
    std::sort(elements.begin(), elements.end(), [this](ValueId a, ValueId b) { return less(a, b); });
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    Value v;
    v.kind = ValueKind::set;
    v.elements = std::move(elements);
    return intern(std::move(v));
}

const Value& ValueTable::value(ValueId id) const {
    QM_REQUIRE(id.value < size(), "value id out of range");
    return id.value < base_size_ ? base_->values[id.value] : values_[id.value - base_size_];
}

bool ValueTable::less(ValueId a, ValueId b) const {
    if (a == b) return false;
    const Value& x = value(a);
    const Value& y = value(b);
    auto rank = [](ValueKind k) {
        switch (k) {
            case ValueKind::integer: return 0;
            case ValueKind::symbol: return 1;
            case ValueKind::direction: return 2;
            case ValueKind::set: return 3;
        }
        return 4;
    };
    if (x.kind != y.kind) return rank(x.kind) < rank(y.kind);
    switch (x.kind) {
        case ValueKind::integer: return x.integer < y.integer;
        case ValueKind::symbol: return x.text < y.text;
        case ValueKind::direction:
            if (x.text.size() != y.text.size()) return x.text.size() < y.text.size();
            return x.text < y.text;
        case ValueKind::set:
            return std::lexicographical_compare(x.elements.begin(), x.elements.end(), y.elements.begin(),
                                                y.elements.end(),
                                                [this](ValueId p, ValueId q) { return less(p, q); });
    }
    return false;
}

std::string ValueTable::render(const Value& v) const {
    switch (v.kind) {
        case ValueKind::symbol: return v.text;
        case ValueKind::integer: return std::to_string(v.integer);
        case ValueKind::direction: {
            std::string out = "(";
            for (std::size_t i = 0; i < v.text.size(); ++i) {
                if (i > 0) out += ' ';
                out += v.text[i];
            }
            return out + ")";
        }
        case ValueKind::set: {
            std::string out = "{";
            for (std::size_t i = 0; i < v.elements.size(); ++i) {
                if (i > 0) out += ' ';
                out += print(v.elements[i]);
            }
            return out + "}";
        }
    }
    return {};
}

ValueId ValueTable::intern(Value v) {
    std::string text = render(v);
    if (base_)
        if (auto it = base_->by_text.find(text); it != base_->by_text.end()) return it->second;
    if (auto it = by_text_.find(text); it != by_text_.end()) return it->second;
    const ValueId id{static_cast<std::uint32_t>(size())};
    values_.push_back(std::move(v));
    printed_.push_back(text);
    by_text_.emplace(std::move(text), id);
    return id;
}

void ValueTable::share() {
    if (values_.empty() && applications_.empty()) return;
    auto merged = base_ ? std::make_shared<Values>(*base_) : std::make_shared<Values>();
    for (auto& v : values_) merged->values.push_back(std::move(v));
    for (auto& p : printed_) merged->printed.push_back(std::move(p));
    merged->by_text.merge(by_text_);
    for (auto& [key, a] : applications_) merged->applications.insert_or_assign(key, std::move(a));
    base_ = std::move(merged);
    base_size_ = static_cast<std::uint32_t>(base_->values.size());
    values_.clear();
    printed_.clear();
    by_text_.clear();
    applications_.clear();
}

std::size_t ValueTable::KeyHash::operator()(const ApplicationKey& k) const noexcept {
    std::size_t h = 1469598103934665603ull;
    for (std::uint64_t x : k) h = (h ^ x) * 1099511628211ull;
    return h;
}

// The function, the argument count, and the 32-bit argument ids packed two to a word.
ValueTable::ApplicationKey ValueTable::application_key(std::uintptr_t function, std::span<const ValueId> args) {
    ApplicationKey key{};
    key[0] = static_cast<std::uint64_t>(function);
    key[1] = args.size();
    for (std::size_t i = 0; i < args.size(); ++i) key[1 + (i + 1) / 2] |= std::uint64_t{args[i].value} << (32 * ((i + 1) % 2));
    return key;
}

const ValueTable::Application* ValueTable::remembered(std::uintptr_t function, std::span<const ValueId> args) const {
    if (args.size() > max_remembered_args) return nullptr;
    const ApplicationKey key = application_key(function, args);
    if (auto it = applications_.find(key); it != applications_.end()) return &it->second;
    if (base_)
        if (auto it = base_->applications.find(key); it != base_->applications.end()) return &it->second;
    return nullptr;
}

void ValueTable::remember(std::uintptr_t function, std::span<const ValueId> args, Application result) {
    if (args.size() > max_remembered_args) return;
    applications_.insert_or_assign(application_key(function, args), std::move(result));
}

}  // namespace qm::engine
