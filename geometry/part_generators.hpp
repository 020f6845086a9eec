// geometry/part_generators.hpp
// Provides:   generators for the parts the thesis' mechanisms use (chapters 7 and 9): spur gear
//             with N teeth and a given play, ratchet wheel, scape wheel, anchor pallets, pawl,
//             Scotch-yoke crank (its pin) and yoke (its slot), disk cam and flat follower, and
//             a block. Each is a table of named parameters with defaults and ranges (so the
//             scene checker can point at a bad one) and a function from values to a Shape:
//             closed profiles of lines and arcs in the part's own frame, with its n-fold
//             rotational symmetry about the frame's origin.
// Ownership:  the table is static; shapes are values.
// Invariants: every shape a generator returns passes check_profile / check_profiles_apart
//             (tests/geometry/part_generators_test.cpp checks this over the parameter ranges).
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/profile.hpp"
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace qm::geometry {

struct Shape {
    std::vector<Profile> profiles;  // counter-clockwise, in the part's own frame
    int symmetry = 1;               // n-fold about the frame's origin
};

struct GeneratorParam {
    const char* name;
    double default_value;
    double min;            // smallest allowed value
    bool min_exclusive;    // the value must be greater than min
    bool integer;
    const char* meaning;
};

struct ShapeResult {
    std::optional<Shape> shape;
    std::string error;     // why the values give no valid shape (shape empty)
    int bad_param = -1;    // index of the parameter to blame, or -1 for the whole entry
};

struct Generator {
    const char* name;
    const char* description;
    std::vector<GeneratorParam> params;
    ShapeResult (*make)(const std::vector<double>& values);  // values in params order
};

[[nodiscard]] const std::vector<Generator>& generators();
[[nodiscard]] const Generator* find_generator(std::string_view name);

// Values for `g` from named settings (others at their defaults), range-checked, then made.
// Unknown names are reported as an error naming the parameter.
[[nodiscard]] ShapeResult make_shape(const Generator& g, const std::vector<std::pair<std::string, double>>& settings);
// Convenience for code and tests. Pre: name is a generator's name.
[[nodiscard]] ShapeResult make_shape(std::string_view name, const std::vector<std::pair<std::string, double>>& settings = {});

}  // namespace qm::geometry
