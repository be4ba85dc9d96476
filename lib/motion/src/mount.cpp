// SPDX-License-Identifier: Apache-2.0
// Mount kinematics (static, commanded, tabulated, whisk, tracking) and affine placements
// (glint/motion/mount.h).
#include "glint/motion/mount.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/motion/euler.h"

namespace glint::motion {
namespace {

constexpr double kFullTurn_rad = 2.0 * std::numbers::pi;

std::string mount_label(const model::Mount& mount) {
    return mount.name.empty() ? std::string("mount") : "mount \"" + mount.name + "\"";
}

EulerOrder order_or_throw(const std::string& text, const ErrorContext& where) {
    const std::optional<EulerOrder> order = parse_euler_order(text);
    if (!order) {
        throw input_error("unknown rotation order \"" + text +
                              "\", expected a permutation of xyz (xyz, xzy, yxz, yzx, zxy, zyx)",
                          where);
    }
    return *order;
}

bool finite(const std::array<double, 3>& a) {
    return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

/// The transform of one table entry.
Rigid entry_transform(const model::MountEntry& entry, EulerOrder order) noexcept {
    return {euler_to_quaternion(to_vec3(entry.rotation_rad), order), to_vec3(entry.translation_m)};
}

/// Interpolation between entries a (at ta) and b (at tb) at time t in [ta, tb].
Rigid interpolate(const model::MountEntry& a, double ta, const model::MountEntry& b, double tb,
                  double t, EulerOrder order) noexcept {
    const Rigid ra = entry_transform(a, order);
    const Rigid rb = entry_transform(b, order);
    const double span = tb - ta;
    const double u = span > 0.0 ? std::clamp((t - ta) / span, 0.0, 1.0) : 0.0;
    return {slerp(ra.rotation, rb.rotation, u),
            ra.translation_m + (rb.translation_m - ra.translation_m) * u};
}

/// A non-periodic table: the entries' transforms interpolated, held constant outside.
Rigid table_at(const std::vector<model::MountEntry>& entries, double t, EulerOrder order) noexcept {
    if (t <= entries.front().time_s) return entry_transform(entries.front(), order);
    if (t >= entries.back().time_s) return entry_transform(entries.back(), order);
    // First entry after t; there is one before it since t > front.
    const auto next =
        std::upper_bound(entries.begin(), entries.end(), t,
                         [](double time, const model::MountEntry& e) { return time < e.time_s; });
    const auto prev = next - 1;
    return interpolate(*prev, prev->time_s, *next, next->time_s, t, order);
}

/// The table repeated every `period` s: entry times + k·period, the gap from the last entry
/// to the first entry of the next repetition interpolated like any other segment.
Rigid periodic_table_at(const std::vector<model::MountEntry>& entries, double period, double t,
                        EulerOrder order) noexcept {
    const double first = entries.front().time_s;
    const double last = entries.back().time_s;
    double u = first + (t - first - period * std::floor((t - first) / period));
    if (u >= first + period) u = first;  // round-off of the modulo
    if (u <= last) return table_at(entries, u, order);
    return interpolate(entries.back(), last, entries.front(), first + period, u, order);
}

void validate_entries(const model::Mount& mount) {
    if (mount.entries.empty()) {
        throw input_error(
            mount_label(mount) + " (" + mount.type_text + ") has no entries, expected at least one",
            mount.where);
    }
    for (std::size_t i = 0; i < mount.entries.size(); ++i) {
        const model::MountEntry& e = mount.entries[i];
        if (!std::isfinite(e.time_s) || !finite(e.rotation_rad) || !finite(e.translation_m)) {
            throw input_error("entry has a non-finite value", e.where);
        }
        if (i > 0 && !(e.time_s > mount.entries[i - 1].time_s)) {
            throw input_error("entry times are not strictly increasing", e.where);
        }
    }
    if (mount.type == model::MountType::tabulated && mount.period_s) {
        const double p = *mount.period_s;
        if (!(std::isfinite(p) && p > 0.0 &&
              p >= mount.entries.back().time_s - mount.entries.front().time_s)) {
            throw input_error(mount_label(mount) + " period " + std::to_string(p) +
                                  " s, expected a positive period covering the table",
                              mount.where);
        }
    }
}

}  // namespace

Rigid affine_transform(const model::AffineTransform& transform) {
    if (!transform.matrix) {
        if (!finite(transform.translation_m) || !finite(transform.rotation_rad)) {
            throw input_error("affinetransform has a non-finite value", transform.where);
        }
        const EulerOrder order = order_or_throw(transform.rotation_order, transform.where);
        return {euler_to_quaternion(to_vec3(transform.rotation_rad), order),
                to_vec3(transform.translation_m)};
    }
    const std::array<double, 16>& m = *transform.matrix;
    for (const double v : m) {
        if (!std::isfinite(v)) {
            throw input_error("affinetransform matrix has a non-finite value", transform.where);
        }
    }
    const double tol = kRigidMatrixTolerance;
    if (std::abs(m[12]) > tol || std::abs(m[13]) > tol || std::abs(m[14]) > tol ||
        std::abs(m[15] - 1.0) > tol) {
        throw input_error("affinetransform matrix is not rigid: last row is not 0 0 0 1",
                          transform.where);
    }
    const Mat3 r{{{{m[0], m[1], m[2]}, {m[4], m[5], m[6]}, {m[8], m[9], m[10]}}}};
    const Mat3 rtr = transpose(r) * r;
    double worst = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
            worst = std::max(worst, std::abs(rtr(i, j) - (i == j ? 1.0 : 0.0)));
        }
    }
    if (worst > tol) {
        throw input_error(
            "affinetransform matrix is not rigid: its 3x3 part is not a rotation (scale or "
            "shear; |R^T R - I| = " +
                std::to_string(worst) + "), expected an orthonormal rotation",
            transform.where);
    }
    if (determinant(r) < 0.0) {
        throw input_error(
            "affinetransform matrix is not rigid: its 3x3 part is a reflection (determinant -1), "
            "expected a proper rotation",
            transform.where);
    }
    return {quaternion_from_matrix(r), {m[3], m[7], m[11]}};
}

