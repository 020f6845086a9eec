// engine/json_writer.cpp
#include "engine/json_writer.hpp"
#include "qm/json.hpp"

namespace qm::engine {
namespace {

std::string env_list(const std::vector<EnvText>& envs) {
    std::string out = "[";
    for (std::size_t i = 0; i < envs.size(); ++i) {
        if (i > 0) out += ", ";
        out += "[";
        for (std::size_t k = 0; k < envs[i].size(); ++k) {
            if (k > 0) out += ", ";
            out += json_string(envs[i][k]);
        }
        out += "]";
    }
    return out + "]";
}

std::string string_list(const std::vector<std::string>& xs) {
    std::string out = "[";
    for (std::size_t i = 0; i < xs.size(); ++i) out += (i > 0 ? ", " : "") + json_string(xs[i]);
    return out + "]";
}

std::string derivation_list(const std::vector<Derivation>& ds) {
    std::string out = "[";
    for (std::size_t i = 0; i < ds.size(); ++i) {
        if (i > 0) out += ", ";
        out += "{\"environment\": " + string_list(ds[i].environment) + ", \"steps\": [";
        for (std::size_t k = 0; k < ds[i].steps.size(); ++k) {
            const WhyStep& s = ds[i].steps[k];
            if (k > 0) out += ", ";
            out += "{\"fact\": " + json_string(s.consequent) + ", \"informant\": " + json_string(s.informant) +
                   ", \"binding\": " + string_list(s.binding) + ", \"antecedents\": " + string_list(s.antecedents) + ", \"not\": " + string_list(s.absent) + "}";
        }
        out += "]}";
    }
    return out + "]";
}

}  // namespace

std::string to_json(const RunReport& report) {
    std::string out = "{\"facts\": [";
    for (std::size_t i = 0; i < report.facts.size(); ++i) {
        if (i > 0) out += ", ";
        out += "{\"fact\": " + json_string(report.facts[i].fact) + ", \"label\": " + env_list(report.facts[i].label) + "}";
    }
    out += "], \"nogoods\": " + env_list(report.nogoods);
    out += ", \"interpretations\": " + env_list(report.interpretations) + "}";
    return out;
}

std::string to_json(const Why& why) {
    const char* status = why.status == Why::Status::holds       ? "holds"
                         : why.status == Why::Status::ruled_out ? "ruled-out"
                                                                : "unsupported";
    return "{\"fact\": " + json_string(why.fact) + ", \"status\": \"" + status +
           "\", \"derivations\": " + derivation_list(why.derivations) + ", \"nogoods\": " + derivation_list(why.nogoods) + "}";
}

}  // namespace qm::engine
