// support/qm/file_text.hpp
// Provides:   read_file_text(), the whole text of a file for the project's readers (Alex scenes,
//             metric scenes, rule files), or why it cannot be had, in words a user can act on:
//             `no such file`, `it is a directory, not a file`, `permission denied`, ... (an input
//             that cannot be read is bad input, exit 2; an ifstream opens a directory and reads
//             nothing, so a directory is named as such, not as `empty input`).
// Ownership:  returns values.
#pragma once
#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace qm {

struct FileText {
    std::optional<std::string> text;  // the file's bytes; empty when it could not be read
    std::string why_not;              // when !text: why, e.g. "it is a directory, not a file"
};

[[nodiscard]] inline FileText read_file_text(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (ec || !fs::exists(st)) {
        // status() fails with ENOENT for a missing file and with e.g. EACCES for a folder on the way.
        return {std::nullopt, ec && ec != std::errc::no_such_file_or_directory ? ec.message() : "no such file"};
    }
    if (fs::is_directory(st)) return {std::nullopt, "it is a directory, not a file"};
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) return {std::nullopt, errno != 0 ? std::strerror(errno) : "it cannot be opened"};
    std::string text;
    if (fs::is_regular_file(st))
        if (const std::uintmax_t n = fs::file_size(path, ec); !ec) text.reserve(static_cast<std::size_t>(n));
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (in.bad()) return {std::nullopt, "reading it failed"};
    return {std::move(text), {}};
}

}  // namespace qm
