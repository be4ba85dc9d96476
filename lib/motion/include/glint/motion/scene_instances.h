// SPDX-License-Identifier: Apache-2.0
// The motion side of a scene's instances: the trajectories of its dynamic instances (and of
// its moving point sources), and the
// named targets tracking mounts point at (a TargetResolver over the instances: a static
// instance's target is where its transform puts the object's origin, a dynamic instance's
// the position of its trajectory at the time asked).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "glint/core/datetime.h"
#include "glint/core/log.h"
#include "glint/model/scene.h"
#include "glint/motion/frames.h"
#include "glint/motion/mount.h"
#include "glint/motion/trajectory.h"

namespace glint::motion {

/// The trajectories of a scene's dynamic instances, indexed like model::Scene::instances
/// (nullptr for static instances). `frame` places geodetic motion; `reference_utc` is the
/// tasks reference time. Throws glint::Error (input, at the instance) for a motion that
/// cannot be used.
std::vector<std::unique_ptr<Trajectory>> make_instance_trajectories(const model::Scene& scene,
                                                                    const SceneFrame& frame,
                                                                    const DateTime& reference_utc,
                                                                    Log log = {});

/// The trajectories of a scene's moving point sources, indexed like
/// model::Scene::point_sources (nullptr for static ones); as make_instance_trajectories.
std::vector<std::unique_ptr<Trajectory>> make_point_source_trajectories(
    const model::Scene& scene, const SceneFrame& frame, const DateTime& reference_utc,
    Log log = {});

/// Where point source `source` of a scene is at `t_s`: its static position, or its position
/// in the vehicle frame carried by `trajectory` (its entry of make_point_source_trajectories).
Vec3 point_source_position_m(const model::PointSource& source, const Trajectory* trajectory,
                             double t_s);

/// Named targets of a scene for tracking mounts: an instance is found by its name (the first
/// instance of that name, in scene order). Keeps its own copy of what it needs, so the scene
/// may go away. Thread-safe; target_position_m allocates nothing.
class SceneTargets final : public TargetResolver {
public:
    /// Throws what make_instance_trajectories throws.
    SceneTargets(const model::Scene& scene, const SceneFrame& frame, const DateTime& reference_utc,
                 Log log = {});
    std::optional<Vec3> target_position_m(std::string_view name, double t_s) const override;
    /// Number of named instances.
    std::size_t size() const noexcept { return m_targets.size(); }

private:
    struct Target {
        std::string name;
        Vec3 static_position_m;
        std::shared_ptr<const Trajectory> trajectory;  ///< dynamic instances
    };
    std::vector<Target> m_targets;
};

}  // namespace glint::motion
