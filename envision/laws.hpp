// envision/laws.hpp
// Provides:   Laws, the envisioner's rule program (every *.rules file directly in a folder, by
//             default rules/clock/, in name order), read, checked and compiled once
//             (engine/rule_folder.hpp), and fresh engines over it: one for a chain's state
//             space, one per state for its transitions. Each of these two gets only the rules
//             that can matter for it (a slice, engine/program_slice.hpp, of the one spec read,
//             with the facts the bridge gives it and the conclusions the driver reads,
//             bridge/clock_vocabulary.hpp): a state's engine is small, and it is made hundreds
//             of times.
// Ownership:  Laws holds the compiled programs (engine/shared_program.hpp) and their pristine value
//             tables (ValueTable::share), both read only: each engine made shares the program and
//             gets a copy of the table that owns only the values the engine adds, so engines are
//             independent (and may run in different threads) and cheap to make.
// Errors:     a folder that gives no .rules file, or rule files with errors: located diagnostics
//             (engine/rule_folder.hpp), and load() returns nothing.
// Knows nothing of any law: which laws there are is the folder's business.
#pragma once
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "qm/diagnostics.hpp"
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>

namespace qm::envision {

class Laws {
public:
    [[nodiscard]] static std::optional<Laws> load(const std::filesystem::path& folder, Diagnostics& diagnostics);
    // Exactly these files (e.g. a folder's files but one, to see what that law changes).
    [[nodiscard]] static std::optional<Laws> load_files(std::span<const std::string> files, const std::filesystem::path& folder,
                                                        Diagnostics& diagnostics);
    // Over every law (for tests and questions about any law).
    [[nodiscard]] std::unique_ptr<engine::Engine> engine() const;
    [[nodiscard]] std::unique_ptr<engine::Engine> state_space_engine() const;
    [[nodiscard]] std::unique_ptr<engine::Engine> state_engine() const;
    [[nodiscard]] const std::filesystem::path& folder() const noexcept { return folder_; }

private:
    struct Program {
        std::shared_ptr<const engine::SharedProgram> program;
        engine::ValueTable values;  // shared (ValueTable::share)
        explicit Program(engine::LoadedProgram loaded);
        [[nodiscard]] std::unique_ptr<engine::Engine> engine() const;
    };
    Laws(Program all, Program space, Program state, std::filesystem::path folder)
        : all_(std::move(all)), space_(std::move(space)), state_(std::move(state)), folder_(std::move(folder)) {}
    Program all_, space_, state_;
    std::filesystem::path folder_;
};

}  // namespace qm::envision
