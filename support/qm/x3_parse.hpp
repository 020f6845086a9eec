// support/qm/x3_parse.hpp
// Provides:   the Boost.Spirit X3 plumbing shared by the project's three readers (rule files:
//             engine/rule_parser*; Alex scenes: scene/scene_parser*; metric scenes:
//             geometry/metric_scene_parser*):
//             - state_tag: a grammar reads its per-parse state through x3::with<state_tag>;
//             - annotate: the on_success handler storing in each position_tagged node where it
//               starts (after leading blanks and comments), as the state's position_id(offset);
//             - first_failure: the on_error handler handing the first expectation failure of a
//               parse to the state's expectation_failed(where, what); the rule then fails, so no
//               exception leaves a parse;
//             - PositionTable (qm/position_table.hpp): a node's position tag -> its byte offset.
//             The s-expression readers' state and whole-text run are in qm/x3_sexpr.hpp.
// Contract:   a state type used with these handlers has `Iterator begin` (the start of the text),
//             `bool failed`, `int position_id(std::size_t offset)` and
//             `void expectation_failed(Iterator where, const std::string& what)`.
// Ownership:  handlers are stateless.
#pragma once
#include "qm/position_table.hpp"
#include <boost/spirit/home/x3.hpp>
#include <cstddef>
#include <string>
#include <type_traits>

namespace qm::x3_parse {
namespace x3 = boost::spirit::x3;
using Iterator = std::string::const_iterator;

struct state_tag;

// on_success: records where each position_tagged node starts (after leading blanks and comments).
struct annotate {
    template <class It, class Attr, class Ctx>
    void on_success(const It& first, const It& last, Attr& node, const Ctx& ctx) const {
        if constexpr (std::is_base_of_v<x3::position_tagged, Attr>) {
            auto& st = x3::get<state_tag>(ctx);
            It f = first;
            x3::skip_over(f, last, ctx);
            node.id_first = st.position_id(static_cast<std::size_t>(f - st.begin));
        }
    }
};

// on_error: the first expectation failure is handed to the state; the rule then fails.
struct first_failure {
    template <class It, class Exception, class Ctx>
    x3::error_handler_result on_error(It&, const It&, const Exception& x, const Ctx& ctx) const {
        auto& st = x3::get<state_tag>(ctx);
        if (!st.failed) st.expectation_failed(x.where(), x.which());
        st.failed = true;
        return x3::error_handler_result::fail;
    }
};

}  // namespace qm::x3_parse
