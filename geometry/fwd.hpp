// geometry/fwd.hpp
// Provides:   forward declarations of the geometry module's public types, so that headers can name
//             them without including each other (as atms/fwd.hpp does); the ids are complete here
//             and only here.
#pragma once
#include "qm/id.hpp"

namespace qm::geometry {
using PartId = qm::Id<struct PartTag>;    // a part of a Mechanism (mechanism.hpp)
using PlaceId = qm::Id<struct PlaceTag>;  // a place of a PlaceVocabulary (place_vocabulary.hpp)

struct Part;
struct Profile;
struct Mechanism;
struct MechanismSettings;
struct PairSpec;
struct Configuration;
struct ExternalForce;
struct ParsedMechanism;
class PairOracle;
class FclPairOracle;
struct ContactRequest;
struct ContactResult;
struct CSpaceRequest;
struct CSpaceResult;
struct Place;
struct PlaceVocabulary;
struct PlaceRequest;
struct PlaceResult;
class PlaceCache;
struct QualDirection;
}  // namespace qm::geometry
