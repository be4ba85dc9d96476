// SPDX-License-Identifier: Apache-2.0
// Direction sampling warps (hemisphere, cosine hemisphere, cone) and the orthonormal shading
// frame. Each warp maps two uniforms to a direction deterministically; the pdfs here are the
// ones the chi-square tests in tests/unit/radiometry/sampling_test.cpp check.
#include "glint/radiometry/sampling.h"

#include <algorithm>
#include <cmath>

namespace glint::radiometry {

Frame Frame::from_normal(const Vec3& n) noexcept {
    // Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin (2017), listing 3.
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    Frame f;
    f.s = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    f.t = {b, sign + n.y * n.y * a, -n.y};
    f.n = n;
    return f;
}

std::array<double, 2> sample_concentric_disk(double u1, double u2) noexcept {
    const double x = 2.0 * u1 - 1.0;
    const double y = 2.0 * u2 - 1.0;
    if (x == 0.0 && y == 0.0) return {0.0, 0.0};
    double r = 0.0;
    double phi = 0.0;
    if (std::abs(x) > std::abs(y)) {
        r = x;
        phi = (kPi / 4.0) * (y / x);
    } else {
        r = y;
        phi = (kPi / 2.0) - (kPi / 4.0) * (x / y);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

Vec3 sample_uniform_hemisphere(double u1, double u2) noexcept {
    const double z = u1;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Vec3 sample_cosine_hemisphere(double u1, double u2) noexcept {
    const auto d = sample_concentric_disk(u1, u2);
    const double z = std::sqrt(std::max(0.0, 1.0 - d[0] * d[0] - d[1] * d[1]));
    return {d[0], d[1], z};
}

double cosine_hemisphere_pdf_per_sr(double cos_theta) noexcept {
    return std::max(cos_theta, 0.0) / kPi;
}

namespace {

/// 1 − cos α, without cancellation: 2 sin²(α/2).
double one_minus_cos(double angle_rad) noexcept {
    const double s = std::sin(0.5 * angle_rad);
    return 2.0 * s * s;
}

}  // namespace

double cone_solid_angle_sr(double half_angle_rad) noexcept {
    return 2.0 * kPi * one_minus_cos(half_angle_rad);
}

Vec3 sample_uniform_cone(double u1, double u2, double half_angle_rad) noexcept {
    const double d = u1 * one_minus_cos(half_angle_rad);  // 1 − cos θ
    const double cos_theta = 1.0 - d;
    const double sin_theta = std::sqrt(std::max(0.0, d * (2.0 - d)));
    const double phi = 2.0 * kPi * u2;
    return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

double uniform_cone_pdf_per_sr(double half_angle_rad) noexcept {
    const double omega = cone_solid_angle_sr(half_angle_rad);
    return omega > 0.0 ? 1.0 / omega : 0.0;
}

bool cone_contains(const Vec3& v, double half_angle_rad) noexcept {
    // Compare 1 − cos θ = |v − z|²/2 (no cancellation) with 1 − cos α.
    const double dx = v.x, dy = v.y, dz = v.z - 1.0;
    const double d = 0.5 * (dx * dx + dy * dy + dz * dz);
    return d <= one_minus_cos(half_angle_rad);
}

}  // namespace glint::radiometry
