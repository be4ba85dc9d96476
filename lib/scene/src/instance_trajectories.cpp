// SPDX-License-Identifier: Apache-2.0
// make_instance_trajectories: one glint::motion trajectory per dynamic instance of a scene,
// errors placed at the motion's own element when it has one, else at the instance.
#include <string>

#include "glint/core/error.h"
#include "glint/scene/geometry_scene.h"

namespace glint::scene {

std::vector<std::unique_ptr<motion::Trajectory>> make_instance_trajectories(
    const model::Scene& scene, const motion::SceneFrame& frame, const DateTime& reference_utc,
    Log log) {
    std::vector<std::unique_ptr<motion::Trajectory>> out;
    out.reserve(scene.instances.size());
    for (const model::Instance& instance : scene.instances) {
        if (!instance.dynamic()) {
            out.emplace_back();
            continue;
        }
        try {
            out.push_back(motion::make_trajectory(*instance.motion, frame, reference_utc, log));
        } catch (const Error& e) {
            if (!e.context().file.empty() || e.category() != ErrorCategory::input) throw;
            throw input_error("instance \"" + instance.name + "\": " + e.message(), instance.where);
        }
    }
    return out;
}

}  // namespace glint::scene
