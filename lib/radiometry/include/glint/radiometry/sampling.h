// SPDX-License-Identifier: Apache-2.0
// Direction sampling for the path tracer: a local shading frame built from a normal, and
// warps from two uniforms in [0, 1) to the uniform hemisphere, the cosine-weighted hemisphere
// (Malley's method over Shirley–Chiu's concentric disk) and a uniform cone (the sun disk),
// each with its pdf per steradian. Local directions have the normal along +z. The routines
// draw no random numbers themselves (the caller passes RandomStream::uniform() values) and
// never allocate. Formulas and tests: docs/physics.md, "Radiometry: sampling and BRDFs".
#pragma once

#include <array>

#include "glint/motion/geometry.h"

namespace glint::radiometry {

using motion::Vec3;

/// π.
inline constexpr double kPi = 3.14159265358979323846;
/// Mean angular radius of the solar disk seen from Earth: 0.2666° (≈ 16′), in radians.
inline constexpr double kSunAngularRadiusRad = 0.2666 * kPi / 180.0;

/// An orthonormal right-handed basis (s, t, n): n is the shading normal, local +z.
struct Frame {
    Vec3 s{1.0, 0.0, 0.0};  ///< local +x
    Vec3 t{0.0, 1.0, 0.0};  ///< local +y
    Vec3 n{0.0, 0.0, 1.0};  ///< local +z

    /// The frame with `n` (unit length) as +z, tangents by the branchless construction of
    /// Duff et al., "Building an orthonormal basis, revisited" (JCGT 6(1), 2017); continuous
    /// everywhere except across n.z = 0's sign flip, exact to rounding for every unit n.
    static Frame from_normal(const Vec3& n) noexcept;

    /// World direction `v` expressed in this frame (components along s, t, n).
    Vec3 to_local(const Vec3& v) const noexcept { return {dot(v, s), dot(v, t), dot(v, n)}; }
    /// Local direction `v` expressed in world coordinates.
    Vec3 to_world(const Vec3& v) const noexcept { return s * v.x + t * v.y + n * v.z; }
};

/// cos x and sin x.
struct CosSin {
    double cos = 1.0;
    double sin = 0.0;
};
/// cos x and sin x for |x| ≤ π/4 from their Taylor series to x¹⁶ and x¹⁵ (the first terms
/// left out are below 5 × 10⁻¹⁷ of the result there): within two units in the last place of
/// the correctly rounded values, without libm's range reduction. Outside that range the
/// error grows; the samplers never go there.
CosSin cos_sin_quarter(double x_rad) noexcept;
/// cos 2πt and sin 2πt for t in [0, 1) (a turn): the octant by exact reflections and swaps,
/// the rest by cos_sin_quarter — within two units in the last place.
CosSin cos_sin_turn(double turns) noexcept;

/// Maps (u1, u2) in [0, 1)² to the unit disk with Shirley and Chiu's concentric mapping
/// (area-preserving, low distortion); returns (x, y) with x² + y² ≤ 1.
std::array<double, 2> sample_concentric_disk(double u1, double u2) noexcept;

/// A direction uniform over the upper hemisphere (z ≥ 0): cos θ = u1, φ = 2π u2.
Vec3 sample_uniform_hemisphere(double u1, double u2) noexcept;
/// The pdf of sample_uniform_hemisphere: 1 / (2π) per steradian.
inline constexpr double uniform_hemisphere_pdf_per_sr() noexcept { return 1.0 / (2.0 * kPi); }

/// A direction on the upper hemisphere with density cos θ / π (Malley: a concentric-disk
/// point lifted to the hemisphere, z = √(1 − x² − y²)).
Vec3 sample_cosine_hemisphere(double u1, double u2) noexcept;
/// The pdf of sample_cosine_hemisphere at a direction with cosine `cos_theta` to the normal:
/// max(cos θ, 0) / π per steradian.
double cosine_hemisphere_pdf_per_sr(double cos_theta) noexcept;

/// The solid angle 2π (1 − cos α) = 4π sin²(α/2) of a cone of half-angle `half_angle_rad`
/// in [0, π], computed without cancellation for small cones (sun disk: ≈ 6.80 × 10⁻⁵ sr).
double cone_solid_angle_sr(double half_angle_rad) noexcept;
/// A direction uniform over the cone of half-angle `half_angle_rad` about +z:
/// 1 − cos θ = u1 (1 − cos α), φ = 2π u2 (sin θ from 1 − cos θ, so tiny cones keep their
/// precision).
Vec3 sample_uniform_cone(double u1, double u2, double half_angle_rad) noexcept;
/// 1 − cos α for a cone of half-angle `half_angle_rad`, without cancellation (2 sin²(α/2)).
double cone_one_minus_cos(double half_angle_rad) noexcept;
/// sample_uniform_cone for a cone given by its 1 − cos α (cone_one_minus_cos): the same
/// direction, without the sine of the half-angle on every draw.
Vec3 sample_uniform_cone_1mc(double u1, double u2, double one_minus_cos_alpha) noexcept;
/// The pdf of sample_uniform_cone inside the cone: 1 / cone_solid_angle_sr(half_angle_rad)
/// per steradian (0 outside; callers test membership with cone_contains).
double uniform_cone_pdf_per_sr(double half_angle_rad) noexcept;
/// Whether the local direction `v` (unit length) lies within the cone of half-angle
/// `half_angle_rad` about +z.
bool cone_contains(const Vec3& v, double half_angle_rad) noexcept;

}  // namespace glint::radiometry
