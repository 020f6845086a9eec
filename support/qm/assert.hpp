// support/qm/assert.hpp
// Provides:   InternalError (a bug or misuse of an API, exit status 1), QM_ASSERT (internal
//             invariants, active in debug and test builds) and QM_REQUIRE (API preconditions,
//             always active, so bad use of a public API is a clear error, never UB).
// Knows nothing of any module.
#pragma once
#include <stdexcept>
#include <string>

namespace qm {

// Thrown for internal failures and for violated API preconditions. main() maps it to exit 1.
class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

namespace detail {
[[noreturn]] inline void fail(const char* kind, const char* expr, const std::string& msg,
                              const char* file, int line) {
    throw InternalError(std::string(kind) + " failed: " + expr + (msg.empty() ? "" : " (" + msg + ")") +
                        " at " + file + ":" + std::to_string(line));
}
}  // namespace detail
}  // namespace qm

// Precondition of a public API: always checked.
#define QM_REQUIRE(cond, msg) \
    ((cond) ? static_cast<void>(0) : ::qm::detail::fail("precondition", #cond, (msg), __FILE__, __LINE__))

#if defined(QM_ENABLE_ASSERTS)
#define QM_ASSERT(cond, msg) \
    ((cond) ? static_cast<void>(0) : ::qm::detail::fail("assertion", #cond, (msg), __FILE__, __LINE__))
#else
#define QM_ASSERT(cond, msg) static_cast<void>(0)
#endif
