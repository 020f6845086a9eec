// engine/law_check.cpp: citations and direction arities of law files (engine/law_check.hpp).
#include "engine/law_check.hpp"
#include <algorithm>
#include <cctype>
#include <set>

namespace qm::engine {
namespace {

void warn(Diagnostics& d, const SourceLocation& where, std::string message) {
    d.add({Severity::warning, where, std::move(message), {}, {}});
}

// A numbered part of the thesis: "section 3.1", "Table 3.2", "Def 25", "Definitions 8-10", "Law 5",
// "Figure 7.14", "chapter 6", "Appendix A" (case-insensitive; the number may follow a blank).
bool names_part_of_thesis(const std::string& text) {
    std::string lower(text.size(), ' ');
    std::transform(text.begin(), text.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* word : {"section", "table", "def", "law", "figure", "chapter", "appendix"}) {
        for (std::size_t at = lower.find(word); at != std::string::npos; at = lower.find(word, at + 1)) {
            std::size_t i = at + std::string(word).size();
            while (i < lower.size() && std::isalpha(static_cast<unsigned char>(lower[i]))) ++i;  // "definitions", "sections"
            while (i < lower.size() && lower[i] == ' ') ++i;
            if (i < lower.size() && (std::isdigit(static_cast<unsigned char>(lower[i])) || (lower[i] >= 'a' && lower[i] <= 'd' &&
                                                                                           std::string(word) == "appendix")))
                return true;
        }
    }
    return false;
}

void directions(const TermSpec& t, std::vector<const TermSpec*>& out) {
    if (t.kind == TermSpec::Kind::direction) out.push_back(&t);
    for (const TermSpec& a : t.args) directions(a, out);
}
void directions(const std::vector<TermSpec>& ts, std::vector<const TermSpec*>& out) {
    for (const TermSpec& t : ts) directions(t, out);
}
void directions(const std::vector<TestSpec>& ts, std::vector<const TermSpec*>& out) {
    for (const TestSpec& t : ts) directions(t.args, out);
}

// Every direction literal of the program, in reading order within each item.
std::vector<const TermSpec*> direction_literals(const ProgramSpec& spec) {
    std::vector<const TermSpec*> out;
    for (const AtomSpec& a : spec.facts) directions(a.args, out);
    for (const AtomSpec& a : spec.assumptions) directions(a.args, out);
    for (const RuleSpec& r : spec.rules) {
        for (const ConditionSpec& c : r.conditions) {
            directions(c.atom.args, out);
            directions(c.test.args, out);
            directions(c.set, out);
            directions(c.tests, out);
            for (const AtomSpec& a : c.atoms) directions(a.args, out);
            directions(c.value, out);
            directions(c.start, out);
        }
        for (const ConsequentSpec& c : r.consequents) {
            directions(c.atom.args, out);
            directions(c.set, out);
            directions(c.tests, out);
        }
    }
    return out;
}

std::string direction_text(const std::string& signs) {
    std::string out = "(";
    for (std::size_t i = 0; i < signs.size(); ++i) out += (i ? " " : "") + std::string(1, signs[i]);
    return out + ")";
}

}  // namespace

void check_laws(const ProgramSpec& spec, const LawCheckOptions& options, Diagnostics& diagnostics) {
    if (options.require_citations) {
        std::set<std::string> cited, warned;
        for (const CitationSpec& c : spec.citations) {
            cited.insert(c.where.file.str());
            if (!names_part_of_thesis(c.text))
                warn(diagnostics, c.where, "a citation names the part of the thesis the file encodes, with its number (e.g. \"section 3.2, "
                                           "Table 3.2\", \"Definition 24\", \"Law 5\"), but '" + c.text + "' names none");
        }
        for (const RuleSpec& r : spec.rules)
            if (!cited.contains(r.where.file.str()) && warned.insert(r.where.file.str()).second)
                warn(diagnostics, r.where, "a law file cites the thesis: add a line `cite \"section ..., Table ...\"` to this "
                                           "file naming what its rules encode (explanations print it beside each law)");
    }
    if (!options.direction_arities.empty())
        for (const TermSpec* t : direction_literals(spec)) {
            const std::size_t n = t->text.size();
            const auto& ok = options.direction_arities;
            if (n < 2 || std::find(ok.begin(), ok.end(), n) != ok.end()) continue;
            warn(diagnostics, t->where, "the direction " + direction_text(t->text) + " has " + std::to_string(n) + " signs, but " +
                                            options.arity_context + ": it can match none of them");
        }
}

std::map<std::string, std::string> citations(const ProgramSpec& spec) {
    std::map<std::string, std::string> out;
    for (const CitationSpec& c : spec.citations) {
        std::string& text = out[c.where.file.str()];
        text += (text.empty() ? "" : "; ") + c.text;
    }
    return out;
}

}  // namespace qm::engine
