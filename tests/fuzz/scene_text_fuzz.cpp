// tests/fuzz/scene_text_fuzz.cpp: libFuzzer target for the Alex scene reader (scene/scene_parser.hpp):
// parser + checker on arbitrary bytes, then the printers and the command-line forms on what parses.
// Properties checked (abort on violation): no exception escapes; a result exists exactly when no
// error was reported; a syntax error's "expected X" names X in words (no mangled X3 type name);
// a checked scene (with its corners and linkages) re-read from either printed notation is equal
// to itself.
// Assertions on, whatever the build type (RelWithDebInfo defines NDEBUG): BOOST_ASSERT guards
// Spirit's preconditions (a 2026-11-23 replay of the corpus in a debug build found any byte >= 0x80
// aborting the parser), and QM_ASSERT the scene model's. Before any include, so that all see it.
#undef NDEBUG
#ifndef QM_ENABLE_ASSERTS
#define QM_ENABLE_ASSERTS 1
#endif
#include "scene/scene_parser.hpp"
#include "scene/scene_printer.hpp"

// The fuzz build instruments only this target, not the qm_scene library it links, so libFuzzer
// would be blind to the parser's branches. Compiling the reader's sources into this TU
// instruments them; the linker then takes no object from libqm_scene.a for these symbols.
#include "scene/scene.cpp"
#include "scene/scene_checker.cpp"
#include "scene/scene_checker_constraints.cpp"
#include "scene/scene_checker_directions.cpp"
#include "scene/scene_checker_situations.cpp"
#include "scene/scene_checker_surfaces.cpp"
#include "scene/scene_parser.cpp"
#include "scene/scene_printer.cpp"

#include <cstdint>
#include <cstdlib>
#include <string>

namespace {
// An expectation on an unnamed X3 parser reports typeid(...).name(), e.g. "N5boost6spirit...".
void require_readable(const qm::Diagnostics& diags) {
    for (const auto& d : diags.items()) {
        const auto found = d.message.find(" but found ");
        if (d.message.rfind("expected ", 0) != 0 || found == std::string::npos) continue;
        const std::string what = d.message.substr(0, found);
        if (what.find("boost") != std::string::npos || what.find("spirit") != std::string::npos) std::abort();
    }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    qm::Diagnostics diags;
    auto scene = qm::scene::read_scene("fuzz.def", text, diags);
    if (scene.has_value() == diags.has_errors()) std::abort();
    require_readable(diags);
    if (!scene) return 0;
    for (const std::string& printed : {qm::scene::print_scene(*scene), qm::scene::print_scene_keywords(*scene)}) {
        qm::Diagnostics again;
        auto back = qm::scene::read_scene("printed.def", printed, again);
        if (!back || !(*back == *scene)) std::abort();
    }
    // The same bytes as a --given motion and as a query fact, against the scene just read.
    qm::Diagnostics d1, d2;
    auto g = qm::scene::parse_given(*scene, text.substr(0, 200), d1);
    auto q = qm::scene::parse_query_fact(*scene, text.substr(0, 200), d2);
    if (g.has_value() == d1.has_errors() || q.has_value() == d2.has_errors()) std::abort();
    require_readable(d1);
    require_readable(d2);
    return 0;
}
