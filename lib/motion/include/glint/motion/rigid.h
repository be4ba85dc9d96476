// SPDX-License-Identifier: Apache-2.0
// Rigid transforms (rotation + translation, no scale): the value type that carries an
// instrument frame through its mounts and attachments into the vehicle and the scene.
// Built on geometry.h (Hamilton quaternions, active rotations, composition right to left).
//
// A Rigid T = {R, t} maps a point p given in the child frame to the parent frame:
//     p_parent = R · p_child + t
// so R's columns are the child axes expressed in the parent, and t is the child's origin in
// the parent. Directions see only R. Composition reads right to left like geometry.h:
// (a * b) applies b first, so a chain written outermost first,
//     instrument_to_scene = vehicle_to_scene * attachment_0 * mount_0 * ... * attachment_n,
// maps instrument coordinates to the scene.
#pragma once

#include "glint/motion/geometry.h"

namespace glint::motion {

/// A rigid transform child → parent: p_parent = rotation · p_child + translation_m.
/// Default-constructed it is the identity.
struct Rigid {
    Quaternion rotation;  ///< unit quaternion, child → parent
    Vec3 translation_m;   ///< the child origin in the parent frame (m)

    /// The identity transform.
    static constexpr Rigid identity() noexcept { return {}; }
    friend constexpr bool operator==(const Rigid&, const Rigid&) = default;
};

/// A pure rotation (no translation).
constexpr Rigid rigid_rotation(const Quaternion& rotation) noexcept { return {rotation, {}}; }
/// A pure translation (no rotation).
constexpr Rigid rigid_translation(const Vec3& translation_m) noexcept {
    return {Quaternion::identity(), translation_m};
}

/// Maps point `p` of the child frame into the parent frame: R · p + t.
constexpr Vec3 apply_point(const Rigid& a, const Vec3& p) noexcept {
    return rotate(a.rotation, p) + a.translation_m;
}
/// Maps direction `d` of the child frame into the parent frame: R · d (no translation).
constexpr Vec3 apply_direction(const Rigid& a, const Vec3& d) noexcept {
    return rotate(a.rotation, d);
}

/// Composition a ∘ b: applies b first, then a. If b maps frame C into B and a maps B into A,
/// a * b maps C into A: rotation R_a·R_b, translation R_a·t_b + t_a. The rotation is
/// renormalised so long chains do not drift.
Rigid operator*(const Rigid& a, const Rigid& b) noexcept;
/// The same as a * b.
inline Rigid compose(const Rigid& a, const Rigid& b) noexcept { return a * b; }
/// The inverse transform parent → child: rotation R*, translation −R*·t.
Rigid inverse(const Rigid& a) noexcept;

/// The rotation matrix of the transform (child → parent).
inline Mat3 rotation_matrix(const Rigid& a) noexcept { return to_matrix(a.rotation); }

}  // namespace glint::motion
