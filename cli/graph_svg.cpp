// cli/graph_svg.cpp: DOT to SVG with Graphviz's library (cli/graph_svg.hpp).
#include "graph_svg.hpp"
#include <gvc.h>
#include <memory>

namespace qm::cli {
namespace {

// Graphviz reports through a global hook; its messages are kept for the answer, not printed.
std::string graphviz_said;
int keep_message(char* message) {
    graphviz_said += message;
    return 0;
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

}  // namespace

#if defined(QM_SANITIZED_BUILD)
// Graphviz 2.42 and the fontconfig its renderer loads keep allocations for the life of the process
// (plugin tables, string dictionaries, font caches) that no call of theirs frees; LeakSanitizer
// reads these patterns at exit, so only leaks inside those libraries are ignored.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libgvc.so\nleak:libcgraph.so\nleak:libcdt.so\nleak:libpathplan.so\nleak:libgvplugin_\nleak:libfontconfig.so\n";
}
// Quietly: a report of the suppressions used would be taken for the command's own messages.
extern "C" const char* __lsan_default_options() { return "print_suppressions=0"; }
#endif

GraphSvg graph_svg(const std::string& dot) {
    graphviz_said.clear();
    const agusererrf before = agseterrf(keep_message);
    struct Restore {
        agusererrf f;
        ~Restore() { agseterrf(f); }
    } restore{before};
    const std::unique_ptr<GVC_t, int (*)(GVC_t*)> gvc(gvContext(), gvFreeContext);
    if (!gvc) return {std::nullopt, "Graphviz could not start"};
    const std::unique_ptr<Agraph_t, int (*)(Agraph_t*)> g(agmemread(dot.c_str()), agclose);
    if (!g) return {std::nullopt, "Graphviz could not read the graph: " + trimmed(graphviz_said)};
    if (gvLayout(gvc.get(), g.get(), "dot") != 0) {
        const bool no_plugin = graphviz_said.find("not recognized") != std::string::npos;
        return {std::nullopt, "Graphviz could not lay out the graph: " + trimmed(graphviz_said) +
                                  (no_plugin ? " (its plugins are not configured: run `dot -c` or `libgvc6-config-update -c` as root)" : "")};
    }
    char* data = nullptr;
    unsigned int length = 0;
    const int rendered = gvRenderData(gvc.get(), g.get(), "svg", &data, &length);
    GraphSvg out;
    if (rendered == 0 && data) out.svg = std::string(data, length);
    else out.why_not = "Graphviz could not draw the graph as SVG: " + trimmed(graphviz_said);
    if (data) gvFreeRenderData(data);
    gvFreeLayout(gvc.get(), g.get());
    return out;
}

}  // namespace qm::cli
