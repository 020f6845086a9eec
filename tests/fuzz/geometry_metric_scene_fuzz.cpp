// tests/fuzz/geometry_metric_scene_fuzz.cpp: libFuzzer target for the metric scene reader
// (geometry/metric_scene_parser.hpp): parser + checker on arbitrary bytes, then the CONFIG reader
// and the choice of kinematic pairs (Def 20) on what reads.
// Properties checked (abort on violation): no exception escapes; a result exists exactly when no
// error was reported; every diagnostic points inside the input; every part of a checked scene
// has closed counter-clockwise profiles and a positive size.
// Assertions on, whatever the build type (the fuzz build may define NDEBUG): BOOST_ASSERT guards
// Spirit's preconditions (x3's character classes abort on bytes >= 0x80, which the readers avoid
// through qm/x3_ascii.hpp), and QM_ASSERT the model's. Before any include, so that all see it.
#undef NDEBUG
#ifndef QM_ENABLE_ASSERTS
#define QM_ENABLE_ASSERTS 1
#endif
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"

// The fuzz build instruments only this target, not the qm_geometry library it links, so the
// reader's sources are compiled into this TU (as tests/fuzz/scene_text_fuzz.cpp does).
#include "geometry/detail/metric_keywords.cpp"
#include "geometry/detail/metric_part_checker.cpp"
#include "geometry/mechanism.cpp"
#include "geometry/metric_scene_checker.cpp"
#include "geometry/metric_scene_parser.cpp"
#include "geometry/part.cpp"
#include "geometry/part_generators.cpp"
#include "geometry/profile.cpp"
#include "geometry/profile_check.cpp"
#include "geometry/segment_queries.cpp"

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

namespace {

void check_locations(const qm::Diagnostics& d, const std::string& text) {
    std::size_t lines = 1;
    for (char c : text) lines += c == '\n';
    for (const auto& x : d.items())
        if (x.where.line < 1 || x.where.line > lines || x.where.column < 1 || x.where.column > text.size() + 1) std::abort();
    std::ostringstream os;
    d.print(os);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    qm::Diagnostics diags;
    const auto m = qm::geometry::read_mechanism("fuzz.def", text, diags);
    if (m.has_value() == diags.has_errors()) std::abort();
    check_locations(diags, text);
    if (!m) return 0;
    for (const auto& p : m->parts) {
        if (p.profiles.empty() || !(p.size() > 0)) std::abort();
        for (const auto& profile : p.profiles)
            if (!(qm::geometry::signed_area(profile) > 0)) std::abort();
    }
    // The first line of the input as a CONFIG, against the scene just read.
    const std::string config = text.substr(0, std::min(text.find('\n'), std::size_t{200}));
    qm::Diagnostics d2;
    const auto q = qm::geometry::parse_configuration(*m, config, d2);
    if (q.has_value() == d2.has_errors()) std::abort();
    check_locations(d2, config);
    if (m->parts.size() <= 8) (void)qm::geometry::kinematic_pairs(*m);
    return 0;
}
