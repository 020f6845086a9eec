// engine/why_printer.cpp
#include "engine/why_printer.hpp"

namespace qm::engine {
namespace {

std::string join(const std::vector<std::string>& xs, const char* sep) {
    std::string out;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        if (i > 0) out += sep;
        out += xs[i];
    }
    return out;
}

void print_derivation(std::string& out, const Derivation& d) {
    for (const auto& s : d.steps) {
        out += "    " + s.consequent + " <= " + s.informant;
        if (!s.binding.empty()) out += " {" + join(s.binding, ", ") + "}";
        if (!s.antecedents.empty()) out += ": " + join(s.antecedents, ", ");
        out += "\n";
        for (const auto& a : s.absent) out += "      and not " + a + "\n";
    }
}

}  // namespace

std::string print_why(const Why& why) {
    std::string out;
    switch (why.status) {
        case Why::Status::holds:
            out += why.fact + " holds\n";
            for (const auto& d : why.derivations) {
                out += "  in {" + join(d.environment, ", ") + "}:\n";
                print_derivation(out, d);
            }
            break;
        case Why::Status::ruled_out:
            out += why.fact + " is ruled out: every environment supporting it is nogood\n";
            for (const auto& d : why.nogoods) {
                out += "  nogood {" + join(d.environment, ", ") + "}:\n";
                print_derivation(out, d);
            }
            break;
        case Why::Status::unsupported: out += why.fact + " has no support (no rule concludes it)\n"; break;
    }
    return out;
}

}  // namespace qm::engine
