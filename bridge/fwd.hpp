// bridge/fwd.hpp: forward declarations of the bridge module (geometry -> facts): its contacts half
// (scene_at_config.hpp: the Alex scene model at a configuration) and its place-vocabulary half
// (place_facts.hpp, place_forces.hpp: premises for the envisioner's laws).
#pragma once

namespace qm::bridge {
// Contacts half.
class SceneAtConfig;
// Place-vocabulary half.
struct PlaceForce;
struct PairForces;
struct PairPlaces;
struct PlaceFactOptions;
}  // namespace qm::bridge
