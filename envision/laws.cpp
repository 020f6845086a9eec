// envision/laws.cpp
#include "envision/laws.hpp"
#include "bridge/clock_vocabulary.hpp"
#include "engine/rule_folder.hpp"
#include <set>

namespace qm::envision {

std::optional<Laws> Laws::load(const std::filesystem::path& folder, Diagnostics& diagnostics) {
    const std::vector<std::string> files = engine::rule_folder_files(folder, diagnostics);
    if (files.empty()) return std::nullopt;
    return load_files(files, folder, diagnostics);
}

std::optional<Laws> Laws::load_files(std::span<const std::string> files, const std::filesystem::path& folder, Diagnostics& diagnostics) {
    auto laws = engine::load_rule_files(files, diagnostics);  // every error of every file, once
    if (!laws) return std::nullopt;
    auto slice = [&](std::initializer_list<const char*> in, std::initializer_list<const char*> out) {
        return engine::compile_slice(*laws, std::set<std::string>(in.begin(), in.end()), std::set<std::string>(out.begin(), out.end()));
    };
    namespace c = bridge::clock;
    auto space = slice(c::state_space_inputs, c::state_space_outputs);
    auto state = slice(c::state_inputs, c::state_outputs);
    return Laws(Program(std::move(laws->compiled)), Program(std::move(space)), Program(std::move(state)), folder);
}

Laws::Program::Program(engine::LoadedProgram loaded)
    : program(engine::share_program(std::move(loaded.program))), values(std::move(loaded.values)) {
    values.share();
}

std::unique_ptr<engine::Engine> Laws::Program::engine() const { return std::make_unique<engine::Engine>(program, values); }

std::unique_ptr<engine::Engine> Laws::engine() const { return all_.engine(); }
std::unique_ptr<engine::Engine> Laws::state_space_engine() const { return space_.engine(); }
std::unique_ptr<engine::Engine> Laws::state_engine() const { return state_.engine(); }

}  // namespace qm::envision
