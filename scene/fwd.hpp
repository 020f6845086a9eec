// scene/fwd.hpp
// Provides:   forward declarations of the scene language's public types (the checked model of
//             scene/scene.hpp, the reader's results of scene/scene_parser.hpp), so that headers
//             can name them without including each other; the ids and Direction are complete.
#pragma once
#include "qm/id.hpp"
#include <cstdint>
#include <vector>

namespace qm::scene {
enum class Sign : std::int8_t;
using Direction = std::vector<Sign>;
struct PatternSlot;
using DirectionPattern = std::vector<PatternSlot>;
using ObjectId = Id<struct ObjectTag>;
using SurfaceId = Id<struct SurfaceTag>;
using CauseId = Id<struct CauseTag>;
struct CornerSides;
struct Surface;
struct Linkage;
struct Object;
struct Cause;
struct Force;
struct Contact;
struct Motion;
struct Situation;
struct Scene;
struct QueryFact;
struct ParsedScene;
namespace ast {
struct Scenario;
}
}  // namespace qm::scene
