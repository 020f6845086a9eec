// tests/engine/rule_printer_test.cpp: print_program() is the reader's inverse. Reading the printed
// text of a spec gives the same spec (source locations aside) for every bundled .rules file and
// for seeded random specs drawn from the whole language (every term, condition and consequent
// kind); printing is also a fixed point (print(read(print(s))) == print(s)).
#include "engine/builtin_registry.hpp"
#include "engine/rule_printer.hpp"
#include "engine/rule_spec_reader.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <random>

using namespace qm::engine;

namespace {

// Structural equality ignoring `where`, written field by field so that a printer bug cannot hide
// behind a comparison that goes through the printer itself.
bool same(const TermSpec& a, const TermSpec& b);
bool same(const std::vector<TermSpec>& a, const std::vector<TermSpec>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same(a[i], b[i])) return false;
    return true;
}
bool same(const TermSpec& a, const TermSpec& b) {
    return a.kind == b.kind && a.text == b.text && a.integer == b.integer && same(a.args, b.args);
}
bool same(const AtomSpec& a, const AtomSpec& b) { return a.predicate == b.predicate && same(a.args, b.args); }
bool same(const TestSpec& a, const TestSpec& b) { return a.name == b.name && same(a.args, b.args); }
bool same(const ConditionSpec& a, const ConditionSpec& b);
bool same(const ConsequentSpec& a, const ConsequentSpec& b);
bool same(const RuleSpec& a, const RuleSpec& b);
template <class T>
bool same_all(const std::vector<T>& a, const std::vector<T>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same(a[i], b[i])) return false;
    return true;
}
bool same(const ConditionSpec& a, const ConditionSpec& b) {
    return a.kind == b.kind && same(a.atom, b.atom) && same(a.test, b.test) && a.variable == b.variable &&
           same(a.set, b.set) && same_all(a.tests, b.tests) && same_all(a.atoms, b.atoms) &&
           a.function == b.function && same(a.value, b.value) && same(a.start, b.start);
}
bool same(const ConsequentSpec& a, const ConsequentSpec& b) {
    return a.kind == b.kind && same(a.atom, b.atom) && a.variable == b.variable && same(a.set, b.set) &&
           same_all(a.tests, b.tests);
}
bool same(const RuleSpec& a, const RuleSpec& b) {
    return a.name == b.name && same_all(a.conditions, b.conditions) && same_all(a.consequents, b.consequents);
}
bool same(const ProgramSpec& a, const ProgramSpec& b) {
    return same_all(a.rules, b.rules) && same_all(a.facts, b.facts) && same_all(a.assumptions, b.assumptions);
}

ProgramSpec read_spec(const std::string& text, qm::Diagnostics& d) {
    ProgramSpec spec;
    read_rule_text(text, "printed.rules", spec, d);
    return spec;
}

// Random specs over the whole language. Names are chosen so the reader cannot take them for
// keywords or builtins; tests and calls use real builtins of the default registry.
class Generator {
public:
    explicit Generator(unsigned seed) : rng_(seed) {
        const BuiltinRegistry& r = default_builtins();
        for (std::uint32_t i = 0; i < r.size(); ++i) {
            const Builtin& b = r.get(BuiltinId{i});
            (b.kind == BuiltinKind::test ? tests_ : functions_).push_back(b.name);
        }
    }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
    std::string name(const char* prefix) { return prefix + std::to_string(pick(5)); }
    std::string var() { return "v" + std::to_string(pick(4)); }

