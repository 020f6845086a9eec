// cli/exit_owned.hpp
// Provides:   ExitOwned<T>, the owner of a command's last big object (the analysis of a scene),
//             which lives until the process ends: its destructor leaves the memory to the operating
//             system, which takes the whole heap back at exit at once, instead of freeing it node by
//             node (5 % of the instructions of a thesis Alex scene, docs/perf/startup.md).
// Ownership:  holds a T on the heap; in a sanitized build (QM_SANITIZED_BUILD) the destructor deletes
//             it as usual, so that LeakSanitizer still checks every other allocation.
// Pre:        only for an object that lives until the command returns to main, once per process
//             (never in a loop, never in a library function called again).
#pragma once
#include <utility>

namespace qm::cli {

template <class T>
class ExitOwned {
public:
    explicit ExitOwned(T value) : value_(new T(std::move(value))) {}
    ~ExitOwned() {
#ifdef QM_SANITIZED_BUILD
        delete value_;
#endif
    }
    ExitOwned(const ExitOwned&) = delete;
    ExitOwned& operator=(const ExitOwned&) = delete;
    [[nodiscard]] T& operator*() const noexcept { return *value_; }
    [[nodiscard]] T* operator->() const noexcept { return value_; }

private:
    T* value_;
};

}  // namespace qm::cli
