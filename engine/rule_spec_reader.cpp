// engine/rule_spec_reader.cpp: tokenizer and recursive-descent reader for the rule syntax.
#include "engine/rule_spec_reader.hpp"
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace qm::engine {
namespace {

struct Token {
    enum class Kind : std::uint8_t { punct, word, string, end } kind = Kind::end;
    std::string text;
    std::uint32_t line = 1, column = 1;
};

std::vector<Token> tokenize(const std::string& text, const std::string& file, Diagnostics& diagnostics) {
    std::vector<Token> out;
    std::uint32_t line = 1, column = 1;
    std::size_t i = 0;
    auto advance = [&] {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
        ++i;
    };
    while (i < text.size()) {
        char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            advance();
        } else if (c == '#') {
            while (i < text.size() && text[i] != '\n') advance();
        } else if (std::string_view("()[]{}:").find(c) != std::string_view::npos) {
            out.push_back({Token::Kind::punct, std::string(1, c), line, column});
            advance();
        } else if (c == '"') {
            Token t{Token::Kind::string, "", line, column};
            advance();
            while (i < text.size() && text[i] != '"' && text[i] != '\n') {
                t.text += text[i];
                advance();
            }
            if (i >= text.size() || text[i] != '"') {
                diagnostics.error({file, t.line, t.column}, "unterminated string");
            } else {
                advance();
            }
            out.push_back(std::move(t));
        } else {
            Token t{Token::Kind::word, "", line, column};
            while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) &&
                   std::string_view("()[]{}:#\"").find(text[i]) == std::string_view::npos) {
                t.text += text[i];
                advance();
            }
            out.push_back(std::move(t));
        }
    }
    out.push_back({Token::Kind::end, "", line, column});
    return out;
}

bool is_sign(const Token& t) {
    return t.kind == Token::Kind::word && (t.text == "+" || t.text == "-" || t.text == "0" || t.text == "?");
}
bool is_integer(const std::string& s) {
    std::size_t k = s[0] == '-' ? 1 : 0;
    if (k >= s.size()) return false;
    for (std::size_t j = k; j < s.size(); ++j)
        if (!std::isdigit(static_cast<unsigned char>(s[j]))) return false;
    return s.size() - k <= 18;
}
bool is_variable(const Token& t) { return t.kind == Token::Kind::word && t.text.size() > 1 && t.text[0] == '?'; }
bool is_name(const Token& t) {
    return t.kind == Token::Kind::word && !t.text.empty() && !is_integer(t.text) && t.text[0] != '?';
}
bool top_level_keyword(const Token& t) {
    return t.kind == Token::Kind::word && t.column == 1 &&
           (t.text == "rule" || t.text == "fact" || t.text == "assume" || t.text == "include");
}

struct Failure {};  // unwinds to the item loop, which resynchronises

class Reader {
public:
    Reader(std::vector<Token> tokens, std::string file, ProgramSpec& spec, Diagnostics& diagnostics,
           const BuiltinRegistry& builtins, std::set<std::string>& open_files)
        : tokens_(std::move(tokens)), file_(std::move(file)), spec_(spec), diagnostics_(diagnostics),
          builtins_(builtins), open_files_(open_files) {}

    void program() {
        while (peek().kind != Token::Kind::end) {
            std::size_t start = pos_;
            try {
                item();
            } catch (const Failure&) {
                // Resume at the next top-level item (which may be where the error was found).
                if (pos_ == start) ++pos_;
                while (peek().kind != Token::Kind::end && !top_level_keyword(peek())) ++pos_;
            }
        }
    }

private:
    const Token& peek(std::size_t k = 0) const { return tokens_[std::min(pos_ + k, tokens_.size() - 1)]; }
    SourceLocation where(const Token& t) const { return {file_, t.line, t.column}; }
    std::string describe(const Token& t) const {
        switch (t.kind) {
            case Token::Kind::end: return "the end of the file";
            case Token::Kind::string: return "a string";
            default: return "'" + t.text + "'";
        }
    }
    [[noreturn]] void fail(const std::string& expected) {
        diagnostics_.error(where(peek()), "expected " + expected + " but found " + describe(peek()));
        throw Failure{};
    }
    bool at(const char* text) const { return peek().kind != Token::Kind::string && peek().text == text; }
    void expect(const char* text) {
        if (!at(text)) fail(std::string("'") + text + "'");
        ++pos_;
    }

    void item() {
        const Token& t = peek();
        if (!top_level_keyword(t)) fail("'rule', 'fact', 'assume' or 'include' at the start of a line");
        ++pos_;
        if (t.text == "include") return include(t);
        if (t.text == "fact") return spec_.facts.push_back(atom());
        if (t.text == "assume") return spec_.assumptions.push_back(atom());
        rule(t);
    }

