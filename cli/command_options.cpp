// cli/command_options.cpp: a command's options read by CLI11, in qm-atms' words (cli/command_options.hpp).
#include "command_options.hpp"
#include "qm/spelling.hpp"
#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>

namespace qm::cli {

struct CommandOptions::Parser {
    struct Flag {
        CLI::Option* option;
        bool* target;
    };
    struct Value {
        CLI::Option* option;
        std::string name, what, advice;
        std::optional<std::string>* single;   // exactly one of single, repeated
        std::vector<std::string>* repeated;
    };
    CLI::App app;
    std::vector<Flag> flags;
    std::vector<Value> values;
    CLI::Option* positional = nullptr;
    std::vector<std::string>* positional_target = nullptr;
    CLI::Option* help = nullptr;
    CLI::Option* version = nullptr;
    std::vector<std::string> first_names;
    std::optional<std::string>* cache_dir = nullptr;  // place_cache()'s targets
    bool* no_cache = nullptr;

    Parser() {
        // Unknown options are kept, not thrown, so that they are named with the nearest known one.
        app.allow_extras(true);
        app.set_help_flag();
        help = app.add_flag("-h,--help")->disable_flag_override();
        version = app.add_flag("--version")->disable_flag_override();
    }

    [[nodiscard]] const Value* value_named(std::string_view name) const {
        for (const Value& v : values)
            if (v.name == name) return &v;
        return nullptr;
    }

    // The long option nearest to a misspelt one (`--lmit`, `--lmit=3`), as "--limit".
    [[nodiscard]] std::optional<std::string> nearest_option(const std::string& given, bool first) const {
        const auto start = given.find_first_not_of('-');
        if (start == std::string::npos) return std::nullopt;  // dashes alone
        const std::string word = given.substr(start, given.find('=', start) - start);
        std::vector<std::string> names;
        for (const CLI::Option* o : app.get_options())
            for (const std::string& n : o->get_lnames()) names.push_back(n);
        if (first)
            for (const std::string& n : first_names) names.push_back(n.substr(n.find_first_not_of('-')));
        auto near = nearest_spelling(word, names);
        if (!near) return std::nullopt;
        return "--" + *near;
    }
};

CommandOptions::CommandOptions(std::string usage) : usage_(std::move(usage)), parser_(std::make_unique<Parser>()) {
    // A line of the top-level usage, indented to follow "usage: ", is this command's usage.
    constexpr std::string_view indent = "       qm-atms";
    if (std::string_view(usage_).starts_with(indent)) usage_.replace(0, 7, "usage: ");
}

CommandOptions::~CommandOptions() = default;

void CommandOptions::flag(const std::string& names, bool& target) {
    parser_->flags.push_back({parser_->app.add_flag(names)->disable_flag_override(), &target});
}

void CommandOptions::single(const std::string& name, std::string what, std::optional<std::string>& target, std::string advice) {
    // Every occurrence is kept: a second one is an error (parse()), not a silent replacement.
    CLI::Option* o = parser_->app.add_option(name)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    parser_->values.push_back({o, name, std::move(what), advice.empty() ? "give it once" : std::move(advice), &target, nullptr});
}

void CommandOptions::repeated(const std::string& name, std::string what, std::vector<std::string>& target) {
    CLI::Option* o = parser_->app.add_option(name)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    parser_->values.push_back({o, name, std::move(what), {}, nullptr, &target});
}

void CommandOptions::positionals(std::vector<std::string>& target) {
    parser_->positional = parser_->app.add_option("arguments")
                              ->expected(0, CLI::detail::expected_max_vector_size)
                              ->allow_extra_args()
                              ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    parser_->positional_target = &target;
}

void CommandOptions::first_may_be(std::vector<std::string> names) { parser_->first_names = std::move(names); }

std::optional<int> CommandOptions::parse(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    Parser& p = *parser_;
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes the last argument first
    try {
        p.app.parse(reversed);
    } catch (const CLI::ArgumentMismatch& e) {
        // CLI11 takes an option's value whatever it looks like, so a value is missing only after the
        // last argument; otherwise the mismatch is a flag given a value (`--json=yes`).
        for (const std::string& a : args) {
            const auto eq = a.find('=');
            if (!a.starts_with("--") || eq == std::string::npos) continue;
            const std::string name = a.substr(2, eq - 2);
            const bool flag = p.help->check_lname(name) || p.version->check_lname(name) ||
                              std::any_of(p.flags.begin(), p.flags.end(), [&](const Parser::Flag& f) { return f.option->check_lname(name); });
            if (flag) return error(err, a.substr(0, eq) + " takes no value, but is given '" + a.substr(eq + 1) + "'");
        }
        if (!args.empty())
            if (const Parser::Value* v = p.value_named(args.back().substr(0, args.back().find('='))))
                return error(err, v->name + " expects " + v->what + ", but nothing follows it");
        return error(err, e.what());
    } catch (const CLI::ParseError& e) {
        return error(err, e.what());
    }
    if (p.help->count() > 0) {
        out << usage_;
        return 0;
    }
    if (p.version->count() > 0) {
        out << version_text() << '\n';
        return 0;
    }
    for (const std::string& a : p.app.remaining()) {
        if (a == "--") continue;  // CLI11 leaves the end of the options among the extras
        if (a.size() > 1 && a[0] == '-') {
            const auto near = p.nearest_option(a, !args.empty() && a == args.front());
            return error(err, "unknown option '" + a + "'" + (near ? "; did you mean '" + *near + "'?" : std::string()));
        }
        return error(err, "unexpected argument '" + a + "'");
    }
    for (const Parser::Value& v : p.values) {
        const std::vector<std::string>& given = v.option->results();
        if (!v.single || given.size() < 2) continue;
        std::string list;
        for (const std::string& g : given) list += (list.empty() ? "'" : ", '") + g + "'";
        return error(err, v.name + " is given " + (given.size() == 2 ? std::string("twice") : std::to_string(given.size()) + " times") +
                              " (" + list + "): " + v.advice);
    }
    for (const Parser::Flag& f : p.flags) *f.target = f.option->count() > 0;
    for (const Parser::Value& v : p.values) {
        const std::vector<std::string>& given = v.option->results();
        if (v.single && !given.empty()) *v.single = given.front();
        if (v.repeated) *v.repeated = given;
    }
    if (p.positional) *p.positional_target = p.positional->results();
    if (p.cache_dir && *p.cache_dir && *p.no_cache) return error(err, "--cache DIR and --no-cache contradict each other: give one");
    return std::nullopt;
}

void CommandOptions::place_cache(std::optional<std::string>& dir, bool& no_cache) {
    single("--cache", "a folder for the place vocabularies", dir);
    flag("--no-cache", no_cache);
    parser_->cache_dir = &dir;
    parser_->no_cache = &no_cache;
}

int CommandOptions::error(std::ostream& err, const std::string& message) const {
    err << "qm-atms: error: " << message << '\n' << usage_;
    return 2;
}

int CommandOptions::bad_value(std::ostream& err, const std::string& option, const std::string& value) const {
    const Parser::Value* v = parser_->value_named(option);
    return error(err, option + " expects " + (v ? v->what : std::string("a value")) + ", not '" + value + "'");
}

std::string version_text() { return std::string("qm-atms ") + QM_ATMS_VERSION; }

int bad_input(const Diagnostics& diagnostics, std::ostream& err) {
    diagnostics.print(err);
    return 2;
}

std::optional<std::size_t> positive(std::string_view s) {
    std::size_t v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || p != s.data() + s.size() || v == 0) return std::nullopt;
    return v;
}

}  // namespace qm::cli
