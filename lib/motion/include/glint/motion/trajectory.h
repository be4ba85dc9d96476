// SPDX-License-Identifier: Apache-2.0
// Platform trajectories: the pose (position and orientation in scene ENU) of a platform or
// moving object at any time, built from a GenericMotion `.ppd` or a FlexMotion description
// (glint/model/motion.h). Conventions (docs/motion.md): positions in scene ENU metres; the
// orientation rotates vehicle vectors (X right wing, Y forward, Z up) into scene ENU; times
// are seconds after the tasks reference time. Jitter is not applied here (glint/motion/
// jitter.h adds it). docs/motion.md ("Platform motion files and trajectories") has every engine's
// formula.
//
// Times outside the span of the data (tables of entries, waypoints, angles) are clamped to
// its nearest end; the first clamp of a trajectory logs one warning, later ones are silent.
// A table with a single entry is constant and never warns.
#pragma once

#include <memory>
#include <optional>

#include "glint/core/datetime.h"
#include "glint/core/log.h"
#include "glint/model/motion.h"
#include "glint/motion/frames.h"
#include "glint/motion/geometry.h"

namespace glint::motion {

/// Where a platform is and how it is turned at one time.
struct Pose {
    Vec3 position_m;         ///< scene ENU
    Quaternion orientation;  ///< vehicle → scene ENU (v_scene = rotate(orientation, v_vehicle))
};

/// A closed interval of time, seconds after the reference.
struct TimeSpan {
    double begin_s = 0.0;
    double end_s = 0.0;
};

/// A platform trajectory. Immutable after construction; pose_at and velocity_m_s may be
/// called from many threads at once.
class Trajectory {
public:
    virtual ~Trajectory();

    /// The pose at `t_s` seconds after the reference time. Throws glint::Error (runtime) only
    /// when an SGP4 orbit cannot be propagated to that time (e.g. the satellite decayed).
    virtual Pose pose_at(double t_s) const = 0;
    /// The velocity (scene ENU, m/s) at `t_s`; outside the data span, the velocity at the
    /// clamped time. Piecewise-linear tables give the velocity of the segment starting at
    /// `t_s` (the last segment at the last time).
    virtual Vec3 velocity_m_s(double t_s) const = 0;
    /// The span where no data is clamped; nullopt when every time is covered (engines
    /// defined at all times). For FlexMotion it is the intersection of the engines' spans,
    /// and begin_s > end_s when they do not overlap.
    virtual std::optional<TimeSpan> span() const = 0;
};

/// The trajectory of a platform motion file. `scene` converts geodetic and ECEF inputs to
/// scene ENU; `reference_utc` (the tasks reference) places relative times for SGP4; `log`
/// receives the one clamp warning. Throws glint::Error (input, with the element's file and
/// line) when the motion cannot be used: neither kind set, no entries, a bad TLE, a
/// location the frames refuse.
std::unique_ptr<Trajectory> make_trajectory(const model::PlatformMotion& motion,
                                            const SceneFrame& scene, const DateTime& reference_utc,
                                            Log log = {});

/// The trajectory of a GenericMotion table (see make_trajectory).
std::unique_ptr<Trajectory> make_trajectory(const model::GenericMotion& motion,
                                            const SceneFrame& scene, Log log = {});

/// The trajectory of a FlexMotion description, e.g. a GLIST dynamic instance (see
/// make_trajectory).
std::unique_ptr<Trajectory> make_trajectory(const model::FlexMotion& motion,
                                            const SceneFrame& scene, const DateTime& reference_utc,
                                            Log log = {});

/// A location of the model in scene ENU metres (geodetic and ECEF through `scene`). Throws
/// glint::Error (input, at location.where) for a location the frames refuse.
Vec3 location_to_scene(const model::Location& location, const SceneFrame& scene);

}  // namespace glint::motion
