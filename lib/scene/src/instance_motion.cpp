// SPDX-License-Identifier: Apache-2.0
// Time-step selection for dynamic instances. A candidate count n is accepted when no step
// turns the instance by more than max_step_rotation_deg and the interpolated pose (linear
// translation, slerped rotation, as Embree does it) stays within max_step_fraction × the
// object's diagonal of the trajectory, the distance measured as |Δposition| + radius ·
// Δangle (a bound on how far any object point moves). The error is checked at every step
// midpoint and on a fixed fine grid of 4·(max − 1) intervals, which also catches a spin that
// aliases onto whole turns between steps. A failing n is replaced by an estimate from the
// worst ratio (rotation shrinks like 1/(n−1), the midpoint error of smooth motion like
// 1/(n−1)²), never less than n + 1.
#include "instance_motion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glint/core/text.h"

namespace glint::scene::detail {
namespace {

using motion::Pose;
using motion::Quaternion;

/// The time of sample i of n over the window (the last exactly at the end).
double sample_time(const TimeWindow& window, std::size_t i, std::size_t n) noexcept {
    if (i + 1 >= n) return window.end_s;
    const double u = static_cast<double>(i) / static_cast<double>(n - 1);
    return window.begin_s + (window.end_s - window.begin_s) * u;
}

Pose checked_pose(const motion::Trajectory& trajectory, double t_s, const ErrorContext& where) {
    Pose pose = trajectory.pose_at(t_s);
    const Quaternion& q = pose.orientation;
    const bool finite = std::isfinite(pose.position_m.x) && std::isfinite(pose.position_m.y) &&
                        std::isfinite(pose.position_m.z) && std::isfinite(q.w) &&
                        std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) &&
                        motion::norm(q) > 0.0;
    if (!finite) {
        throw input_error("the motion gives a non-finite pose at " + format_shortest(t_s) + " s",
                          where);
    }
    pose.orientation = motion::normalized(q);
    return pose;
}

/// The pose interpolated between two steps as Embree does it.
Pose interpolate(const Pose& a, const Pose& b, double f) noexcept {
    return {a.position_m + (b.position_m - a.position_m) * f,
            motion::slerp(a.orientation, b.orientation, f)};
}

double pose_distance(const Pose& a, const Pose& b, double radius_m) noexcept {
    return norm(a.position_m - b.position_m) +
           radius_m * motion::angle_between(a.orientation, b.orientation);
}

struct Candidate {
    std::vector<Pose> poses;
    double max_rotation_rad = 0.0;
    double max_error_m = 0.0;
};

/// The steps for n samples and their worst rotation and interpolation error; `fine` are the
/// trajectory's poses on the fine grid.
Candidate evaluate(const motion::Trajectory& trajectory, const TimeWindow& window, std::size_t n,
                   const std::vector<Pose>& fine, double radius_m, const ErrorContext& where) {
    Candidate c;
    c.poses.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        Pose pose = checked_pose(trajectory, sample_time(window, i, n), where);
        if (i > 0 && motion::dot(pose.orientation, c.poses.back().orientation) < 0.0) {
            const Quaternion& q = pose.orientation;
            pose.orientation = {-q.w, -q.x, -q.y, -q.z};
        }
        c.poses.push_back(pose);
    }
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const Pose& a = c.poses[i];
        const Pose& b = c.poses[i + 1];
        c.max_rotation_rad =
            std::max(c.max_rotation_rad, motion::angle_between(a.orientation, b.orientation));
        const double t_mid = 0.5 * (sample_time(window, i, n) + sample_time(window, i + 1, n));
        const Pose truth = checked_pose(trajectory, t_mid, where);
        c.max_error_m =
            std::max(c.max_error_m, pose_distance(truth, interpolate(a, b, 0.5), radius_m));
    }
    for (std::size_t j = 0; j < fine.size(); ++j) {
        const double u = static_cast<double>(j) / static_cast<double>(fine.size() - 1);
        const double x = u * static_cast<double>(n - 1);
        const std::size_t i = std::min(static_cast<std::size_t>(x), n - 2);
        const Pose p = interpolate(c.poses[i], c.poses[i + 1], x - static_cast<double>(i));
        c.max_error_m = std::max(c.max_error_m, pose_distance(fine[j], p, radius_m));
    }
    return c;
}

}  // namespace

MotionSamples sample_motion(const motion::Trajectory& trajectory, const TimeWindow& window,
                            const MotionSampling& sampling, const ObjectExtent& extent,
                            const ErrorContext& where) {
    MotionSamples out;
    if (!(window.end_s > window.begin_s)) {
        out.poses.push_back(checked_pose(trajectory, window.begin_s, where));
        return out;
    }
    const std::size_t min_n = std::max<std::size_t>(sampling.min_time_steps, 2);
    const std::size_t max_n = std::max<std::size_t>(sampling.max_time_steps, min_n);
    const double max_rotation_rad = sampling.max_step_rotation_deg * std::numbers::pi / 180.0;
    const double max_error_m = sampling.max_step_fraction * extent.diagonal_m;

    std::vector<Pose> fine;
    const std::size_t fine_n = 4 * (max_n - 1) + 1;
    fine.reserve(fine_n);
    for (std::size_t j = 0; j < fine_n; ++j) {
        fine.push_back(checked_pose(trajectory, sample_time(window, j, fine_n), where));
    }

    std::size_t n = min_n;
    for (;;) {
        Candidate c = evaluate(trajectory, window, n, fine, extent.radius_m, where);
        const double rotation_ratio = c.max_rotation_rad / max_rotation_rad;
        const double error_ratio = max_error_m > 0.0 ? c.max_error_m / max_error_m : 0.0;
        // A step of exactly the limit passes despite rounding in the angle.
        const bool ok = rotation_ratio <= 1.0 + 1e-9 && error_ratio <= 1.0 + 1e-9;
        if (ok || n >= max_n) {
            out.poses = std::move(c.poses);
            out.max_step_rotation_rad = c.max_rotation_rad;
            out.max_error_m = c.max_error_m;
            out.within_tolerance = ok;
            return out;
        }
        const double segments = static_cast<double>(n - 1);
        const double needed = std::min(segments * std::max(rotation_ratio, std::sqrt(error_ratio)),
                                       static_cast<double>(max_n));
        const auto estimate = static_cast<std::size_t>(std::ceil(needed - 1e-9)) + 1;
        n = std::min(max_n, std::max(n + 1, estimate));
    }
}

}  // namespace glint::scene::detail
