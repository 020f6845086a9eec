// cli/resource_limits.hpp
// Provides:   the resource limits of the commands that run laws or rule programs (`qm-atms
//             SCENE.def`, `qm-atms run`; `qm-atms envision` takes --max-memory): ResourceLimits, the
//             options that set them (--max-facts N, --max-environments N, --max-memory SIZE),
//             declared by declare_limit_options() (or --max-memory alone, declare_memory_option())
//             and checked by read_limit_options(), their usage text, apply_memory_limit() (the
//             process' address space, RLIMIT_AS), and the message a reached limit ends a run with
//             (the envisioner's state limit, --max-states, included):
//               grow.rules:2:1: error: fact limit 500000 reached while firing rule 'grow'; raise it with --max-facts
//               qm-atms: error: memory limit 11.7G reached while running grow.rules; raise it with --max-memory
//             (exit 2: a program or scene that needs more is bad input at these settings; nothing
//             is written to standard output).
// Defaults:   chosen so that runaway programs (a rule that counts up for ever) stop within
//             seconds while the bundled scenes, rule programs and benchmarks stay far below them
//             (docs/PERFORMANCE.md, "resource limits at their defaults"); memory: half the
//             machine's.
// Ownership:  values; apply_memory_limit() changes the process (call it once, from main's commands).
#pragma once
#include "engine/run_options.hpp"
#include "qm/limit_reached.hpp"
#include "command_options.hpp"
#include <cstdint>
#include <optional>
#include <string>

namespace qm::cli {

struct ResourceLimits {
    static constexpr std::size_t default_max_facts = 500000;
    static constexpr std::size_t default_max_environments = 1000000;
    std::size_t max_facts = default_max_facts;
    std::size_t max_environments = default_max_environments;
    std::uint64_t max_memory = default_max_memory();  // bytes of address space
    struct Given {  // the options' texts as given (a second one is an error)
        std::optional<std::string> facts, environments, memory;
    } given;

    // Half the machine's physical memory (4 GB if it cannot be found).
    [[nodiscard]] static std::uint64_t default_max_memory();
    [[nodiscard]] engine::EngineLimits engine_limits() const { return {max_facts, max_environments}; }
};

// Declares the limit options on a command's line, into limits.given.
void declare_limit_options(CommandOptions& options, ResourceLimits& limits);
// Declares --max-memory alone, for a command whose other limits are its own (envision's --max-states).
void declare_memory_option(CommandOptions& options, ResourceLimits& limits);
// After options.parse(): the values given, checked, into limits; nullopt, or 2 after reporting a bad one.
[[nodiscard]] std::optional<int> read_limit_options(const CommandOptions& options, ResourceLimits& limits, std::ostream& err);

// The options' lines for a usage text: all three, or --max-memory's alone.
[[nodiscard]] std::string limits_usage();
[[nodiscard]] const char* memory_usage() noexcept;

// Limits this process' address space to limits.max_memory (RLIMIT_AS; not under AddressSanitizer,
// which reserves terabytes of address space for its shadow memory), so that an allocation beyond it
// fails with std::bad_alloc, reported by report_memory_limit().
void apply_memory_limit(const ResourceLimits& limits);

// The message of a reached limit (`doing`: what the command was doing, when the limit does not say).
[[nodiscard]] std::string limit_message(const LimitReached& limit, const std::string& doing);
// The message of a std::bad_alloc under the memory limit apply_memory_limit() set; nullopt when none was set.
[[nodiscard]] std::optional<std::string> memory_limit_message(const std::string& doing);

// "11.7 GB", "512 MB", "900 bytes".
[[nodiscard]] std::string size_text(std::uint64_t bytes);

}  // namespace qm::cli
