// tests/fuzz/cli_query_text_fuzz.cpp: libFuzzer target for the query reader of --why, --without and
// the interactive mode (cli/query_text.hpp: the thesis or the JSON spelling of a motion or freedom).
// Properties checked (abort on violation): no exception escapes; a result exists exactly when no
// error was reported; every error is located on line 1 within the text (or one past its end) and
// names what was expected in words (no mangled X3 type name); a JSON spelling's result is thesis
// text that reads back to itself.
// Assertions are on in every object of a fuzz build, whatever its type (cmake/QmDefaults.cmake):
// BOOST_ASSERT guards Spirit's preconditions, QM_ASSERT the model's.
#include "query_text.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    qm::Diagnostics diags;
    auto q = qm::cli::query_text(text, "--why", diags);
    if (q.has_value() == diags.has_errors()) std::abort();
    for (const auto& d : diags.items()) {
        if (d.where.line != 1 || d.where.column < 1 || d.where.column > text.size() + 1) std::abort();
        // Only the "expected ..." part is ours; what follows "but found" echoes the input.
        const std::string expected = d.message.substr(0, d.message.find(" but found "));
        if (expected.find("boost") != std::string::npos || expected.find("spirit") != std::string::npos) std::abort();
    }
    // A JSON spelling becomes thesis text, which passes through unchanged (the thesis spelling only
    // loses its quotes and is checked later, by scene::parse_query_fact).
    const auto first = text.find_first_not_of(" \t");
    if (q && first != std::string::npos && text[first] == '{') {
        qm::Diagnostics again;
        auto back = qm::cli::query_text(*q, "--why", again);
        if (!back || *back != *q) std::abort();
    }
    return 0;
}
