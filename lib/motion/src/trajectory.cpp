// SPDX-License-Identifier: Apache-2.0
// Trajectories: the entry points (make_trajectory for a motion file, a GenericMotion or a
// FlexMotion), the FlexMotion trajectory that pairs a location model with an orientation
// model, and the shared pieces: the once-per-trajectory clamp warning, table segment lookup,
// and the frames built from a forward/up or look/up pair of directions.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "glint/core/text.h"
#include "trajectory_parts.h"

namespace glint::motion {

Trajectory::~Trajectory() = default;

namespace detail {

namespace {

constexpr Vec3 kNorth{0.0, 1.0, 0.0};
constexpr Vec3 kEast{1.0, 0.0, 0.0};
/// Below this length (of a cross product of unit vectors) two directions count as parallel.
constexpr double kParallel = 1e-9;

}  // namespace

std::string seconds_text(double seconds) { return format_shortest(seconds) + " s"; }

double ClampNotice::clamp(double t_s, double begin_s, double end_s, const ErrorContext& where,
                          const char* what) const {
    if (t_s >= begin_s && t_s <= end_s) return t_s;
    const double clamped = t_s < begin_s ? begin_s : end_s;
    if (end_s > begin_s && !m_warned.exchange(true, std::memory_order_relaxed)) {
        m_log.warning(format_located(
            where, "time " + seconds_text(t_s) + " is outside the " + what + " (" +
                       seconds_text(begin_s) + " to " + seconds_text(end_s) +
                       "); the pose is held at the nearest end (warned once per motion)"));
    }
    return clamped;
}

Segment find_segment(const std::vector<double>& times, double t_s) noexcept {
    if (times.size() < 2) return {};
    const auto upper = std::upper_bound(times.begin(), times.end(), t_s);
    std::size_t i =
        upper == times.begin() ? 0 : static_cast<std::size_t>(upper - times.begin()) - 1;
    if (i >= times.size() - 1) return {times.size() - 2, 1.0};
    const double f = (t_s - times[i]) / (times[i + 1] - times[i]);
    return {i, std::clamp(f, 0.0, 1.0)};
}

Quaternion frame_from_forward_up(const Vec3& forward, const Vec3& up) noexcept {
    const Vec3 y = norm(forward) > 0.0 ? normalized(forward) : kNorth;
    const Vec3 u = norm(up) > 0.0 ? normalized(up) : Vec3{0.0, 0.0, 1.0};
    Vec3 x = cross(y, u);
    // Forward along up: the right wing points east, as if pitched from level flight north.
    if (norm(x) < kParallel) x = kEast - dot(kEast, y) * y;
    if (norm(x) < kParallel) x = kNorth - dot(kNorth, y) * y;
    x = normalized(x);
    const Vec3 z = cross(x, y);
    return quaternion_from_matrix(Mat3::from_columns(x, y, z));
}

Quaternion frame_from_look_up(const Vec3& look, const Vec3& up) noexcept {
    const Vec3 z = norm(look) > 0.0 ? -normalized(look) : Vec3{0.0, 0.0, 1.0};
    const auto perpendicular = [&](const Vec3& hint) { return hint - dot(hint, z) * z; };
    Vec3 y = perpendicular(normalized(up));
    if (norm(y) < kParallel) y = perpendicular(kNorth);
    if (norm(y) < kParallel) y = perpendicular(kEast);
    y = normalized(y);
    const Vec3 x = cross(y, z);
    return quaternion_from_matrix(Mat3::from_columns(x, y, z));
}

Vec3 hint_to_scene(const model::DirectionHint& hint, const SceneFrame& scene) noexcept {
    const Vec3 v = to_vec3(hint.vector);
    return hint.frame == model::LocationFrame::ecef ? scene.ecef_direction_to_enu(v) : v;
}

}  // namespace detail

namespace {

/// A FlexMotion trajectory: a location model and an orientation model.
class FlexTrajectory final : public Trajectory {
public:
    FlexTrajectory(std::unique_ptr<detail::LocationModel> location,
                   std::unique_ptr<detail::OrientationModel> orientation)
        : m_location(std::move(location)), m_orientation(std::move(orientation)) {}

    Pose pose_at(double t_s) const override {
        return {m_location->position_m(t_s), m_orientation->orientation(t_s, *m_location)};
    }
    Vec3 velocity_m_s(double t_s) const override { return m_location->velocity_m_s(t_s); }
    std::optional<TimeSpan> span() const override {
        const std::optional<TimeSpan> a = m_location->span();
        const std::optional<TimeSpan> b = m_orientation->span();
        if (!a) return b;
        if (!b) return a;
        return TimeSpan{std::max(a->begin_s, b->begin_s), std::min(a->end_s, b->end_s)};
    }

private:
    std::unique_ptr<detail::LocationModel> m_location;
    std::unique_ptr<detail::OrientationModel> m_orientation;
};

}  // namespace

Vec3 location_to_scene(const model::Location& location, const SceneFrame& scene) {
    try {
        switch (location.frame) {
            case model::LocationFrame::scene:
                return to_vec3(location.xyz_m);
            case model::LocationFrame::ecef:
                return scene.ecef_to_enu(to_vec3(location.xyz_m));
            case model::LocationFrame::geodetic:
                return scene.geodetic_to_enu(location.latitude_deg, location.longitude_deg,
                                             location.altitude_m);
        }
    } catch (const Error& error) {
        throw input_error(error.message(), location.where);
    }
    return {};
}

std::unique_ptr<Trajectory> make_trajectory(const model::FlexMotion& motion,
                                            const SceneFrame& scene, const DateTime& reference_utc,
                                            Log log) {
    const auto notice = std::make_shared<const detail::ClampNotice>(std::move(log));
    auto location = detail::make_location_model(motion.location, scene, reference_utc, notice);
    auto orientation =
        detail::make_orientation_model(motion.orientation, scene, reference_utc, notice);
    return std::make_unique<FlexTrajectory>(std::move(location), std::move(orientation));
}

std::unique_ptr<Trajectory> make_trajectory(const model::PlatformMotion& motion,
                                            const SceneFrame& scene, const DateTime& reference_utc,
                                            Log log) {
    if (motion.generic && motion.flexible) {
        throw input_error("the motion is both GenericMotion and FlexMotion, expected one",
                          ErrorContext{motion.file, 0, {}});
    }
    if (motion.generic) return make_trajectory(*motion.generic, scene, std::move(log));
    if (motion.flexible) {
        return make_trajectory(*motion.flexible, scene, reference_utc, std::move(log));
    }
    throw input_error("no motion was read (neither GenericMotion nor FlexMotion)",
                      ErrorContext{motion.file, 0, {}});
}

}  // namespace glint::motion
