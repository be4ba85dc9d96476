// SPDX-License-Identifier: Apache-2.0
// Euler (Tait–Bryan) angles in the six DIRSIG rotation orders, and their conversions to and
// from rotation matrices and quaternions.
//
// Definition used everywhere in glint (DIRSIG `rotationorder`, `.ppd` `<eulerangles>`, mount
// and instance rotations):
//   - An angle triple (x, y, z) holds the rotation angle about the X axis, the Y axis and the
//     Z axis, in that slot order whatever the rotation order (DIRSIG's `<cartesiantriple>`).
//   - The rotation order names the axes in the order the rotations are APPLIED, each about the
//     FIXED parent axes (extrinsic), each an ACTIVE right-handed rotation of the body:
//         "xyz": R = Rz(z) · Ry(y) · Rx(x)     (X first, then Y, then Z)
//         "xzy": R = Ry(y) · Rz(z) · Rx(x)
//         "yxz": R = Rz(z) · Rx(x) · Ry(y)
//         "yzx": R = Rx(x) · Rz(z) · Ry(y)
//         "zxy": R = Ry(y) · Rx(x) · Rz(z)
//         "zyx": R = Rx(x) · Ry(y) · Rz(z)
//     with Rx, Ry, Rz from geometry.h (rotation_z(+90°) takes +X to +Y). The same matrix is
//     the intrinsic sequence read backwards: "xyz" = Z first, then Y' about the once-rotated
//     Y axis, then X'' about the twice-rotated X axis.
//   - R maps body (vehicle, object) coordinates into the parent (scene) frame:
//     v_parent = R · v_body; its columns are the body axes expressed in the parent frame.
//     The passive transform parent → body is transpose(R).
//   - Angles are in radians in this API; convert degrees with glint::deg_to_rad
//     (glint/core/units.h) or euler_deg_to_rad below.
// In the vehicle frame (X right wing, Y forward, Z up) x is pitch (nose up > 0), y is roll
// (right wing down > 0) and z is yaw (counter-clockwise seen from above > 0).
#pragma once

#include <optional>
#include <string_view>

#include "glint/motion/geometry.h"

namespace glint::motion {

/// The order in which the three elementary rotations are applied (see the file comment).
enum class EulerOrder { xyz, xzy, yxz, yzx, zxy, zyx };

/// All six orders, for loops in tests and parsers.
inline constexpr EulerOrder kAllEulerOrders[] = {EulerOrder::xyz, EulerOrder::xzy, EulerOrder::yxz,
                                                 EulerOrder::yzx, EulerOrder::zxy, EulerOrder::zyx};

/// Parses "xyz", "XYZ", "zyx", ... (case-insensitive, surrounding blanks ignored); nullopt
/// for anything else (including proper-Euler orders such as "zxz", which DIRSIG lacks).
std::optional<EulerOrder> parse_euler_order(std::string_view text) noexcept;
/// The lower-case name of `order`, e.g. "xyz".
std::string_view to_string(EulerOrder order) noexcept;

/// Converts an angle triple from degrees to radians.
Vec3 euler_deg_to_rad(const Vec3& angles_deg) noexcept;
/// Converts an angle triple from radians to degrees.
Vec3 euler_rad_to_deg(const Vec3& angles_rad) noexcept;

/// The rotation matrix of the angle triple (x, y, z) in radians applied in `order`.
Mat3 euler_to_matrix(const Vec3& angles_rad, EulerOrder order) noexcept;
/// The unit quaternion of the angle triple (x, y, z) in radians applied in `order`
/// (the same rotation as euler_to_matrix).
Quaternion euler_to_quaternion(const Vec3& angles_rad, EulerOrder order) noexcept;

/// The angle triple (x, y, z) in radians that gives rotation `m` in `order`. The angle of
/// the second-applied axis is in [−π/2, π/2], the other two in [−π, π]. At gimbal lock (the
/// second angle at ±π/2, within about 1e-12 in its cosine) the first-applied angle is set
/// to 0 and the third absorbs the whole rotation. `m` should be a proper rotation.
Vec3 matrix_to_euler(const Mat3& m, EulerOrder order) noexcept;
/// The angle triple of the unit quaternion `q` in `order` (via its matrix; same ranges and
/// gimbal-lock rule as matrix_to_euler).
Vec3 quaternion_to_euler(const Quaternion& q, EulerOrder order) noexcept;

}  // namespace glint::motion
