// cli/explore_assets.hpp
// Provides:   explore_assets(), the files of the explorer page (cli/explore/: index.html with a
//             @QM_DATA@ placeholder for the data blob, explore.js, explore.css), compiled into
//             the executable by cli/explore/embed_assets.cmake so that the page is written
//             without looking for files at run time.
// Ownership:  static storage.
#pragma once
#include <span>
#include <string_view>

namespace qm::cli {

struct ExploreAsset {
    std::string_view name;
    std::string_view text;
};

[[nodiscard]] std::span<const ExploreAsset> explore_assets() noexcept;

}  // namespace qm::cli
