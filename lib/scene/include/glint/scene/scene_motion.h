// SPDX-License-Identifier: Apache-2.0
// A scene's motion over a run: the trajectories of its dynamic instances, made once before the
// first capture, and the Embree scene of a capture window built from them (once for a scene
// where nothing moves, per capture window where something does).
#pragma once

#include <memory>
#include <vector>

#include "glint/core/datetime.h"
#include "glint/core/log.h"
#include "glint/model/scene.h"
#include "glint/motion/frames.h"
#include "glint/motion/trajectory.h"
#include "glint/scene/geometry_scene.h"

namespace glint::scene {

/// The trajectories of a scene's dynamic instances. Immutable once made.
class SceneMotion {
public:
    /// The motion of `scene`'s instances, geodetic motion placed by `frame`, times relative
    /// to the tasks reference time `reference_utc` (motion::make_instance_trajectories).
    /// Throws glint::Error (input, at the instance) for a motion that cannot be used.
    static SceneMotion make(const model::Scene& scene, const motion::SceneFrame& frame,
                            const DateTime& reference_utc, Log log = {});

    /// Whether some instance moves: the Embree scene then differs per capture window.
    bool moves() const noexcept { return m_moves; }

    /// The Embree scene of `scene` (the scene it was made for) over `options.window`
    /// (GeometryScene::build). Throws glint::Error as GeometryScene::build, and internal for
    /// a scene with another number of instances than the one it was made for.
    GeometryScene build(const model::Scene& scene, const BuildOptions& options, Log log = {}) const;

private:
    std::vector<std::unique_ptr<motion::Trajectory>> m_trajectories;  ///< like scene.instances
    bool m_moves = false;
};

}  // namespace glint::scene
