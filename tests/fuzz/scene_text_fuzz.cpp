// tests/fuzz/scene_text_fuzz.cpp: libFuzzer target for the Alex scene reader (scene/scene_parser.hpp):
// parser + checker on arbitrary bytes, then the printers and the command-line forms on what parses.
// Properties checked (abort on violation): no exception escapes; a result exists exactly when no
// error was reported; a syntax error's "expected X" names X in words (no mangled X3 type name);
// a checked scene (with its corners and linkages) re-read from either printed notation is equal
// to itself.
// Assertions are on in every object of a fuzz build, whatever its type (cmake/QmDefaults.cmake):
// BOOST_ASSERT guards Spirit's preconditions, QM_ASSERT the model's.
#include "scene/scene_parser.hpp"
#include "scene/scene_printer.hpp"

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
