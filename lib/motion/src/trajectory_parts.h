// SPDX-License-Identifier: Apache-2.0
// Internal interface of the trajectories (trajectory.cpp, generic_trajectory.cpp,
// flex_location.cpp, flex_orientation.cpp): the once-per-trajectory clamp warning, table
// lookup, and the FlexMotion location and orientation models the engines are built into.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/datetime.h"
#include "glint/core/error.h"
#include "glint/core/log.h"
#include "glint/model/motion.h"
#include "glint/motion/frames.h"
#include "glint/motion/geometry.h"
#include "glint/motion/trajectory.h"

namespace glint::motion::detail {

/// Clamps times to a table's span and logs the first clamp of a trajectory (thread-safe:
/// one atomic flag shared by every table of the trajectory).
class ClampNotice {
public:
    explicit ClampNotice(Log log) : m_log(std::move(log)) {}

    /// `t_s` clamped to [begin_s, end_s]; the first time a trajectory clamps (and the span
    /// is not a single instant) it logs a warning naming `where` and `what`.
    double clamp(double t_s, double begin_s, double end_s, const ErrorContext& where,
                 const char* what) const;

private:
    Log m_log;
    mutable std::atomic<bool> m_warned{false};
};

/// Position of `t_s` in strictly increasing `times`: segment index i and fraction f in
/// [0, 1] so that t = times[i] + f (times[i+1] − times[i]); i = size − 2, f = 1 at the
/// last time; i = 0, f = 0 for a single time. `t_s` must lie within the span.
struct Segment {
    std::size_t index = 0;
    double fraction = 0.0;
};
Segment find_segment(const std::vector<double>& times, double t_s) noexcept;

/// Velocity and heading of a FlexMotion location engine.
class LocationModel {
public:
    virtual ~LocationModel() = default;
    virtual Vec3 position_m(double t_s) const = 0;
    virtual Vec3 velocity_m_s(double t_s) const = 0;
    /// A direction of travel where the velocity is zero (e.g. a waypoint pause): the nearest
    /// non-zero motion; zero when the engine never moves. Default: the velocity.
    virtual Vec3 travel_direction(double t_s) const { return velocity_m_s(t_s); }
    virtual std::optional<TimeSpan> span() const { return std::nullopt; }
};

/// A FlexMotion orientation engine (it may use the location, never the reverse).
class OrientationModel {
public:
    virtual ~OrientationModel() = default;
    /// Vehicle → scene rotation at `t_s` for a platform moving along `location`.
    virtual Quaternion orientation(double t_s, const LocationModel& location) const = 0;
    virtual std::optional<TimeSpan> span() const { return std::nullopt; }
};

/// Builds the model of a location engine. Throws glint::Error (input) at the engine's
/// element for a motion that cannot be used (bad TLE, unusable location).
std::unique_ptr<LocationModel> make_location_model(const model::LocationEngine& engine,
                                                   const SceneFrame& scene,
                                                   const DateTime& reference_utc,
                                                   std::shared_ptr<const ClampNotice> notice);

/// Builds the model of an orientation engine (same errors).
std::unique_ptr<OrientationModel> make_orientation_model(const model::OrientationEngine& engine,
                                                         const SceneFrame& scene,
                                                         const DateTime& reference_utc,
                                                         std::shared_ptr<const ClampNotice> notice);

/// The vehicle → scene rotation whose forward axis (+Y) is `forward` and whose up axis (+Z)
/// is as close to `up` as possible (X = Y × up normalised, Z = X × Y). When `forward` is zero
/// scene north is used; when `up` is parallel to `forward`, the right wing (+X) is scene east
/// (north when forward is east) made perpendicular to `forward`.
Quaternion frame_from_forward_up(const Vec3& forward, const Vec3& up) noexcept;

/// The vehicle → scene rotation whose −Z axis (the boresight) is `look` and whose +Y axis is
/// as close to `up` as possible (Z = −look, Y = up − (up·Z) Z normalised, X = Y × Z). When
/// `up` is parallel to `look`, scene north (or east) stands in for it; a zero `look` looks
/// straight down.
Quaternion frame_from_look_up(const Vec3& look, const Vec3& up) noexcept;

/// A direction hint as a scene ENU vector (ECEF directions rotated through `scene`).
Vec3 hint_to_scene(const model::DirectionHint& hint, const SceneFrame& scene) noexcept;

/// Seconds as text for messages ("12.5 s").
std::string seconds_text(double seconds);

}  // namespace glint::motion::detail
