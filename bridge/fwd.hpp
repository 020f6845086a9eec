// bridge/fwd.hpp: forward declarations of the bridge module (geometry -> facts).
#pragma once

namespace qm::bridge {
struct PlaceForce;
struct PairForces;
struct PairPlaces;
struct PlaceFactOptions;
}  // namespace qm::bridge
