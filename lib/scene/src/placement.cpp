// SPDX-License-Identifier: Apache-2.0
// Instance placements: static transforms and poses as double-precision affine maps (the
// rotation order through glint::motion's Euler composition, as the scene readers define it),
// their Embree float 3×4 form, normal matrices and transformed bounding boxes.
#include "placement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glint/core/error.h"
#include "glint/motion/euler.h"

namespace glint::scene::detail {
namespace {

bool finite(const Mat3& m) noexcept {
    for (const auto& row : m.m) {
        for (const double v : row) {
            if (!std::isfinite(v)) return false;
        }
    }
    return true;
}

}  // namespace

Affine static_affine(const model::StaticTransform& transform, const ErrorContext& where) {
    Affine affine;
    if (transform.matrix) {
        const auto& m = *transform.matrix;
        for (std::size_t i = 0; i < 3; ++i) {
            for (std::size_t j = 0; j < 3; ++j) affine.linear(i, j) = m[i * 4 + j];
            affine.translation_m[i] = m[i * 4 + 3];
        }
    } else {
        const auto order = motion::parse_euler_order(transform.rotation_order);
        if (!order) {
            throw input_error(
                "rotation order \"" + transform.rotation_order + "\" is not a permutation of xyz",
                where);
        }
        const Mat3 rotation =
            motion::euler_to_matrix(motion::to_vec3(transform.rotation_rad), *order);
        // R · (s ∘ p): column j of R scaled by s_j.
        for (std::size_t i = 0; i < 3; ++i) {
            for (std::size_t j = 0; j < 3; ++j) {
                affine.linear(i, j) = rotation(i, j) * transform.scale[j];
            }
        }
        affine.translation_m = motion::to_vec3(transform.translation_m);
    }
    const double det = motion::determinant(affine.linear);
    if (!finite(affine.linear) || !std::isfinite(norm(affine.translation_m))) {
        throw input_error("the instance transform is not finite", where);
    }
    if (!(std::abs(det) > 0.0)) {
        throw input_error("the instance transform is singular (it flattens the object)", where);
    }
    return affine;
}

Affine pose_affine(const motion::Pose& pose) noexcept {
    return {motion::to_matrix(motion::normalized(pose.orientation)), pose.position_m};
}

Mat3 inverse_transpose(const Mat3& m) noexcept {
    // The cofactor matrix divided by the determinant.
    const Vec3 c0 = cross(m.column(1), m.column(2));
    const Vec3 c1 = cross(m.column(2), m.column(0));
    const Vec3 c2 = cross(m.column(0), m.column(1));
    const double det = dot(m.column(0), c0);
    return Mat3::from_columns(c0 / det, c1 / det, c2 / det);
}

std::array<float, 12> to_float3x4(const Affine& affine) noexcept {
    std::array<float, 12> out{};
    for (std::size_t j = 0; j < 3; ++j) {
        for (std::size_t i = 0; i < 3; ++i)
            out[j * 3 + i] = static_cast<float>(affine.linear(i, j));
    }
    for (std::size_t i = 0; i < 3; ++i) out[9 + i] = static_cast<float>(affine.translation_m[i]);
    return out;
}

Affine from_float3x4(const float (&m)[12]) noexcept {
    Affine affine;
    for (std::size_t j = 0; j < 3; ++j) {
        for (std::size_t i = 0; i < 3; ++i) affine.linear(i, j) = m[j * 3 + i];
    }
    affine.translation_m = {m[9], m[10], m[11]};
    return affine;
}

Bounds empty_bounds() noexcept {
    constexpr double inf = std::numeric_limits<double>::infinity();
    return {{inf, inf, inf}, {-inf, -inf, -inf}};
}

void expand(Bounds& box, const Bounds& other) noexcept {
    for (std::size_t i = 0; i < 3; ++i) {
        box.lower[i] = std::min(box.lower[i], other.lower[i]);
        box.upper[i] = std::max(box.upper[i], other.upper[i]);
    }
}

Bounds padded(const Bounds& box, double pad_m) noexcept {
    const Vec3 pad{pad_m, pad_m, pad_m};
    return {box.lower - pad, box.upper + pad};
}

Bounds transformed(const Bounds& object, const Affine& affine) noexcept {
    Bounds out = empty_bounds();
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{(corner & 1) ? object.upper.x : object.lower.x,
                     (corner & 2) ? object.upper.y : object.lower.y,
                     (corner & 4) ? object.upper.z : object.lower.z};
        const Vec3 q = affine.apply(p);
        expand(out, {q, q});
    }
    return out;
}

}  // namespace glint::scene::detail
