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

/// The trajectory of a scene element's motion, nullptr when it has none; a motion error
/// without a place is placed at the element.
template <class Element>
std::unique_ptr<Trajectory> trajectory_of(const Element& element, const char* kind,
                                          const SceneFrame& frame, const DateTime& reference_utc,
                                          Log log) {
    if (!element.dynamic()) return nullptr;
    try {
        return make_trajectory(*element.motion, frame, reference_utc, log);
    } catch (const Error& e) {
        if (!e.context().file.empty() || e.category() != ErrorCategory::input) throw;
        throw input_error(std::string(kind) + " \"" + element.name + "\": " + e.message(),
                          element.where);
    }
}

}  // namespace

std::vector<std::unique_ptr<Trajectory>> make_instance_trajectories(const model::Scene& scene,
                                                                    const SceneFrame& frame,
                                                                    const DateTime& reference_utc,
                                                                    Log log) {
    std::vector<std::unique_ptr<Trajectory>> out;
    out.reserve(scene.instances.size());
    for (const model::Instance& instance : scene.instances) {
        out.push_back(trajectory_of(instance, "instance", frame, reference_utc, log));
    }
    return out;
}

std::vector<std::unique_ptr<Trajectory>> make_point_source_trajectories(
    const model::Scene& scene, const SceneFrame& frame, const DateTime& reference_utc, Log log) {
    std::vector<std::unique_ptr<Trajectory>> out;
    out.reserve(scene.point_sources.size());
    for (const model::PointSource& source : scene.point_sources) {
        out.push_back(trajectory_of(source, "point source", frame, reference_utc, log));
    }
    return out;
}

Vec3 point_source_position_m(const model::PointSource& source, const Trajectory* trajectory,
                             double t_s) {
    const Vec3 local = to_vec3(source.position_m);
    if (trajectory == nullptr) return local;
    const Pose pose = trajectory->pose_at(t_s);
    return pose.position_m + rotate(normalized(pose.orientation), local);
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
