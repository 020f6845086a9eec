// envision/fwd.hpp: forward declarations of the envisioner.
#pragma once

namespace qm::envision {
struct Chain;
struct State;
struct Transition;
struct ChainEnvisionment;
struct Envisionment;
struct EnvisionOptions;
class Laws;
}  // namespace qm::envision
