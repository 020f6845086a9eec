// tests/analysis/why_printer_test.cpp: the forms of a "why" answer (analysis/why_printer.hpp) on
// answers built by hand: the verdict line names the first reason's law with its citation; a
// subtree met again is referred to by the number it got where first shown, and only subtrees a
// visible line refers to get one; trees are cut at the default depth and the reasons after the
// first are a line each, and --full shows everything; a premise met again is repeated, not
// referred to; JSON keeps every tree whole and gives the same subtrees the same `ref`.
#include "analysis/why_printer.hpp"
#include <doctest/doctest.h>
#include <sstream>

using namespace qm::analysis;

namespace {

Derivation leaf(std::string fact, std::string source) {
    Derivation d;
    d.fact = std::move(fact);
    d.source = std::move(source);
    return d;
}

Derivation step(std::string fact, std::string law, std::vector<Derivation> from) {
    Derivation d;
    d.fact = std::move(fact);
    d.law = std::move(law);
    d.citation = "section 3.1, Table 3.1";
    d.source = "contact_constraint.rules:" + std::to_string(10 + from.size());
    d.bindings = {"?o = block"};
    d.from = std::move(from);
    return d;
}

// Two reasons sharing the subtree (touch a b); the first also repeats the premise (dimensions 2).
WhyAnswer answer() {
    const Derivation touch = step("(touch a b)", "surface-contact", {leaf("Contact (a b)", "s.def:3"), leaf("(dimensions 2)", "s.def:1")});
    WhyAnswer w;
    w.status = WhyAnswer::Status::ruled_out;
    w.query = "Translational-Motion (block (0 -))";
    w.situation = 2;
    Derivation shared_premise = leaf("(dimensions 2)", "");
    shared_premise.shown_above = true;
    w.exclusions.push_back({{"Contact (a b)"},
                            step("false", "constraint-prevents-translation",
                                 {step("TransConstraint (block (0 -))", "contact-constraint", {touch, shared_premise}),
                                  step("(deep 1)", "d1", {step("(deep 2)", "d2", {step("(deep 3)", "d3", {step("(deep 4)", "d4", {leaf("(x)", "s.def:9")})})})})})});
    w.exclusions.push_back({{"Contact (a b)", "Force (block (0 -) (0 0))"},
                            step("false", "other-law", {touch})});
    w.responsible_sets = {{"Contact (a b)"}};
    return w;
}

std::string text(const WhyAnswer& w, WhyPrintOptions o = {}) {
    std::ostringstream os;
    print_why(os, w, o);
    return os.str();
}

std::size_t count(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (auto at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("analysis/why_printer: the verdict first, with the decisive law and its citation") {
    const std::string t = text(answer());
    CHECK(t.substr(0, t.find('\n')) ==
          "Translational-Motion (block (0 -)) in situation 2: ruled out by constraint-prevents-translation "
          "(section 3.1, Table 3.1), resting on {Contact (a b)} (2 reasons in all)");
    WhyAnswer holds;
    holds.query = "Rotational-Motion (g (+))";
    holds.situation = 1;
    CHECK(text(holds) == "Rotational-Motion (g (+)) in situation 1: holds\n");
}

TEST_CASE("analysis/why_printer: default: first reason cut at depth 3, the others a line each") {
    const std::string t = text(answer());
    CHECK(t.find("(deep 3)  <= d3 (section 3.1, Table 3.1) at contact_constraint.rules:11  ... (2 steps below)\n") != std::string::npos);
    CHECK(t.find("(deep 4)") == std::string::npos);
    CHECK(t.find("  Reason 2: resting on {Contact (a b), Force (block (0 -) (0 0))}, by other-law\n") != std::string::npos);
    CHECK(t.find("(the derivations of reasons 2 and every step cut short: --full)") != std::string::npos);
    CHECK(t.find("?o = block") == std::string::npos);  // bindings only in the full answer
    // The shared subtree is shown once in reason 1 and referred to nowhere visible: no number.
    CHECK(t.find("[1]") == std::string::npos);
    // A law's citation is printed the first time only.
    CHECK(count(t, "(section 3.1, Table 3.1)") == 7);  // the verdict, and the six laws of reason 1 once each
}

TEST_CASE("analysis/why_printer: --full numbers shared subtrees and refers to them") {
    const std::string t = text(answer(), {.full = true});
    CHECK(t.find("[1] (touch a b)  <= surface-contact (section 3.1, Table 3.1) at contact_constraint.rules:12  {?o = block}\n") !=
          std::string::npos);
    CHECK(count(t, "(touch a b)  (see [1])") == 1);  // in reason 2
    CHECK(t.find("(deep 4)") != std::string::npos);
    CHECK(t.find("--full)") == std::string::npos);
    // A premise met again is shown again (one line either way), not as a reference.
    CHECK(count(t, "(dimensions 2)  from s.def:1") == 2);
    CHECK(t.find("derived") == std::string::npos);
}

TEST_CASE("analysis/why_printer: JSON keeps every tree whole, with citations and shared references") {
    std::ostringstream os;
    write_why_json(os, answer());
    const std::string j = os.str();
    CHECK(count(j, "\"fact\": \"(touch a b)\"") == 2);           // whole in both reasons
    CHECK(count(j, "\"fact\": \"(touch a b)\", \"law\": \"surface-contact\", \"citation\": \"section 3.1, Table 3.1\"") == 2);
    CHECK(count(j, "\"ref\": 1,") == 2);                           // the same number both times
    CHECK(j.find("\"ref\": 2") == std::string::npos);             // nothing else is shared
    CHECK(j.find("\"absent\": []") != std::string::npos);
    CHECK(j.find("\"fact\": \"(deep 4)\"") != std::string::npos);
}
