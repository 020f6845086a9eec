// engine/report_printer.cpp
#include "engine/report_printer.hpp"

namespace qm::engine {
namespace {

std::string env(const EnvText& e) {
    std::string out = "{";
    for (std::size_t i = 0; i < e.size(); ++i) {
        if (i > 0) out += ", ";
        out += e[i];
    }
    return out + "}";
}

}  // namespace

std::string print_report(const RunReport& report) {
    std::string out = "facts (" + std::to_string(report.facts.size()) + "):\n";
    for (const auto& f : report.facts) {
        out += "  " + f.fact + "  ";
        if (f.label.empty()) out += "ruled out";
        for (std::size_t i = 0; i < f.label.size(); ++i) {
            if (i > 0) out += ' ';
            out += env(f.label[i]);
        }
        out += "\n";
    }
    out += "nogoods (" + std::to_string(report.nogoods.size()) + "):\n";
    for (const auto& n : report.nogoods) out += "  " + env(n) + "\n";
    for (const auto& u : report.unlisted) {
        // The first members and the last one: the set itself is in the JSON form.
        std::string members;
        for (std::size_t i = 0; i < u.members.size(); ++i) {
            if (i == 3 && u.members.size() > 4) {
                members += ", ...";
                i = u.members.size() - 1;
            }
            members += (members.empty() ? "" : ", ") + u.members[i];
        }
        out += "  any two of the " + std::to_string(u.members.size()) + " assumptions {" + members +
               "} of the choice set at " + u.where + " (" + std::to_string(u.nogoods) + " nogoods, not listed)\n";
    }
    out += "interpretations (" + std::to_string(report.interpretations.size()) + "):\n";
    for (const auto& i : report.interpretations) out += "  " + env(i) + "\n";
    return out;
}

}  // namespace qm::engine
