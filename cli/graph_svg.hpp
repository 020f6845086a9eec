// cli/graph_svg.hpp
// Provides:   graph_svg(), a graph written in DOT laid out by Graphviz's `dot` layout and drawn as
//             SVG through Graphviz's library (gvc and cgraph, Debian libgraphviz-dev; at run time
//             libgvc6, whose core and dot_layout plugins do the work): no `dot` program and no
//             shell, so the file names around it may hold any character.
// Errors:     a graph Graphviz refuses, or a Graphviz that cannot find its plugins, gives the
//             reason (Graphviz's own words) instead of the SVG. The plugins are found through
//             the list libgvc6 writes when it is installed (/usr/lib/<arch>/graphviz/config6a);
//             `dot -c` or libgvc6-config-update -c, as root, writes it again.
// Ownership:  a value; Graphviz's context lives for one call.
#pragma once
#include <optional>
#include <string>

namespace qm::cli {

struct GraphSvg {
    std::optional<std::string> svg;
    std::string why_not;  // set when svg is empty
};

[[nodiscard]] GraphSvg graph_svg(const std::string& dot);

}  // namespace qm::cli
