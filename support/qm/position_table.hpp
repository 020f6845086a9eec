// support/qm/position_table.hpp
// Provides:   PositionTable, which maps an X3 AST node's position tag (id_first, set by the
//             `annotate` handler of qm/x3_parse.hpp) to the byte offset where the node starts, so
//             that a checker run after parsing can point at the source. Used by the Alex scene and
//             metric scene readers (the rule reader stores offsets in the tags directly).
// Ownership:  a value filled by one parse.
// Memory:     a tag below 2^30 is the offset itself, so the table costs nothing per node (a table
//             entry per node would be a tenth of a large scene's peak memory; X3 also tags nodes
//             that backtracking later drops). Only offsets at or beyond 1 GiB, which a
//             tag cannot hold directly, are kept in a table, indexed from 2^30 on.
#pragma once
#include <boost/spirit/home/x3/support/ast/position_tagged.hpp>
#include <cstddef>
#include <vector>

namespace qm::x3_parse {

class PositionTable {
public:
    static constexpr std::size_t direct_limit = std::size_t{1} << 30;

    int add(std::size_t offset) {
        if (offset < direct_limit) return static_cast<int>(offset);
        // Past 2^31 - 1 tags the ids would overflow int: those nodes read as untagged (offset 0).
        if (far_.size() >= direct_limit - 1) return -1;
        far_.push_back(offset);
        return static_cast<int>(direct_limit + far_.size() - 1);
    }
    // Offset of a node; 0 for an untagged node (id_first < 0).
    [[nodiscard]] std::size_t offset_of(const boost::spirit::x3::position_tagged& node) const {
        if (node.id_first < 0) return 0;
        const auto id = static_cast<std::size_t>(node.id_first);
        if (id < direct_limit) return id;
        return id - direct_limit < far_.size() ? far_[id - direct_limit] : 0;
    }

private:
    std::vector<std::size_t> far_;  // offsets >= direct_limit, in the order they were tagged
};

}  // namespace qm::x3_parse
