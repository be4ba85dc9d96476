// SPDX-License-Identifier: Apache-2.0
// The time steps of a dynamic instance: how many (MotionSampling's rule) and the poses at
// them, uniformly spaced over the window. Embree interpolates between steps (translation
// linearly, rotation by slerp), so the rule bounds how far that interpolation may stray from
// the trajectory.
#pragma once

#include <vector>

#include "glint/core/error.h"
#include "glint/motion/trajectory.h"
#include "glint/scene/geometry_scene.h"

namespace glint::scene::detail {

/// The size of an object, for the tolerance of its motion sampling.
struct ObjectExtent {
    double diagonal_m = 0.0;  ///< diagonal of its bounding box
    double radius_m = 0.0;    ///< largest distance of a vertex from the object origin
};

/// The poses of one dynamic instance at its time steps.
struct MotionSamples {
    /// Poses at begin + (end − begin) · i / (n − 1), i = 0..n−1 (one pose at begin for an
    /// instant); consecutive quaternions have a non-negative dot product.
    std::vector<motion::Pose> poses;
    /// Largest rotation between consecutive steps, rad.
    double max_step_rotation_rad = 0.0;
    /// Largest distance found between an object point under the interpolated pose and under
    /// the trajectory's pose (checked at step midpoints and on a fine grid), m.
    double max_error_m = 0.0;
    /// False when even max_time_steps leave a step above the tolerances.
    bool within_tolerance = true;
};

/// Samples `trajectory` over `window` with the fewest steps in [min, max] that meet the
/// rotation and interpolation-error tolerances of `sampling` for an object of `extent`.
/// Throws glint::Error (input, at `where`) when the trajectory gives a non-finite pose.
MotionSamples sample_motion(const motion::Trajectory& trajectory, const TimeWindow& window,
                            const MotionSampling& sampling, const ObjectExtent& extent,
                            const ErrorContext& where);

}  // namespace glint::scene::detail
