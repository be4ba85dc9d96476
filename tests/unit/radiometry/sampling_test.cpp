// SPDX-License-Identifier: Apache-2.0
// Tests of the direction samplers in glint/radiometry/sampling.h: the shading frame is
// orthonormal and right-handed; each warp's pdf integrates to 1 (Simpson quadrature); and
// chi-square goodness-of-fit tests (10 θ × 20 φ cells, cells expected < 5 pooled, p-value
// threshold 1e-3, fixed seeds) show the samples follow the stated pdfs: uniform and cosine
// hemisphere, the 0.2666° sun disk and a wide cone. Also determinism and edge inputs.
#include "glint/radiometry/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "chi_square.h"
#include "glint/core/rng.h"

namespace glint::radiometry {
namespace sampling_test {

using testing::chi_square_direction_test;
using testing::DirectionHistogram;
using testing::kChiSquarePValueThreshold;

constexpr std::uint64_t kSeed = 20260521;
constexpr int kSamples = 200000;

double degrees(double d) { return d * kPi / 180.0; }

TEST(Frame, OrthonormalRightHandedForManyNormals) {
    RandomStream rng(kSeed, {1});
    for (int i = 0; i < 10000; ++i) {
        Vec3 n = sample_uniform_hemisphere(rng.uniform(), rng.uniform());
        if (i % 2) n.z = -n.z;  // both hemispheres, including n.z < 0 branch
        if (i == 0) n = {0.0, 0.0, 1.0};
        if (i == 1) n = {0.0, 0.0, -1.0};
        if (i == 2) n = {1.0, 0.0, 0.0};
        const Frame f = Frame::from_normal(n);
        EXPECT_NEAR(norm(f.s), 1.0, 1e-12);
        EXPECT_NEAR(norm(f.t), 1.0, 1e-12);
        EXPECT_NEAR(dot(f.s, f.t), 0.0, 1e-12);
        EXPECT_NEAR(dot(f.s, f.n), 0.0, 1e-12);
        EXPECT_NEAR(dot(f.t, f.n), 0.0, 1e-12);
        const Vec3 c = cross(f.s, f.t);
        EXPECT_NEAR(norm(c - f.n), 0.0, 1e-12);
        // Round trip and the normal maps to local +z.
        const Vec3 v{0.3, -0.4, 0.866};
        EXPECT_NEAR(norm(f.to_local(f.to_world(v)) - v), 0.0, 1e-12);
        EXPECT_NEAR(f.to_local(n).z, 1.0, 1e-12);
    }
}

TEST(ConcentricDisk, InsideUnitDiskAndCentred) {
    RandomStream rng(kSeed, {2});
    double sx = 0.0, sy = 0.0;
    for (int i = 0; i < 10000; ++i) {
        const auto p = sample_concentric_disk(rng.uniform(), rng.uniform());
        EXPECT_LE(p[0] * p[0] + p[1] * p[1], 1.0 + 1e-15);
        sx += p[0];
        sy += p[1];
    }
    EXPECT_NEAR(sx / 10000, 0.0, 0.02);
    EXPECT_NEAR(sy / 10000, 0.0, 0.02);
    const auto c = sample_concentric_disk(0.5, 0.5);
    EXPECT_EQ(c[0], 0.0);
    EXPECT_EQ(c[1], 0.0);
}

TEST(Pdfs, IntegrateToOne) {
    const DirectionHistogram hemi;  // θ ∈ [0, π/2]
    const auto cosine =
        hemi.expected(1.0, [](const Vec3& w) { return cosine_hemisphere_pdf_per_sr(w.z); });
    EXPECT_NEAR(1.0 - cosine.back(), 1.0, 1e-9);
    const auto uniform =
        hemi.expected(1.0, [](const Vec3&) { return uniform_hemisphere_pdf_per_sr(); });
    EXPECT_NEAR(1.0 - uniform.back(), 1.0, 1e-9);
    for (double half_deg : {0.2666, 5.0, 30.0, 90.0, 150.0}) {
        const double a = degrees(half_deg);
        DirectionHistogram cone;
        cone.theta_max_rad = a;
        const auto e = cone.expected(1.0, [a](const Vec3&) { return uniform_cone_pdf_per_sr(a); });
        EXPECT_NEAR(1.0 - e.back(), 1.0, 1e-9) << half_deg;
    }
}

/// Units in the last place of `reference` (its gap to the next double away from zero).
double ulp(double reference) {
    const double a = std::abs(reference);
    return std::nextafter(a, INFINITY) - a;
}

TEST(CosSin, QuarterIsWithinTwoUlpOfLibm) {
    // 400,001 evenly spaced angles over [−π/4, π/4] and tiny ones: the Taylor sums against
    // glibc's cos and sin (correctly rounded in practice); 2 ulp allows the Horner sums'
    // rounding.
    std::vector<double> angles{0.0, 1e-300, -1e-300, 1e-8, -1e-8, kPi / 4.0, -kPi / 4.0};
    for (int i = 0; i <= 400000; ++i) angles.push_back((kPi / 4.0) * (i / 200000.0 - 1.0));
    for (const double x : angles) {
        const CosSin r = cos_sin_quarter(x);
        EXPECT_LE(std::abs(r.cos - std::cos(x)), 2.0 * ulp(std::cos(x))) << x;
        EXPECT_LE(std::abs(r.sin - std::sin(x)), 2.0 * ulp(std::sin(x))) << x;
    }
}

TEST(CosSin, TurnMatchesLibmOnEveryOctant) {
    // cos 2πt and sin 2πt against libm's of the rounded 2πt: that argument alone carries
    // up to ½ ulp of 2π ≈ 4.4e-16 rad of error, so the bound is absolute, 1e-15; exact
    // values at the quarter turns; cos² + sin² = 1 within 4 ulp of 1.
    RandomStream rng(kSeed, {21});
    std::vector<double> turns{0.0,
                              0.125,
                              0.25,
                              0.375,
                              0.5,
                              0.625,
                              0.75,
                              0.875,
                              std::nextafter(1.0, 0.0),
                              std::nextafter(0.25, 0.0)};
    for (int i = 0; i < 200000; ++i) turns.push_back(rng.uniform());
    for (const double t : turns) {
        const CosSin r = cos_sin_turn(t);
        EXPECT_NEAR(r.cos, std::cos(2.0 * kPi * t), 1e-15) << t;
        EXPECT_NEAR(r.sin, std::sin(2.0 * kPi * t), 1e-15) << t;
        EXPECT_NEAR(r.cos * r.cos + r.sin * r.sin, 1.0, 4.0 * ulp(1.0)) << t;
    }
    EXPECT_EQ(cos_sin_turn(0.0).cos, 1.0);
    EXPECT_EQ(cos_sin_turn(0.0).sin, 0.0);
    EXPECT_EQ(cos_sin_turn(0.25).cos, 0.0);
    EXPECT_EQ(cos_sin_turn(0.25).sin, 1.0);
    EXPECT_EQ(cos_sin_turn(0.5).cos, -1.0);
    EXPECT_EQ(cos_sin_turn(0.75).sin, -1.0);
}

TEST(Cone, OneMinusCosGivesTheSameDirections) {
    RandomStream rng(kSeed, {22});
    const double one_minus_cos = cone_one_minus_cos(kSunAngularRadiusRad);
    for (int i = 0; i < 1000; ++i) {
        const double u1 = rng.uniform();
        const double u2 = rng.uniform();
        const Vec3 a = sample_uniform_cone(u1, u2, kSunAngularRadiusRad);
        const Vec3 b = sample_uniform_cone_1mc(u1, u2, one_minus_cos);
        EXPECT_EQ(a.x, b.x);
        EXPECT_EQ(a.y, b.y);
        EXPECT_EQ(a.z, b.z);
    }
}

TEST(Cone, SunDiskSolidAngle) {
    // Ω = 2π(1 − cos α), α = 0.2666°: 6.8018e-5 sr; its series πα²(1 − α²/12 + α⁴/360).
    const double a = kSunAngularRadiusRad;
    const double omega = cone_solid_angle_sr(a);
    EXPECT_NEAR(omega, 6.8018e-5, 1e-9);
    EXPECT_NEAR(omega, kPi * a * a * (1.0 - a * a / 12.0 + a * a * a * a / 360.0), 1e-19);
    EXPECT_DOUBLE_EQ(uniform_cone_pdf_per_sr(kSunAngularRadiusRad), 1.0 / omega);
    EXPECT_NEAR(cone_solid_angle_sr(kPi / 2.0), 2.0 * kPi, 1e-14);
    EXPECT_NEAR(cone_solid_angle_sr(kPi), 4.0 * kPi, 1e-14);
    EXPECT_EQ(uniform_cone_pdf_per_sr(0.0), 0.0);
}

TEST(Cone, SamplesStayInsideTheCone) {
    RandomStream rng(kSeed, {3});
    for (int i = 0; i < 10000; ++i) {
        const Vec3 w = sample_uniform_cone(rng.uniform(), rng.uniform(), kSunAngularRadiusRad);
        EXPECT_NEAR(norm(w), 1.0, 1e-14);
        EXPECT_TRUE(cone_contains(w, kSunAngularRadiusRad * (1.0 + 1e-9)));
    }
    EXPECT_TRUE(cone_contains({0.0, 0.0, 1.0}, 0.0));
    EXPECT_FALSE(cone_contains({std::sin(0.01), 0.0, std::cos(0.01)}, 0.009));
    EXPECT_TRUE(cone_contains({std::sin(0.01), 0.0, std::cos(0.01)}, 0.011));
}

TEST(Hemisphere, CosineSamplesAreUnitAndAbove) {
    RandomStream rng(kSeed, {4});
    for (int i = 0; i < 10000; ++i) {
        const Vec3 w = sample_cosine_hemisphere(rng.uniform(), rng.uniform());
        EXPECT_NEAR(norm(w), 1.0, 1e-12);
        EXPECT_GE(w.z, 0.0);
    }
    EXPECT_EQ(cosine_hemisphere_pdf_per_sr(-0.5), 0.0);
    EXPECT_DOUBLE_EQ(cosine_hemisphere_pdf_per_sr(1.0), 1.0 / kPi);
}

TEST(ChiSquare, UniformHemisphere) {
    const auto r = chi_square_direction_test(
        DirectionHistogram{}, kSamples,
        [](double u1, double u2) { return std::optional<Vec3>(sample_uniform_hemisphere(u1, u2)); },
        [](const Vec3& w) { return w.z >= 0.0 ? uniform_hemisphere_pdf_per_sr() : 0.0; }, kSeed,
        10);
    EXPECT_GT(r.p_value, kChiSquarePValueThreshold) << "chi2 " << r.statistic << " dof " << r.dof;
}

TEST(ChiSquare, CosineHemisphere) {
    const auto r = chi_square_direction_test(
        DirectionHistogram{}, kSamples,
        [](double u1, double u2) { return std::optional<Vec3>(sample_cosine_hemisphere(u1, u2)); },
        [](const Vec3& w) { return cosine_hemisphere_pdf_per_sr(w.z); }, kSeed, 11);
    EXPECT_GT(r.p_value, kChiSquarePValueThreshold) << "chi2 " << r.statistic << " dof " << r.dof;
    EXPECT_GT(r.dof, 150);
}

TEST(ChiSquare, SunDiskAndWideCone) {
    std::uint64_t stream = 12;
    for (double a : {kSunAngularRadiusRad, degrees(30.0), degrees(120.0)}) {
        DirectionHistogram hist;
        hist.theta_max_rad = a;
        const auto r = chi_square_direction_test(
            hist, kSamples,
            [a](double u1, double u2) {
                return std::optional<Vec3>(sample_uniform_cone(u1, u2, a));
            },
            [a](const Vec3&) { return uniform_cone_pdf_per_sr(a); }, kSeed, stream++);
        EXPECT_GT(r.p_value, kChiSquarePValueThreshold)
            << "half-angle " << a << " chi2 " << r.statistic << " dof " << r.dof;
        EXPECT_GT(r.dof, 150);
    }
}

TEST(ChiSquare, DetectsAWrongPdf) {
    // The test has power: cosine samples against the uniform pdf fail decisively.
    const auto r = chi_square_direction_test(
        DirectionHistogram{}, kSamples,
        [](double u1, double u2) { return std::optional<Vec3>(sample_cosine_hemisphere(u1, u2)); },
        [](const Vec3&) { return uniform_hemisphere_pdf_per_sr(); }, kSeed, 20);
    EXPECT_LT(r.p_value, 1e-12);
}

TEST(Determinism, SameUniformsSameDirections) {
    RandomStream a(kSeed, {5}), b(kSeed, {5});
    for (int i = 0; i < 1000; ++i) {
        const double u1 = a.uniform(), u2 = a.uniform();
        EXPECT_EQ(u1, b.uniform());
        EXPECT_EQ(u2, b.uniform());
        EXPECT_EQ(sample_cosine_hemisphere(u1, u2), sample_cosine_hemisphere(u1, u2));
        EXPECT_EQ(sample_uniform_cone(u1, u2, kSunAngularRadiusRad),
                  sample_uniform_cone(u1, u2, kSunAngularRadiusRad));
    }
}

}  // namespace sampling_test
}  // namespace glint::radiometry