void validate_mount(const model::Mount& mount) {
    switch (mount.type) {
        case model::MountType::static_mount:
        case model::MountType::other:
            order_or_throw(mount.rotation_order, mount.where);
            if (!finite(mount.rotation_rad)) {
                throw input_error(mount_label(mount) + " has a non-finite rotation", mount.where);
            }
            return;
        case model::MountType::commanded:
        case model::MountType::tabulated:
            order_or_throw(mount.rotation_order, mount.where);
            validate_entries(mount);
            return;
        case model::MountType::whisk: {
            if (!mount.whisk) {
                throw input_error(mount_label(mount) + " (whisk) has no scan", mount.where);
            }
            const model::WhiskScan& s = *mount.whisk;
            if (!std::isfinite(s.min_angle_rad) || !std::isfinite(s.max_angle_rad) ||
                !std::isfinite(s.phase_rad) || !std::isfinite(s.rate_hz)) {
                throw input_error(mount_label(mount) + " (whisk) has a non-finite value",
                                  mount.where);
            }
            if (!(s.rate_hz > 0.0)) {
                throw input_error(mount_label(mount) + " (whisk) rate must be > 0 Hz", mount.where);
            }
            if (s.min_angle_rad > s.max_angle_rad) {
                throw input_error(
                    mount_label(mount) + " (whisk) minimum angle is above the maximum angle",
                    mount.where);
            }
            return;
        }
        case model::MountType::tracking: {
            if (!mount.tracking || (!mount.tracking->point_m && mount.tracking->name.empty())) {
                throw input_error(mount_label(mount) +
                                      " (tracking) has no target, expected "
                                      "<targetname> or <point>",
                                  mount.where);
            }
            if (!finite(mount.tracking->offset_m) ||
                (mount.tracking->point_m && !finite(*mount.tracking->point_m))) {
                throw input_error(mount_label(mount) + " (tracking) has a non-finite target",
                                  mount.where);
            }
            return;
        }
    }
}

bool mount_is_time_varying(const model::Mount& mount) noexcept {
    switch (mount.type) {
        case model::MountType::static_mount:
        case model::MountType::other:
            return false;
        case model::MountType::commanded:
        case model::MountType::tabulated:
            return mount.entries.size() > 1;
        case model::MountType::whisk:
        case model::MountType::tracking:
            return true;
    }
    return true;
}

