// support/qm/position_table.hpp
// Provides:   PositionTable, which maps an X3 AST node's position tag (id_first, set by the
//             `annotate` handler of qm/x3_parse.hpp) to the byte offset where the node starts, so
//             that a checker run after parsing can point at the source. Used by the Alex scene and
//             metric scene readers (the rule reader stores offsets in the tags directly).
// Ownership:  a value filled by one parse.
#pragma once
#include <boost/spirit/home/x3/support/ast/position_tagged.hpp>
#include <cstddef>
#include <vector>

namespace qm::x3_parse {

class PositionTable {
public:
    int add(std::size_t offset) {
        offsets_.push_back(offset);
        return static_cast<int>(offsets_.size() - 1);
    }
    // Offset of a node; 0 for an untagged node (id_first < 0).
    [[nodiscard]] std::size_t offset_of(const boost::spirit::x3::position_tagged& node) const {
        return node.id_first >= 0 && static_cast<std::size_t>(node.id_first) < offsets_.size()
                   ? offsets_[static_cast<std::size_t>(node.id_first)]
                   : 0;
    }

private:
    std::vector<std::size_t> offsets_;
};

}  // namespace qm::x3_parse
