// envision/laws.cpp
#include "envision/laws.hpp"
#include "bridge/clock_vocabulary.hpp"
#include "engine/program_slice.hpp"
#include "engine/rule_spec_reader.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <set>
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
    auto all = engine::load_programs(files, diagnostics);  // every error of every file, once
    if (!all) return std::nullopt;
    engine::ProgramSpec spec;
    engine::read_rule_files(files, spec, diagnostics);
    auto slice = [&](std::initializer_list<const char*> in, std::initializer_list<const char*> out) {
        const std::set<std::string> inputs(in.begin(), in.end()), outputs(out.begin(), out.end());
        auto p = engine::compile_program(engine::slice_program(spec, inputs, outputs), diagnostics);
        if (!p) throw InternalError("a slice of a program that compiles does not compile");
        return std::move(*p);
    };
    namespace c = bridge::clock;
    auto space = slice(c::state_space_inputs, c::state_space_outputs);
    auto state = slice(c::state_inputs, c::state_outputs);
    return Laws(Program(std::move(*all)), Program(std::move(space)), Program(std::move(state)), folder);
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