    void include(const Token& keyword) {
        if (peek().kind != Token::Kind::string) fail("a file name in double quotes");
        const Token& name = peek();
        ++pos_;
        std::filesystem::path target = std::filesystem::path(file_).parent_path() / name.text;
        std::string path = target.lexically_normal().string();
        if (open_files_.count(path)) {
            diagnostics_.error(where(keyword), "include cycle: '" + path + "' is already being read");
            return;
        }
        std::ifstream in(path);
        if (!in) {
            diagnostics_.error(where(name), "cannot open included file '" + path + "'");
            return;
        }
        std::stringstream text;
        text << in.rdbuf();
        read_text(text.str(), path);
    }

  public:
    void read_text(const std::string& text, const std::string& path) {
        if (included_.count(path)) return;  // each file is read once
        included_.insert(path);
        open_files_.insert(path);
        Reader nested(tokenize(text, path, diagnostics_), path, spec_, diagnostics_, builtins_, open_files_);
        nested.included_ = included_;
        nested.program();
        included_ = nested.included_;
        open_files_.erase(path);
    }
    std::set<std::string> included_;

  private:
    void rule(const Token& keyword) {
        RuleSpec r;
        r.where = where(keyword);
        if (!is_name(peek())) fail("a rule name");
        r.name = peek().text;
        ++pos_;
        expect("when");
        while (!at("then")) {
            if (peek().kind == Token::Kind::end || top_level_keyword(peek())) fail("a condition or 'then'");
            r.conditions.push_back(condition());
        }
        ++pos_;
        do {
            if (peek().kind == Token::Kind::end || top_level_keyword(peek()))
                fail("a consequent (an atom, 'false', 'assume' or a bracketed quantifier)");
            r.consequents.push_back(consequent());
        } while (peek().kind != Token::Kind::end && !top_level_keyword(peek()));
        spec_.rules.push_back(std::move(r));
    }

    std::string variable() {
        if (!is_variable(peek())) fail("a variable like ?x");
        return tokens_[pos_++].text.substr(1);
    }

    AtomSpec atom() {
        AtomSpec a;
        a.where = where(peek());
        expect("(");
        if (!is_name(peek())) fail("a predicate name");
        a.predicate = tokens_[pos_++].text;
        while (!at(")")) a.args.push_back(term());
        ++pos_;
        return a;
    }

    bool builtin_test_ahead() const {
        if (!(peek().kind == Token::Kind::punct && peek().text == "(") || peek(1).kind != Token::Kind::word) return false;
        auto id = builtins_.find(peek(1).text);
        return id && builtins_.get(*id).kind == BuiltinKind::test;
    }

    TestSpec test() {
        TestSpec t;
        t.where = where(peek());
        if (!builtin_test_ahead()) fail("a builtin test like (= ?x ?y)");
        ++pos_;
        t.name = tokens_[pos_++].text;
        while (!at(")")) t.args.push_back(term());
        ++pos_;
        return t;
    }

    TermSpec term() {
        const Token& t = peek();
        TermSpec out;
        out.where = where(t);
        if (t.kind == Token::Kind::punct && t.text == "{") {
            ++pos_;
            out.kind = TermSpec::Kind::set;
            while (!at("}")) {
                if (peek().kind == Token::Kind::end) fail("'}'");
                out.args.push_back(term());
            }
            ++pos_;
            return out;
        }
        if (t.kind == Token::Kind::punct && t.text == "(") return parenthesised();
        if (t.kind != Token::Kind::word) fail("a term");
        ++pos_;
        if (is_variable(t)) {
            out.kind = TermSpec::Kind::variable;
            out.text = t.text.substr(1);
        } else if (is_integer(t.text)) {
            out.kind = TermSpec::Kind::integer;
            out.integer = std::stoll(t.text);
        } else if (std::isalpha(static_cast<unsigned char>(t.text[0]))) {
            out.kind = TermSpec::Kind::symbol;
            out.text = t.text;
        } else {
            --pos_;
            fail("a term (a symbol, integer, variable, direction, set or function call)");
        }
        return out;
    }

