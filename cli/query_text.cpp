// cli/query_text.cpp: the JSON spelling of a query, read with Boost.Spirit X3.
#include "query_text.hpp"
#include <boost/fusion/include/adapt_struct.hpp>
#include "qm/x3_ascii.hpp"
#include <boost/spirit/home/x3.hpp>
#include <algorithm>

namespace qm::cli {
namespace {
namespace x3 = boost::spirit::x3;

struct Entry {
    bool freedom = false;
    std::string object, kind, direction;
};

// One JSON string without escapes (names and directions never need them).
const auto json_string = x3::lexeme['"' > *(x3::char_ - '"' - '\\') > '"'];

// A parser named in words: an expectation failure on it names what was expected. (A parser with a
// semantic action has no name of its own: x3 would print its mangled C++ type.)
template <class Tag, class Parser>
auto named(const char* name, Parser p) {
    return x3::rule<Tag>{name} = p;
}

std::optional<Entry> parse_json(std::string_view text, std::size_t& error_at, std::string& expected, std::string& hint) {
    Entry e;
    auto set = [](std::string& out) { return [&out](auto& ctx) { out = x3::_attr(ctx); }; };
    auto flag = [&e](auto&) { e.freedom = true; };
    const auto object = named<class object_tag>("an object name in a JSON string", json_string[set(e.object)]);
    const auto kind = named<class kind_tag>("\"translation\" or \"rotation\"", json_string[set(e.kind)]);
    const auto direction = named<class direction_tag>("a direction in a JSON string, like \"(0 +)\"", json_string[set(e.direction)]);
    const auto inner = named<class inner_tag>("a JSON object like {\"rotation\": \"(-)\"}",
                                              x3::lit('{') > kind > ':' > direction > '}');
    const auto motion = x3::lit('{') > object > ':' > inner > '}';
    const auto freedom = (x3::lit('{') >> x3::lit("\"freedom\"")[flag]) > ':' > x3::lit('{') > object > ':' > inner > '}' > '}';
    auto first = text.begin();
    try {
        if (x3::phrase_parse(first, text.end(), (freedom | motion) > x3::eoi, qm::x3_ascii::blank)) return e;
        error_at = static_cast<std::size_t>(first - text.begin());
        expected = "a JSON entry like {\"follower\": {\"rotation\": \"(-)\"}}";
    } catch (const x3::expectation_failure<std::string_view::const_iterator>& f) {
        error_at = static_cast<std::size_t>(f.where() - text.begin());
        const std::string& which = f.which();
        expected = which == "'\"'" || which.empty() ? "a closing '\"'"
                   : which == "eoi"                   ? "the end of the query"
                   // Any parser left unnamed would print its mangled C++ type: say it in words.
                   : which.find("boost") != std::string::npos ? "a JSON entry like {\"follower\": {\"rotation\": \"(-)\"}}"
                                                              : which;
        // A whole motion entry of the output (translation and rotation): a query asks about one.
        if (which == "'}'" && error_at < text.size() && text[error_at] == ',' && !e.direction.empty())
            hint = ": a query asks about one motion at a time, e.g. {\"" + e.object + "\": {\"" + e.kind + "\": \"" +
                   e.direction + "\"}}; ask about the " + (e.kind == "translation" ? "rotation" : "translation") +
                   " in a query of its own";
    }
    return std::nullopt;
}

// What was found at `at`: the token there (up to a blank or JSON punctuation), or the end.
std::string found_at(std::string_view text, std::size_t at) {
    if (at >= text.size()) return "the end of the query";
    std::size_t end = at + 1;
    if (text[at] != '{' && text[at] != '}' && text[at] != ':' && text[at] != ',')
        while (end < text.size() && std::string_view(" \t{}:,").find(text[end]) == std::string_view::npos) ++end;
    return "'" + std::string(text.substr(at, end - at)) + "'";
}

}  // namespace

std::optional<std::string> query_text(std::string_view text, const std::string& origin, Diagnostics& diagnostics) {
    const auto start = text.find_first_not_of(" \t");
    if (start == std::string_view::npos || text[start] != '{') {
        std::string out(text);
        out.erase(std::remove(out.begin(), out.end(), '"'), out.end());
        return out;
    }
    std::size_t at = 0;
    std::string expected, hint;
    auto e = parse_json(text, at, expected, hint);
    if (!e || (e->kind != "translation" && e->kind != "rotation")) {
        if (e) {
            expected = "\"translation\" or \"rotation\"";
            at = text.find("\"" + e->kind + "\"");
        }
        diagnostics.error({origin, 1, static_cast<std::uint32_t>(at + 1)}, "expected " + expected + " but found " + found_at(text, at) + hint,
                          std::string(text));
        return std::nullopt;
    }
    const std::string kind = e->kind == "translation" ? "Translational-" : "Rotational-";
    return kind + (e->freedom ? "Freedom" : "Motion") + " (" + e->object + " " + e->direction + ")";
}

}  // namespace qm::cli
