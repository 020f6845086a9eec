// bridge/detail/alex_scene_builder.hpp
// Provides:   AlexSceneBuilder, which assembles the Alex scene model of a mechanism at one
//             configuration item by item, as bridge/scene_at_config.hpp's table says: objects from
//             parts (a shaft's parts as one, Def 21), surfaces and corners from contact features
//             (Defs 16-18), contacts (Def 19), forces with their causes; and finish(), which puts
//             the surfaces in the order the scene model's invariants ask (faces before corners).
// Ownership:  holds references to the mechanism and configuration, which must outlive it; the
//             scene it builds is moved out by finish().
// Knows nothing of the ATMS, the engine or the laws. Internal to the bridge.
#pragma once
#include "geometry/contact_detection.hpp"
#include "geometry/mechanism.hpp"
#include "scene/scene.hpp"
#include <map>
#include <optional>
#include <string>

namespace qm::bridge::detail {

class AlexSceneBuilder {
public:
    AlexSceneBuilder(const geometry::Mechanism& m, const geometry::Configuration& q);

    // The contacts of one kinematic pair (its features as surfaces or corners), located at the pair.
    void add_contacts(const geometry::PairSpec& pair, const geometry::ContactResult& r);
    // The external forces acting at the configuration, located at their declarations.
    void add_forces();
    // The finished scene, its surfaces in the order of the invariants of scene/scene.hpp.
    [[nodiscard]] scene::Scene finish() &&;

private:
    [[nodiscard]] double zero_length(const geometry::Part& p) const;
    [[nodiscard]] scene::Object object_for(geometry::PartId p) const;
    scene::CauseId cause(const std::string& name);
    // A feature touching `other`: its origin direction is resolved against the contact's normal
    // (geometry::origin_direction_at_contact) when the contact has one normal (a face, or a corner
    // against a face); against another corner (Def 26) it is the plain origin direction.
    scene::SurfaceId feature(geometry::PartId p, const geometry::ContactFeature& f, const geometry::ContactFeature& other, double tol,
                             const SourceLocation& where);
    // `contact_normal`: the normal the origin is resolved against; none for a corner's sides.
    scene::SurfaceId surface(geometry::PartId p, const geometry::ContactFeature& f, const std::optional<Eigen::Vector2d>& contact_normal,
                             double tol, const SourceLocation& where);
    scene::SurfaceId corner(geometry::PartId p, const geometry::ContactFeature& f, const std::optional<Eigen::Vector2d>& contact_normal,
                            double tol, const SourceLocation& where);
    // Def 17's origin direction of part p at `point`, resolved against the contact's normal if any.
    [[nodiscard]] geometry::QualDirection origin(geometry::PartId p, const Eigen::Vector2d& point,
                                                 const std::optional<Eigen::Vector2d>& contact_normal, double tol) const;
    // The surface s under the first free name of base, base-2, ...; or the existing one of those
    // names that equals s in everything but its name.
    scene::SurfaceId named(scene::Surface s, const std::string& base);

    const geometry::Mechanism& m_;
    const geometry::Configuration& q_;
    scene::Scene scene_;
    std::map<std::uint32_t, scene::ObjectId> object_;  // PartId -> its object
};

}  // namespace qm::bridge::detail
