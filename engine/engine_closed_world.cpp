// engine/engine_closed_world.cpp: when a fact "holds" for `not` and aggregates.
// The rules are those of docs/RULES.md "## Semantics":
//  - generically, a fact holds if its label is {{}}, does not hold if its label is empty, and is
//    undecidable otherwise (its truth depends on assumptions, which a monotonic label cannot carry);
//  - in a context C, a fact holds if it holds in C + {closed-world of C}; it is undecidable if it does
//    not, but would in some consistent extension of C by choice-set assumptions (a motion chosen by
//    an interpretation is not part of a context); otherwise it does not hold.
#include "engine/engine.hpp"

namespace qm::engine {
namespace {

std::string print_label(const Engine& e, const std::vector<atms::EnvId>& label) {
    std::string out = "{";
    for (std::size_t i = 0; i < label.size(); ++i) {
        if (i > 0) out += ", ";
        out += "{";
        auto as = e.atms().env(label[i]).assumptions();
        for (std::size_t k = 0; k < as.size(); ++k) {
            if (k > 0) out += ", ";
            out += e.print(as[k]);
        }
        out += "}";
    }
    return out + "}";
}

}  // namespace

ClosedWorldStatus Engine::status(FactId f, std::optional<std::uint32_t> context) {
    atms::NodeId n = fact_nodes_[f].node;
    const auto& label = atms_.label(n);
    if (!context) {
        if (label.empty()) return ClosedWorldStatus::absent;
        if (atms_.is_true(n)) return ClosedWorldStatus::holds;
        return ClosedWorldStatus::undecidable;
    }
    const Context& c = contexts_[*context];
    if (atms_.holds_in(n, c.environment)) return ClosedWorldStatus::holds;
    const atms::Environment world = atms_.env(c.environment);  // a copy: environment() below may grow the table
    for (atms::EnvId e : label) {
        bool only_choices = true;
        for (atms::AssumptionId a : atms_.env(e).assumptions()) {
            if (world.contains(a)) continue;
            if (a.value >= is_choice_assumption_.size() || !is_choice_assumption_[a.value]) {
                only_choices = false;
                break;
            }
        }
        if (!only_choices) continue;
        // e extends the context by choices only; undecidable if that extension is consistent.
        auto as = world.assumptions();
        auto extra = atms_.env(e).assumptions();
        as.insert(as.end(), extra.begin(), extra.end());
        if (atms_.is_consistent(atms_.environment(as))) return ClosedWorldStatus::undecidable;
    }
    return ClosedWorldStatus::absent;
}

std::string Engine::why_undecidable(FactId f, std::optional<std::uint32_t> context) const {
    std::string fact = print(f);
    std::string label = print_label(*this, atms_.label(fact_nodes_[f].node));
    if (!context)
        return "cannot decide " + fact + " for `not` or an aggregate without a context: its label " + label +
               " depends on assumptions (run it relative to a context environment; see docs/RULES.md, Semantics)";
    return "cannot decide " + fact + " for `not` or an aggregate in context " + std::to_string(*context) +
           ": it holds only in some choices of a choice set (label " + label +
           "), and a choice is not part of a context (see docs/RULES.md, Semantics)";
}

}  // namespace qm::engine
