// SPDX-License-Identifier: Apache-2.0
// Where an instance puts its object: the affine map object → scene ENU of a static transform
// or of one pose, in double precision, with what the Embree scene needs from it (the float
// 3×4 matrix, the normal matrix, transformed bounds).
#pragma once

#include <array>

#include "glint/model/scene.h"
#include "glint/motion/geometry.h"
#include "glint/motion/trajectory.h"
#include "glint/scene/geometry_scene.h"

namespace glint::scene::detail {

using motion::Mat3;

/// p_scene = linear · p_object + translation_m.
struct Affine {
    Mat3 linear = Mat3::identity();
    Vec3 translation_m;

    Vec3 apply(const Vec3& p) const noexcept { return linear * p + translation_m; }
};

/// The affine map of a static transform (model/scene.h: translation + R · (scale ∘ p), R the
/// rotations applied in rotation_order, first letter first; or the row-major 4×4 matrix).
/// Throws glint::Error (input, at `where`) for an unknown rotation order or a transform
/// that is not finite or not invertible.
Affine static_affine(const model::StaticTransform& transform, const ErrorContext& where);
/// The affine map of a pose: position + rotate(orientation, p).
Affine pose_affine(const motion::Pose& pose) noexcept;

/// The inverse transpose of `m` (maps object-space normals to scene normals, keeping the
/// outside of a surface outside even under mirroring scales); `m` must be invertible.
Mat3 inverse_transpose(const Mat3& m) noexcept;

/// `affine` as Embree's RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR (columns: the images of x, y, z,
/// then the translation).
std::array<float, 12> to_float3x4(const Affine& affine) noexcept;
/// The affine map of an Embree RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR matrix.
Affine from_float3x4(const float (&m)[12]) noexcept;

/// `box` grown to hold `other`.
void expand(Bounds& box, const Bounds& other) noexcept;
/// `box` grown by `pad_m` on every side.
Bounds padded(const Bounds& box, double pad_m) noexcept;
/// Bounds of the image under `affine` of the box `object` (its eight corners).
Bounds transformed(const Bounds& object, const Affine& affine) noexcept;
/// Bounds that hold nothing (empty() is true; expand() makes them the other box).
Bounds empty_bounds() noexcept;

}  // namespace glint::scene::detail
