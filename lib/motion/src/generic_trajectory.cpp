// SPDX-License-Identifier: Apache-2.0
// The GenericMotion trajectory: the `.ppd` entries converted once to scene ENU positions and
// vehicle → scene quaternions, then position interpolated linearly and orientation
// spherically (slerp) between the two entries around the requested time, clamped outside
// the span of the entries (one warning).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "glint/motion/euler.h"
#include "trajectory_parts.h"

namespace glint::motion {

namespace {

class GenericTrajectory final : public Trajectory {
public:
    GenericTrajectory(std::vector<double> times, std::vector<Vec3> positions,
                      std::vector<Quaternion> orientations, ErrorContext where, Log log)
        : m_times(std::move(times)),
          m_positions(std::move(positions)),
          m_orientations(std::move(orientations)),
          m_where(std::move(where)),
          m_notice(std::move(log)) {}

    Pose pose_at(double t_s) const override {
        if (m_times.size() == 1) return {m_positions[0], m_orientations[0]};
        const detail::Segment s = segment(t_s);
        const std::size_t i = s.index;
        return {m_positions[i] + s.fraction * (m_positions[i + 1] - m_positions[i]),
                slerp(m_orientations[i], m_orientations[i + 1], s.fraction)};
    }

    Vec3 velocity_m_s(double t_s) const override {
        if (m_times.size() == 1) return {};
        const std::size_t i = segment(t_s).index;
        return (m_positions[i + 1] - m_positions[i]) / (m_times[i + 1] - m_times[i]);
    }

    std::optional<TimeSpan> span() const override {
        return TimeSpan{m_times.front(), m_times.back()};
    }

private:
    detail::Segment segment(double t_s) const {
        const double t = m_notice.clamp(t_s, m_times.front(), m_times.back(), m_where,
                                        "time span of the motion entries");
        return detail::find_segment(m_times, t);
    }

    std::vector<double> m_times;
    std::vector<Vec3> m_positions;
    std::vector<Quaternion> m_orientations;
    ErrorContext m_where;
    detail::ClampNotice m_notice;
};

}  // namespace

std::unique_ptr<Trajectory> make_trajectory(const model::GenericMotion& motion,
                                            const SceneFrame& scene, Log log) {
    if (motion.entries.empty()) {
        throw input_error("the motion has no entries, expected at least one", motion.where);
    }
    const std::optional<EulerOrder> order = parse_euler_order(motion.rotation_order);
    if (!order) {
        throw input_error(
            "rotationorder \"" + motion.rotation_order + "\" is not a permutation of xyz",
            motion.where);
    }
    std::vector<double> times;
    std::vector<Vec3> positions;
    std::vector<Quaternion> orientations;
    for (const model::GenericMotionEntry& entry : motion.entries) {
        if (!times.empty() && !(entry.time_s > times.back())) {
            throw input_error("entry time " + detail::seconds_text(entry.time_s) +
                                  " does not follow " + detail::seconds_text(times.back()) +
                                  ", expected strictly increasing times",
                              entry.where);
        }
        times.push_back(entry.time_s);
        positions.push_back(location_to_scene(entry.location, scene));
        Mat3 rotation =
            vehicle_to_scene_rotation(to_vehicle_attitude(to_vec3(entry.euler_rad)), *order);
        if (motion.rotation_frame == model::RotationFrame::ecef) {
            rotation = scene.ecef_to_enu_rotation() * rotation;
        }
        orientations.push_back(quaternion_from_matrix(rotation));
    }
    return std::make_unique<GenericTrajectory>(std::move(times), std::move(positions),
                                               std::move(orientations), motion.where,
                                               std::move(log));
}

}  // namespace glint::motion