    TermSpec term(int depth) {
        TermSpec t;
        int k = pick(depth > 0 ? 6 : 4);
        if (k == 0) {
            t.kind = TermSpec::Kind::symbol;
            t.text = name("s");
        } else if (k == 1) {
            t.kind = TermSpec::Kind::integer;
            t.integer = std::uniform_int_distribution<std::int64_t>(-1000000, 1000000)(rng_);
        } else if (k == 2) {
            t.kind = TermSpec::Kind::variable;
            t.text = var();
        } else if (k == 3) {
            t.kind = TermSpec::Kind::direction;
            int n = 1 + pick(3);
            for (int i = 0; i < n; ++i) t.text += "+0-?"[pick(4)];
        } else {
            t.kind = k == 4 ? TermSpec::Kind::call : TermSpec::Kind::set;
            if (k == 4) t.text = functions_[static_cast<std::size_t>(pick(static_cast<int>(functions_.size())))];
            int n = pick(3) + (k == 4);
            for (int i = 0; i < n; ++i) t.args.push_back(term(depth - 1));
        }
        return t;
    }
    AtomSpec atom() {
        AtomSpec a;
        a.predicate = name("p");
        int n = pick(4);
        for (int i = 0; i < n; ++i) a.args.push_back(term(2));
        return a;
    }
    TestSpec test() {
        TestSpec t;
        t.name = tests_[static_cast<std::size_t>(pick(static_cast<int>(tests_.size())))];
        int n = 1 + pick(2);
        for (int i = 0; i < n; ++i) t.args.push_back(term(1));
        return t;
    }
    std::vector<TestSpec> tests() {
        std::vector<TestSpec> out(static_cast<std::size_t>(pick(3)));
        for (auto& t : out) t = test();
        return out;
    }
    ConditionSpec condition() {
        ConditionSpec c;
        c.kind = static_cast<ConditionSpec::Kind>(pick(6));
        switch (c.kind) {
            case ConditionSpec::Kind::atom:
            case ConditionSpec::Kind::negation: c.atom = atom(); break;
            case ConditionSpec::Kind::test: c.test = test(); break;
            case ConditionSpec::Kind::for_all:
            case ConditionSpec::Kind::exists:
                c.variable = var();
                c.set = term(2);
                c.tests = tests();
                for (int i = 0, n = 1 + pick(2); i < n; ++i) c.atoms.push_back(atom());
                break;
            case ConditionSpec::Kind::aggregate:
                c.value.kind = TermSpec::Kind::variable;
                c.value.text = var();
                c.atom = atom();
                c.function = functions_[static_cast<std::size_t>(pick(static_cast<int>(functions_.size())))];
                c.start = term(1);
                c.variable = var();
                break;
        }
        return c;
    }
    ConsequentSpec consequent() {
        ConsequentSpec c;
        c.kind = static_cast<ConsequentSpec::Kind>(pick(5));
        if (c.kind != ConsequentSpec::Kind::falsity) c.atom = atom();
        if (c.kind == ConsequentSpec::Kind::for_all || c.kind == ConsequentSpec::Kind::exactly_one) {
            c.variable = var();
            c.set = term(2);
            c.tests = tests();
        }
        return c;
    }
    ProgramSpec program() {
        ProgramSpec p;
        for (int i = 0, n = pick(3); i < n; ++i) p.facts.push_back(atom());
        for (int i = 0, n = pick(3); i < n; ++i) p.assumptions.push_back(atom());
        for (int i = 0, n = pick(4); i < n; ++i) {
            RuleSpec r;
            r.name = "r" + std::to_string(i);
            for (int k = 0, m = pick(4); k < m; ++k) r.conditions.push_back(condition());
            for (int k = 0, m = 1 + pick(3); k < m; ++k) r.consequents.push_back(consequent());
            p.rules.push_back(std::move(r));
        }
        return p;
    }

private:
    std::mt19937 rng_;
    std::vector<std::string> tests_, functions_;
};

}  // namespace

TEST_CASE("engine/rule_printer: every bundled rule file reads back to the same spec") {
    std::size_t files = 0;
    for (const char* dir : {"/scenarios/rules", "/rules"}) {
        std::filesystem::path root = std::string(QM_SOURCE_DIR) + dir;
        if (!std::filesystem::exists(root)) continue;
        for (const auto& entry : std::filesystem::directory_iterator(root)) {
            if (entry.path().extension() != ".rules") continue;
            CAPTURE(entry.path().string());
            qm::Diagnostics d;
            ProgramSpec original;
            read_rule_file(entry.path().string(), original, d);
            REQUIRE(!d.has_errors());
            std::string text = print_program(original);
            ProgramSpec again = read_spec(text, d);
            CAPTURE(text);
            CHECK(!d.has_errors());
            CHECK(same(original, again));
            ++files;
        }
    }
    CHECK(files >= 7);  // the scenarios' programs at least
}

TEST_CASE("engine/rule_printer: seeded random specs of every form read back to the same spec") {
    Generator gen(20261123);
    for (int i = 0; i < 400; ++i) {
        ProgramSpec spec = gen.program();
        std::string text = print_program(spec);
        CAPTURE(text);
        qm::Diagnostics d;
        ProgramSpec again = read_spec(text, d);
        CHECK(!d.has_errors());
        CHECK(same(spec, again));
        CHECK(print_program(again) == text);
    }
}

TEST_CASE("engine/rule_printer: the printed forms are the documented ones") {
    TermSpec dir{TermSpec::Kind::direction, "+0-", 0, {}, {}};
    CHECK(print_term(dir) == "(+ 0 -)");
    TermSpec set{TermSpec::Kind::set, "", 0, {TermSpec{TermSpec::Kind::integer, "", -3, {}, {}}, dir}, {}};
    CHECK(print_term(set) == "{-3 (+ 0 -)}");
    qm::Diagnostics d;
    ProgramSpec p = read_spec("rule r\n  when (a ?x) not (b ?x)\n  then [exactly one ?s in {u w}: assume (m ?x ?s)]\n", d);
    REQUIRE(!d.has_errors());
    CHECK(print_program(p) == "\nrule r\n  when (a ?x) not (b ?x)\n  then [exactly one ?s in {u w}: assume (m ?x ?s)]\n");
}