double whisk_angle_rad(const model::WhiskScan& scan, double t_s) noexcept {
    const double centre = 0.5 * (scan.min_angle_rad + scan.max_angle_rad);
    const double amplitude = 0.5 * (scan.max_angle_rad - scan.min_angle_rad);
    if (scan.sinusoidal) {
        return centre + amplitude * std::sin(kFullTurn_rad * scan.rate_hz * t_s + scan.phase_rad);
    }
    const double cycles = scan.rate_hz * t_s + scan.phase_rad / kFullTurn_rad + 0.5;
    const double frac = cycles - std::floor(cycles);
    return centre + amplitude * (2.0 * frac - 1.0);
}

Quaternion tracking_rotation(const Vec3& direction) noexcept {
    const Vec3 d = normalized(direction);
    if (!(norm(d) > 0.0)) return Quaternion::identity();
    const Vec3 z = -d;  // mount +Z in the parent frame (the boresight is −Z)
    Vec3 y = Vec3{0.0, 1.0, 0.0} - z * z.y;
    if (norm(y) < 1e-9) y = Vec3{0.0, 0.0, 1.0} - z * z.z;
    y = normalized(y);
    const Vec3 x = cross(y, z);
    return quaternion_from_matrix(Mat3::from_columns(x, y, z));
}

Vec3 tracking_target_m(const model::Mount& mount, double t_s, const TargetResolver* targets) {
    if (!mount.tracking) {
        throw input_error(mount_label(mount) + " (tracking) has no target", mount.where);
    }
    const model::TrackingTarget& target = *mount.tracking;
    const Vec3 offset = to_vec3(target.offset_m);
    if (target.point_m) return to_vec3(*target.point_m) + offset;
    if (target.name.empty()) {
        throw input_error(mount_label(mount) +
                              " (tracking) has no target, expected "
                              "<targetname> or <point>",
                          mount.where);
    }
    if (targets == nullptr) {
        throw input_error(mount_label(mount) + ": tracking a named target (\"" + target.name +
                              "\") needs the scene (its instances are the targets), and none "
                              "is loaded; give a fixed <point> without one",
                          mount.where);
    }
    const std::optional<Vec3> position = targets->target_position_m(target.name, t_s);
    if (!position) {
        throw input_error(
            mount_label(mount) + ": the scene has no target named \"" + target.name + "\"",
            mount.where);
    }
    return *position + offset;
}

Rigid mount_transform(const model::Mount& mount, double t_s, const MountContext& context) {
    switch (mount.type) {
        case model::MountType::static_mount:
        case model::MountType::other:
            return rigid_rotation(euler_to_quaternion(
                to_vec3(mount.rotation_rad), order_or_throw(mount.rotation_order, mount.where)));
        case model::MountType::commanded: {
            if (mount.entries.empty()) validate_mount(mount);
            return table_at(mount.entries, t_s, order_or_throw(mount.rotation_order, mount.where));
        }
        case model::MountType::tabulated: {
            if (mount.entries.empty()) validate_mount(mount);
            const EulerOrder order = order_or_throw(mount.rotation_order, mount.where);
            if (!mount.period_s || !(*mount.period_s > 0.0)) {
                return table_at(mount.entries, t_s, order);
            }
            return periodic_table_at(mount.entries, *mount.period_s, t_s, order);
        }
        case model::MountType::whisk: {
            if (!mount.whisk) validate_mount(mount);
            const double angle = whisk_angle_rad(*mount.whisk, t_s);
            const Vec3 axis = mount.whisk->axis == model::WhiskScan::Axis::across_track
                                  ? Vec3{0.0, 1.0, 0.0}
                                  : Vec3{1.0, 0.0, 0.0};
            return rigid_rotation(quaternion_from_axis_angle(axis, angle));
        }
        case model::MountType::tracking: {
            if (!context.parent_to_scene) {
                throw internal_error(mount_label(mount) +
                                     " (tracking) needs the parent-to-scene transform");
            }
            const Vec3 target = tracking_target_m(mount, t_s, context.targets);
            const Rigid scene_to_parent = inverse(*context.parent_to_scene);
            return rigid_rotation(tracking_rotation(apply_point(scene_to_parent, target)));
        }
    }
    throw internal_error("unknown mount type");
}

}  // namespace glint::motion
