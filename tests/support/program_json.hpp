// tests/support/program_json.hpp: reads the JSON the program prints, with nlohmann/json, strictly:
// a syntax error, text after the value or a key repeated in one object gives a discarded value.
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

namespace qm::test {

// Json: nlohmann::json (an object's keys in name order) or nlohmann::ordered_json (in the order
// read). nlohmann keeps the last of repeated keys silently, so each object's keys are counted as
// read: an object smaller than its count had one twice.
template <class Json = nlohmann::json>
[[nodiscard]] Json read_json(std::string_view text) {
    using Event = typename Json::parse_event_t;
    std::vector<std::size_t> keys;  // keys read so far in each object being read
    bool repeated = false;
    const auto count = [&](int /*depth*/, Event event, Json& parsed) {
        if (event == Event::object_start) {
            keys.push_back(0);
        } else if (event == Event::key) {
            ++keys.back();
        } else if (event == Event::object_end) {
            repeated = repeated || parsed.size() != keys.back();
            keys.pop_back();
        }
        return true;
    };
    Json value = Json::parse(text, count, /*allow_exceptions=*/false);
    return repeated ? Json(Json::value_t::discarded) : value;
}

}  // namespace qm::test
