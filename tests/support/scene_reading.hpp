// tests/support/scene_reading.hpp: test helper (not a test) for tests that read Alex scenes: a scene
// text or a file of the source tree read with no error expected (doctest REQUIREs it, showing the
// diagnostics), and diagnostics as print() writes them.
#pragma once
#include "scene/scene_parser.hpp"
#include <doctest/doctest.h>
#include <sstream>
#include <string>

namespace qm::test {

inline std::string printed(const Diagnostics& d) {
    std::ostringstream os;
    d.print(os);
    return os.str();
}

inline scene::Scene read_ok(const std::string& text, const std::string& file = "test.def") {
    Diagnostics d;
    auto s = scene::read_scene(file, text, d);
    INFO(text << "\n" << printed(d));
    REQUIRE(s.has_value());
    return std::move(*s);
}

// `path` relative to the source tree, e.g. "scenarios/alex/block.def"; not even a warning expected.
inline scene::Scene load_ok(const std::string& path) {
    Diagnostics d;
    auto s = scene::read_scene_file(std::string(QM_SOURCE_DIR) + "/" + path, d);
    INFO(path << "\n" << printed(d));
    REQUIRE(s.has_value());
    CHECK(d.size() == 0);
    return std::move(*s);
}

}  // namespace qm::test
