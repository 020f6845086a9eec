// cli/place_cache_location.hpp
// Provides:   default_place_cache(), where `qm-atms --places` and `qm-atms envision` keep place
//             vocabularies when --cache is not given: $QM_PLACE_CACHE, else
//             $XDG_CACHE_HOME/qm-atms/places, else ~/.cache/qm-atms/places (empty if none is set).
#pragma once
#include <filesystem>

namespace qm::cli {
[[nodiscard]] std::filesystem::path default_place_cache();
}