    // `(+ 0 -)` is a direction when every element is a sign; otherwise `(f args...)` calls a builtin.
    TermSpec parenthesised() {
        TermSpec out;
        out.where = where(peek());
        std::size_t k = 1;
        while (is_sign(peek(k))) ++k;
        if (k > 1 && peek(k).kind == Token::Kind::punct && peek(k).text == ")") {
            out.kind = TermSpec::Kind::direction;
            for (std::size_t j = 1; j < k; ++j) out.text += peek(j).text;
            pos_ += k + 1;
            return out;
        }
        ++pos_;
        if (peek().kind != Token::Kind::word || !builtins_.find(peek().text))
            fail("a direction of signs or a builtin function name");
        out.kind = TermSpec::Kind::call;
        out.text = tokens_[pos_++].text;
        while (!at(")")) {
            if (peek().kind == Token::Kind::end) fail("')'");
            out.args.push_back(term());
        }
        ++pos_;
        return out;
    }

    // `where TEST [and TEST]...`, then ':'
    std::vector<TestSpec> where_clause() {
        std::vector<TestSpec> tests;
        if (at("where")) {
            ++pos_;
            tests.push_back(test());
            while (at("and") || builtin_test_ahead()) {
                if (at("and")) ++pos_;
                tests.push_back(test());
            }
        }
        expect(":");
        return tests;
    }

    ConditionSpec condition() {
        ConditionSpec c;
        c.where = where(peek());
        if (at("not")) {
            ++pos_;
            c.kind = ConditionSpec::Kind::negation;
            c.atom = atom();
            return c;
        }
        if (builtin_test_ahead()) {
            c.kind = ConditionSpec::Kind::test;
            c.test = test();
            return c;
        }
        if (!at("[")) {
            c.atom = atom();
            return c;
        }
        ++pos_;
        if (at("sum")) {
            ++pos_;
            c.kind = ConditionSpec::Kind::aggregate;
            c.value.kind = TermSpec::Kind::variable;
            c.value.where = where(peek());
            c.value.text = variable();
            expect("over");
            c.atom = atom();
            expect("with");
            if (!is_name(peek())) fail("a builtin function name");
            c.function = tokens_[pos_++].text;
            expect("start");
            c.start = term();
            expect("as");
            c.variable = variable();
        } else {
            if (at("for")) {
                ++pos_;
                expect("all");
                c.kind = ConditionSpec::Kind::for_all;
            } else if (at("exists")) {
                ++pos_;
                c.kind = ConditionSpec::Kind::exists;
            } else {
                fail("'for all', 'exists' or 'sum'");
            }
            c.variable = variable();
            expect("in");
            c.set = term();
            c.tests = where_clause();
            c.atoms.push_back(atom());
            while (at("and") || at("(")) {
                if (at("and")) ++pos_;
                c.atoms.push_back(atom());
            }
        }
        expect("]");
        return c;
    }

    ConsequentSpec consequent() {
        ConsequentSpec c;
        c.where = where(peek());
        if (at("false")) {
            ++pos_;
            c.kind = ConsequentSpec::Kind::falsity;
            return c;
        }
        if (at("assume")) {
            ++pos_;
            c.kind = ConsequentSpec::Kind::assume;
            c.atom = atom();
            return c;
        }
        if (!at("[")) {
            c.atom = atom();
            return c;
        }
        ++pos_;
        if (at("for")) {
            ++pos_;
            expect("all");
            c.kind = ConsequentSpec::Kind::for_all;
        } else if (at("exactly")) {
            ++pos_;
            expect("one");
            c.kind = ConsequentSpec::Kind::exactly_one;
        } else {
            fail("'for all' or 'exactly one'");
        }
        c.variable = variable();
        expect("in");
        c.set = term();
        c.tests = where_clause();
        if (c.kind == ConsequentSpec::Kind::exactly_one) expect("assume");
        c.atom = atom();
        expect("]");
        return c;
    }

    std::vector<Token> tokens_;
    std::string file_;
    ProgramSpec& spec_;
    Diagnostics& diagnostics_;
    const BuiltinRegistry& builtins_;
    std::set<std::string>& open_files_;
    std::size_t pos_ = 0;
};

}  // namespace

void read_rule_text(const std::string& text, const std::string& name, ProgramSpec& spec, Diagnostics& diagnostics,
                    const BuiltinRegistry& builtins) {
    std::set<std::string> open;
    Reader root({}, name, spec, diagnostics, builtins, open);
    root.read_text(text, std::filesystem::path(name).lexically_normal().string());
}

void read_rule_file(const std::string& path, ProgramSpec& spec, Diagnostics& diagnostics,
                    const BuiltinRegistry& builtins) {
    std::ifstream in(path);
    if (!in) {
        diagnostics.error({path, 1, 1}, "cannot open rule file '" + path + "'");
        return;
    }
    std::stringstream text;
    text << in.rdbuf();
    read_rule_text(text.str(), path, spec, diagnostics, builtins);
}

}  // namespace qm::engine
