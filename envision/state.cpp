// envision/state.cpp
#include "envision/state.hpp"

namespace qm::envision {

const char* sign_word(std::int8_t s) noexcept { return s == ambiguous_sign ? "?" : s > 0 ? "+" : s < 0 ? "-" : "0"; }

const char* to_string(Duration d) noexcept { return d == Duration::instant ? "instant" : "interval"; }

std::vector<std::string> cause_words(std::uint8_t causes) {
    std::vector<std::string> out;
    if (causes & Cause::kinematic) out.emplace_back("kinematic");
    if (causes & Cause::dynamic) out.emplace_back("dynamic");
    if (causes & Cause::collision) out.emplace_back("collision");
    return out;
}

}  // namespace qm::envision
