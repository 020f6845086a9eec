// geometry/mechanism.cpp: lookups on the checked metric scene model.
#include "geometry/mechanism.hpp"

#include <algorithm>

namespace qm::geometry {

std::optional<PartId> Mechanism::find_part(std::string_view n) const {
    for (std::uint32_t i = 0; i < parts.size(); ++i)
        if (parts[PartId{i}].name == n) return PartId{i};
    return std::nullopt;
}

std::optional<std::size_t> Mechanism::shaft_of(PartId p) const {
    for (std::size_t i = 0; i < linkages.size(); ++i)
        if (std::find(linkages[i].parts.begin(), linkages[i].parts.end(), p) != linkages[i].parts.end()) return i;
    return std::nullopt;
}

bool Mechanism::same_shaft(PartId a, PartId b) const {
    if (a == b) return true;
    const auto sa = shaft_of(a);
    return sa && sa == shaft_of(b);
}

void Mechanism::error(Diagnostics& diags, const SourceLocation& w, std::string message) const {
    diags.error(w, std::move(message), source ? source->line_of(w) : std::string_view());
}

}  // namespace qm::geometry
