// SPDX-License-Identifier: Apache-2.0
// Trajectories and named targets of a scene's instances (glint/motion/scene_instances.h).
#include "glint/motion/scene_instances.h"

#include <string>

#include "glint/core/error.h"

namespace glint::motion {
namespace {

/// Where a static transform puts the object's origin.
Vec3 static_origin(const model::StaticTransform& transform) {
    if (transform.matrix) {
        const auto& m = *transform.matrix;  // row-major 4 × 4: translation in the last column
        return {m[3], m[7], m[11]};
    }
    return to_vec3(transform.translation_m);
}

}  // namespace

std::vector<std::unique_ptr<Trajectory>> make_instance_trajectories(const model::Scene& scene,
                                                                    const SceneFrame& frame,
                                                                    const DateTime& reference_utc,
                                                                    Log log) {
    std::vector<std::unique_ptr<Trajectory>> out;
    out.reserve(scene.instances.size());
    for (const model::Instance& instance : scene.instances) {
        if (!instance.dynamic()) {
            out.emplace_back();
            continue;
        }
        try {
            out.push_back(make_trajectory(*instance.motion, frame, reference_utc, log));
        } catch (const Error& e) {
            if (!e.context().file.empty() || e.category() != ErrorCategory::input) throw;
            throw input_error("instance \"" + instance.name + "\": " + e.message(), instance.where);
        }
    }
    return out;
}

SceneTargets::SceneTargets(const model::Scene& scene, const SceneFrame& frame,
                           const DateTime& reference_utc, Log log) {
    std::vector<std::unique_ptr<Trajectory>> trajectories =
        make_instance_trajectories(scene, frame, reference_utc, log);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const model::Instance& instance = scene.instances[i];
        if (instance.name.empty()) continue;
        bool seen = false;
        for (const Target& t : m_targets) seen = seen || t.name == instance.name;
        if (seen) continue;  // the first instance of a name is its target
        m_targets.push_back({instance.name, static_origin(instance.transform),
                             std::shared_ptr<const Trajectory>(std::move(trajectories[i]))});
    }
}

std::optional<Vec3> SceneTargets::target_position_m(std::string_view name, double t_s) const {
    for (const Target& t : m_targets) {
        if (t.name != name) continue;
        if (t.trajectory) return t.trajectory->pose_at(t_s).position_m;
        return t.static_position_m;
    }
    return std::nullopt;
}

}  // namespace glint::motion
