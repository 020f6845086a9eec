// geometry/detail/metric_keywords.cpp: the keyword positions of metric scenes (metric_keywords.hpp).
#include "geometry/detail/metric_keywords.hpp"
#include "geometry/part_generators.hpp"

namespace qm::geometry::detail {
namespace {

std::vector<std::string> with_generators(std::vector<std::string> words) {
    for (const Generator& g : generators()) words.emplace_back(g.name);
    return words;
}

std::string generator_list() {
    std::string out;
    for (const Generator& g : generators()) out += (out.empty() ? "" : ", ") + std::string(g.name);
    return out;
}

}  // namespace

const std::vector<std::string>& every_keyword() {
    static const std::vector<std::string> words = with_generators(
        {"defmechanism", "settings", "parts", "pairs", "linkages", "forces", "polygon", "circle", "profile", "at", "turn", "fixed",
         "rotation", "translation", "symmetry", "limits", "line", "arc", "ccw", "cw", "grid", "window", "torque", "direction", "when"});
    return words;
}

const KeywordSlot& defmechanism_keywords() {
    static const KeywordSlot slot{"'Defmechanism'", {"Defmechanism"}, &every_keyword()};
    return slot;
}

const KeywordSlot& section_keywords() {
    static const KeywordSlot slot{"a section keyword (Settings, Parts, Pairs, Linkages, Forces) or ')'",
                                  {"Settings", "Parts", "Pairs", "Linkages", "Forces"}, &every_keyword()};
    return slot;
}

const KeywordSlot& part_item_keywords() {
    static const KeywordSlot slot{
        "a part item (polygon, circle, profile, at, turn, fixed, rotation, translation, symmetry) or a generator (" + generator_list() + ")",
        with_generators({"polygon", "circle", "profile", "at", "turn", "fixed", "rotation", "translation", "symmetry"}), &every_keyword()};
    return slot;
}

const KeywordSlot& step_keywords() {
    static const KeywordSlot slot{"a step (line x y) or (arc x y cx cy ccw|cw)", {"line", "arc"}, &every_keyword()};
    return slot;
}

const KeywordSlot& limits_keywords() {
    static const KeywordSlot slot{"(limits lo hi)", {"limits"}, &every_keyword()};
    return slot;
}

const KeywordSlot& sense_keywords() {
    static const KeywordSlot slot{"ccw or cw", {"ccw", "cw"}, &every_keyword()};
    return slot;
}

const KeywordSlot& pair_item_keywords() {
    static const KeywordSlot slot{"a pair setting (grid n0 n1) or (window part lo hi)", {"grid", "window"}, &every_keyword()};
    return slot;
}

const KeywordSlot& force_item_keywords() {
    static const KeywordSlot slot{"a force item (torque +|-), (direction dx dy), (at x y) or (when lo hi)",
                                  {"torque", "direction", "at", "when"}, &every_keyword()};
    return slot;
}

}  // namespace qm::geometry::detail
