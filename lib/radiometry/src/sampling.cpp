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

namespace {

/// (−1)ᵏ / (2k)! and (−1)ᵏ / (2k + 1)!, k = 0 … 8: the Taylor coefficients of cos and sin.
struct TaylorCoefficients {
    double cos[9]{};
    double sin[9]{};
};
constexpr TaylorCoefficients taylor_coefficients() {
    TaylorCoefficients c;
    double factorial = 1.0;  // n!, exact in double up to 18! (< 2⁵³ · 2⁶)
    double sign = 1.0;
    for (int k = 0; k < 9; ++k) {
        if (k > 0) factorial *= static_cast<double>(2 * k - 1) * static_cast<double>(2 * k);
        c.cos[k] = sign / factorial;
        c.sin[k] = sign / (factorial * static_cast<double>(2 * k + 1));
        sign = -sign;
    }
    return c;
}
constexpr TaylorCoefficients kTaylor = taylor_coefficients();

}  // namespace

CosSin cos_sin_quarter(double x_rad) noexcept {
    // Both series are polynomials in y = x², summed by Estrin's scheme (pairs, then pairs of
    // pairs) rather than Horner's: a third of the dependent steps.
    const double* c = kTaylor.cos;
    const double* s = kTaylor.sin;
    const double y = x_rad * x_rad;
    const double y2 = y * y;
    const double y4 = y2 * y2;
    const double cos_low = (c[0] + c[1] * y) + (c[2] + c[3] * y) * y2;
    const double cos_high = (c[4] + c[5] * y) + (c[6] + c[7] * y) * y2;
    const double sin_low = (s[0] + s[1] * y) + (s[2] + s[3] * y) * y2;
    const double sin_high = (s[4] + s[5] * y) + (s[6] + s[7] * y) * y2;
    return {cos_low + (cos_high + c[8] * y4) * y4, (sin_low + sin_high * y4) * x_rad};
}

CosSin cos_sin_turn(double turns) noexcept {
    // 8t = octant + f. Even octants: φ = quadrant · π/2 + f · π/4; odd ones: the next
    // quadrant's start minus (1 − f) · π/4, so the reduced angle stays within ±π/4.
    const double eighths = 8.0 * turns;
    const double octant = std::floor(eighths);
    const double f = eighths - octant;
    const auto o = static_cast<int>(octant);
    const int quadrant = (o + (o & 1)) / 2;
    const CosSin r = cos_sin_quarter((o & 1) != 0 ? -(kPi / 4.0) * (1.0 - f) : (kPi / 4.0) * f);
    switch (quadrant & 3) {
        case 0:
            return r;
        case 1:
            return {-r.sin, r.cos};
        case 2:
            return {-r.cos, -r.sin};
        default:
            return {r.sin, -r.cos};
    }
}

std::array<double, 2> sample_concentric_disk(double u1, double u2) noexcept {
    const double x = 2.0 * u1 - 1.0;
    const double y = 2.0 * u2 - 1.0;
    if (x == 0.0 && y == 0.0) return {0.0, 0.0};
    // φ = (π/4)(y/x), or π/2 − (π/4)(x/y): cos and sin of an angle within ±π/4.
    if (std::abs(x) > std::abs(y)) {
        const CosSin a = cos_sin_quarter((kPi / 4.0) * (y / x));
        return {x * a.cos, x * a.sin};
    }
    const CosSin a = cos_sin_quarter((kPi / 4.0) * (x / y));
    return {y * a.sin, y * a.cos};
}

Vec3 sample_uniform_hemisphere(double u1, double u2) noexcept {
    const double z = u1;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const CosSin a = cos_sin_turn(u2);  // φ = 2π u2
    return {r * a.cos, r * a.sin, z};
}

Vec3 sample_cosine_hemisphere(double u1, double u2) noexcept {
    const auto d = sample_concentric_disk(u1, u2);
    const double z = std::sqrt(std::max(0.0, 1.0 - d[0] * d[0] - d[1] * d[1]));
    return {d[0], d[1], z};
}

double cosine_hemisphere_pdf_per_sr(double cos_theta) noexcept {
    return std::max(cos_theta, 0.0) / kPi;
}

double cone_one_minus_cos(double half_angle_rad) noexcept {
    const double s = std::sin(0.5 * half_angle_rad);
    return 2.0 * s * s;
}

double cone_solid_angle_sr(double half_angle_rad) noexcept {
    return 2.0 * kPi * cone_one_minus_cos(half_angle_rad);
}

Vec3 sample_uniform_cone_1mc(double u1, double u2, double one_minus_cos_alpha) noexcept {
    const double d = u1 * one_minus_cos_alpha;  // 1 − cos θ
    const double cos_theta = 1.0 - d;
    const double sin_theta = std::sqrt(std::max(0.0, d * (2.0 - d)));
    const CosSin a = cos_sin_turn(u2);  // φ = 2π u2
    return {sin_theta * a.cos, sin_theta * a.sin, cos_theta};
}

Vec3 sample_uniform_cone(double u1, double u2, double half_angle_rad) noexcept {
    return sample_uniform_cone_1mc(u1, u2, cone_one_minus_cos(half_angle_rad));
}

double uniform_cone_pdf_per_sr(double half_angle_rad) noexcept {
    const double omega = cone_solid_angle_sr(half_angle_rad);
    return omega > 0.0 ? 1.0 / omega : 0.0;
}

bool cone_contains(const Vec3& v, double half_angle_rad) noexcept {
    // Compare 1 − cos θ = |v − z|²/2 (no cancellation) with 1 − cos α.
    const double dx = v.x, dy = v.y, dz = v.z - 1.0;
    const double d = 0.5 * (dx * dx + dy * dy + dz * dz);
    return d <= cone_one_minus_cos(half_angle_rad);
}

}  // namespace glint::radiometry
