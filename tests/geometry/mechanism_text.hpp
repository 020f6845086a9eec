// tests/geometry/mechanism_text.hpp: a metric scene read from a test's text, which must read
// without error (the diagnostics are shown when it does not).
#pragma once
#include "geometry/metric_scene_parser.hpp"

#include <doctest/doctest.h>
#include <sstream>
#include <string>

namespace qm::geometry::test {

inline Mechanism read(const std::string& text, const std::string& file = "v.def") {
    qm::Diagnostics d;
    auto m = read_mechanism(file, text, d);
    std::ostringstream os;
    d.print(os);
    INFO(os.str());
    REQUIRE(m);
    return *m;
}

}  // namespace qm::geometry::test
