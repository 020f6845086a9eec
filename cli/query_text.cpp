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

std::optional<Entry> parse_json(std::string_view text, std::size_t& error_at, std::string& expected) {
    Entry e;
    auto set = [](std::string& out) { return [&out](auto& ctx) { out = x3::_attr(ctx); }; };
    auto flag = [&e](auto&) { e.freedom = true; };
    const auto inner = x3::lit('{') > json_string[set(e.kind)] > ':' > json_string[set(e.direction)] > '}';
    const auto motion = x3::lit('{') > json_string[set(e.object)] > ':' > inner > '}';
    const auto freedom =
        (x3::lit('{') >> x3::lit("\"freedom\"")[flag]) > ':' > x3::lit('{') > json_string[set(e.object)] > ':' > inner > '}' > '}';
    auto first = text.begin();
    try {
        if (x3::phrase_parse(first, text.end(), (freedom | motion) > x3::eoi, qm::x3_ascii::blank)) return e;
        error_at = static_cast<std::size_t>(first - text.begin());
        expected = "a JSON entry like {\"follower\": {\"rotation\": \"(-)\"}}";
    } catch (const x3::expectation_failure<std::string_view::const_iterator>& f) {
        error_at = static_cast<std::size_t>(f.where() - text.begin());
        expected = f.which() == "'\"'" || f.which().empty() ? "a JSON string" : f.which();
    }
    return std::nullopt;
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
    std::string expected;
    auto e = parse_json(text, at, expected);
    if (!e || (e->kind != "translation" && e->kind != "rotation")) {
        if (e) {
            expected = "\"translation\" or \"rotation\"";
            at = text.find("\"" + e->kind + "\"");
        }
        const std::string found = at < text.size() ? std::string(1, text[at]) : std::string("the end");
        diagnostics.error({origin, 1, static_cast<std::uint32_t>(at + 1)}, "expected " + expected + " but found '" + found + "'",
                          std::string(text));
        return std::nullopt;
    }
    const std::string kind = e->kind == "translation" ? "Translational-" : "Rotational-";
    return kind + (e->freedom ? "Freedom" : "Motion") + " (" + e->object + " " + e->direction + ")";
}

}  // namespace qm::cli
