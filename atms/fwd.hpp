// atms/fwd.hpp
// Provides:   forward declarations of the ATMS module's public types, so headers can name them
//             without including each other (clasp's claspfwd.h).
#pragma once
#include "atms/ids.hpp"

namespace qm::atms {
class Environment;
class EnvironmentTable;
class NogoodDatabase;
struct Justification;
struct Explanation;
class Consumer;
class Atms;
struct RefutationOptions;
struct Refutation;
struct ChoiceSetIndex;
struct ChoiceSetGroup;
namespace detail {
struct WeaveScratch;
}
}  // namespace qm::atms
