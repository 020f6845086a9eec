// envision/laws.cpp
#include "envision/laws.hpp"
#include <algorithm>
#include <vector>

namespace qm::envision {

std::optional<Laws> Laws::load(const std::filesystem::path& folder, Diagnostics& diagnostics) {
    std::error_code ec;
    std::vector<std::string> files;
    if (std::filesystem::is_directory(folder, ec))
        for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
            if (entry.is_regular_file() && entry.path().extension() == ".rules") files.push_back(entry.path().string());
    if (files.empty()) {
        diagnostics.error({folder.string(), 1, 1}, "expected a folder of .rules files (the envisioner's laws), but found none here");
        return std::nullopt;
    }
    std::sort(files.begin(), files.end());
    return load_files(files, folder, diagnostics);
}

std::optional<Laws> Laws::load_files(std::span<const std::string> files, const std::filesystem::path& folder, Diagnostics& diagnostics) {
    auto program = engine::load_programs(files, diagnostics);
    if (!program) return std::nullopt;
    return Laws(std::move(*program), folder);
}

std::unique_ptr<engine::Engine> Laws::engine() const {
    return std::make_unique<engine::Engine>(program_.program, program_.values);
}

}  // namespace qm::envision
