// SPDX-License-Identifier: Apache-2.0
// A scene's motion over a run (glint/scene/scene_motion.h).
#include "glint/scene/scene_motion.h"

#include <string>

#include "glint/core/error.h"
#include "glint/motion/scene_instances.h"

namespace glint::scene {

SceneMotion SceneMotion::make(const model::Scene& scene, const motion::SceneFrame& frame,
                              const DateTime& reference_utc, Log log) {
    SceneMotion motion;
    motion.m_trajectories =
        motion::make_instance_trajectories(scene, frame, reference_utc, std::move(log));
    for (const model::Instance& instance : scene.instances) {
        motion.m_moves = motion.m_moves || instance.dynamic();
    }
    return motion;
}

GeometryScene SceneMotion::build(const model::Scene& scene, const BuildOptions& options,
                                 Log log) const {
    if (scene.instances.size() != m_trajectories.size()) {
        throw internal_error("the scene has " + std::to_string(scene.instances.size()) +
                             " instances, its motion was made for " +
                             std::to_string(m_trajectories.size()));
    }
    return GeometryScene::build(scene, m_trajectories, options, std::move(log));
}

}  // namespace glint::scene
