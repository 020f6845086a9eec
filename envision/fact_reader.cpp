// envision/fact_reader.cpp
#include "envision/fact_reader.hpp"
#include "envision/state.hpp"
#include "qm/assert.hpp"

namespace qm::envision {

void FactReader::each(const char* predicate, std::size_t arity, const std::function<void(std::span<const engine::ValueId>)>& f) const {
    const engine::ValueId p = e_.values().symbol(predicate);
    for (const engine::FactId id : e_.facts_of(p)) {
        const engine::Fact& fact = e_.facts().fact(id);
        if (fact.args.size() != arity) throw InternalError("the laws conclude " + e_.print(id) + ", expected " + std::to_string(arity) + " arguments");
        const atms::NodeId n = e_.node(id);
        const bool holds = env_ ? e_.atms().holds_in(n, *env_) : e_.atms().is_true(n);
        if (holds) f(fact.args);
    }
}

void FactReader::bad(engine::ValueId v, const char* expected) const {
    throw InternalError(std::string("the laws give ") + e_.values().print(v) + " where the envisioner expects " + expected);
}

const std::string& FactReader::symbol(engine::ValueId v) const {
    const engine::Value& x = e_.values().value(v);
    if (x.kind != engine::ValueKind::symbol) bad(v, "a symbol");
    return x.text;
}

std::int64_t FactReader::integer(engine::ValueId v) const {
    const engine::Value& x = e_.values().value(v);
    if (x.kind != engine::ValueKind::integer) bad(v, "an integer");
    return x.integer;
}

std::int8_t FactReader::sign(engine::ValueId v) const {
    const engine::Value& x = e_.values().value(v);
    if (x.kind != engine::ValueKind::direction || x.text.size() != 1) bad(v, "a sign like (+)");
    switch (x.text[0]) {
        case '+': return 1;
        case '-': return -1;
        case '0': return 0;
        default: return ambiguous_sign;
    }
}

geometry::QualDirection FactReader::direction(engine::ValueId v) const {
    const engine::Value& x = e_.values().value(v);
    if (x.kind != engine::ValueKind::direction || x.text.size() != 2 || x.text.find('?') != std::string::npos)
        bad(v, "a definite pair direction like (+ -)");
    auto s = [](char c) -> std::int8_t { return c == '+' ? 1 : c == '-' ? -1 : 0; };
    return geometry::QualDirection{{s(x.text[0]), s(x.text[1])}};
}

}  // namespace qm::envision
