// engine/program_cache.hpp
// Provides:   load_programs_cached(): load_programs() (rule_compiler.hpp) with the compiled program
//             kept on disk, so that a run whose rule files have not changed since an earlier run
//             does not read, check and compile them again (issue 15 item 1, docs/perf/startup.md).
//             encode_program()/decode_program(): the on-disk form of a LoadedProgram, exposed for tests.
// Contract:   a hit gives exactly the LoadedProgram a load would give (the same rules, values in the
//             same order, locations and citations), or the cache is not used. An entry is found by a
//             hash of what the load depends on besides the files' contents: a format version, the
//             code that wrote it (the GNU build id of the loaded object holding the engine: a
//             rebuild that changes any code misses; without a build id there is no cache), the builtin set (names, kinds, arities in
//             id order), the law options that change what loads (citations required, direction
//             arities) and the paths as given. The entry holds every file the load read (those named
//             and those they include) with its whole text; a hit needs each to read back byte for
//             byte the same, so an edited rule file (or an include) always misses. Only a load with
//             no diagnostic at all is stored, so a hit has none to give (which is also why the
//             scene's name, used only in messages, is not part of the key).
// Failure:    the cache never fails a load: a missing, unreadable, read-only, truncated, corrupt
//             (checksum), foreign (magic, version) or stale entry is a miss, a store that cannot be
//             written is skipped. Writes go to a temporary file renamed into place, so concurrent
//             processes see a whole entry or none. The folder keeps at most max_entries entries
//             (the least recently written are removed after a store).
// Knows nothing of the ATMS.
#pragma once
#include "engine/rule_compiler.hpp"
#include <filesystem>
#include <optional>
#include <span>
#include <string>

namespace qm::engine {

inline constexpr std::size_t program_cache_max_entries = 32;

// As load_programs(); with an empty cache_dir it is load_programs().
[[nodiscard]] std::optional<LoadedProgram> load_programs_cached(std::span<const std::string> paths, Diagnostics& diagnostics,
                                                                const LawCheckOptions& laws,
                                                                const std::filesystem::path& cache_dir);

// One file a load read: its name as in source locations, its text.
struct CachedSource {
    std::string file;
    std::string text;
};

// The entry's bytes: header (magic, version, payload length, checksum), then the key, the sources
// and the program.
[[nodiscard]] std::string encode_program(const std::string& key, const std::vector<CachedSource>& sources,
                                         const LoadedProgram& program, const BuiltinRegistry& builtins = default_builtins());
struct DecodedProgram {
    std::vector<CachedSource> sources;
    LoadedProgram program;
};
// nullopt unless bytes is a whole, intact entry written for key whose ids are all in range.
[[nodiscard]] std::optional<DecodedProgram> decode_program(std::string_view bytes, const std::string& key,
                                                           const BuiltinRegistry& builtins = default_builtins());

}  // namespace qm::engine
