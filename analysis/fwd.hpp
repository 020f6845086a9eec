// analysis/fwd.hpp
// Provides:   forward declarations of the analysis module's public types, so that headers can name
//             them without including each other; and the scene model's type names the analysis is
//             written in (using-declarations of scene/fwd.hpp: a SituationResult speaks of ObjectIds
//             and Directions, the scene language's own).
#pragma once
#include "scene/fwd.hpp"
#include <cstdint>

namespace qm::analysis {
using scene::Cause;
using scene::CauseId;
using scene::Contact;
using scene::CornerSides;
using scene::Direction;
using scene::DirectionPattern;
using scene::Force;
using scene::Linkage;
using scene::Motion;
using scene::Object;
using scene::ObjectId;
using scene::PatternSlot;
using scene::QueryFact;
using scene::Scene;
using scene::Sign;
using scene::Situation;
using scene::Surface;
using scene::SurfaceId;

enum class Granularity : std::uint8_t;
struct WhyLimits;
struct AnalysisOptions;
struct Freedom;
struct ObjectMotion;
struct ChainMotions;
struct SituationResult;
struct Derivation;
struct Exclusion;
struct WhyAnswer;
class Analysis;
struct SceneItem;
class SceneFacts;
}  // namespace qm::analysis
