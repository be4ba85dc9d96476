// SPDX-License-Identifier: Apache-2.0
// Tests of the BRDFs in glint/radiometry/brdf.h. Lambertian: value ρ/π, reciprocity, albedo
// ρ (quadrature) and sample weight ρ. GGX: D and the visible-normal density integrate to 1
// (quadrature); reciprocity; chi-square fits (10 θ × 20 φ cells plus a "lost below the
// horizon" cell, pooling below 5 expected, p-value threshold 1e-3, fixed seeds) of the
// sampler at α ∈ {0.1, 0.3, 0.6, 1} and θo ∈ {0°, 30°, 60°, 85°}; sample weight = f cos/pdf;
// the albedo at α = 1, θo = 0 equals 1 − ln 2 (closed form);
// white furnace: every weight G₂/G₁ ≤ 1 and the Monte Carlo albedo ≤ 1 + 4 standard errors,
// agreeing within 4 combined standard errors with an independent cosine-sampled estimate.
// The mixed material gets the same chi-square, weight and albedo-bound checks.
#include "glint/radiometry/brdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <tuple>

#include "chi_square.h"
#include "glint/core/error.h"
#include "glint/core/rng.h"

namespace glint::radiometry {
namespace brdf_test {

using testing::chi_square_direction_test;
using testing::DirectionHistogram;
using testing::integrate_upper_hemisphere;
using testing::kChiSquarePValueThreshold;
using testing::local_direction;

constexpr std::uint64_t kSeed = 20260522;
constexpr int kChiSamples = 200000;
/// Standard errors allowed between a Monte Carlo estimate and its bound or reference.
constexpr double kSigmas = 4.0;

/// Mean and standard error of n weights.
struct Estimate {
    double mean = 0.0;
    double standard_error = 0.0;
};

template <typename Draw>
Estimate estimate(int n, Draw&& draw) {
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double w = draw();
        sum += w;
        sum2 += w * w;
    }
    const double mean = sum / n;
    const double var = std::max(0.0, sum2 / n - mean * mean) * n / (n - 1.0);
    return {mean, std::sqrt(var / n)};
}

// ---- Lambertian ------------------------------------------------------------------------

TEST(Lambertian, ValueReciprocityAndAlbedo) {
    const LambertianBrdf f(0.7);
    const Vec3 a = local_direction(20, 10), b = local_direction(70, 200);
    EXPECT_DOUBLE_EQ(f.eval(a, b), 0.7 / kPi);
    EXPECT_EQ(f.eval(a, b), f.eval(b, a));
    EXPECT_EQ(f.eval(a, Vec3{0.0, 0.6, -0.8}), 0.0);
    EXPECT_EQ(f.eval(Vec3{0.0, 0.6, -0.8}, a), 0.0);
    const double albedo =
        integrate_upper_hemisphere([&](const Vec3& wi) { return f.eval(a, wi) * wi.z; });
    EXPECT_NEAR(albedo, 0.7, 1e-9);
    RandomStream rng(kSeed, {1});
    for (int i = 0; i < 1000; ++i) {
        const auto s = f.sample(a, rng.uniform(), rng.uniform());
        ASSERT_TRUE(s.has_value());
        EXPECT_EQ(s->weight, 0.7);
        EXPECT_NEAR(s->pdf_per_sr, f.pdf_per_sr(a, s->wi), 1e-15);
    }
    EXPECT_FALSE(f.sample(Vec3{0.0, 0.0, -1.0}, 0.3, 0.3).has_value());
}

TEST(Lambertian, RejectsReflectanceOutsideUnitInterval) {
    EXPECT_THROW(LambertianBrdf(-0.1), Error);
    EXPECT_THROW(LambertianBrdf(1.01), Error);
    EXPECT_THROW(LambertianBrdf(std::nan("")), Error);
}

// ---- GGX -------------------------------------------------------------------------------

TEST(Ggx, DistributionAndVisibleNormalsAreNormalised) {
    for (double alpha : {0.05, 0.1, 0.3, 0.6, 1.0}) {
        const GgxBrdf g(alpha);
        // ∫ D(h) cos θh dωh = 1 (projected microfacet area equals the macro-surface).
        EXPECT_NEAR(
            integrate_upper_hemisphere([&](const Vec3& h) { return g.distribution(h) * h.z; }), 1.0,
            1e-4)
            << alpha;
        for (double theta_o : {0.0, 45.0, 80.0}) {
            const Vec3 wo = local_direction(theta_o, 30.0);
            // ∫ G₁(wo) max(0, wo·h) D(h) / cos θo dωh = 1 (Smith's G₁ is consistent with D).
            const double visible = integrate_upper_hemisphere([&](const Vec3& h) {
                return g.masking(wo) * std::max(0.0, dot(wo, h)) * g.distribution(h) / wo.z;
            });
            EXPECT_NEAR(visible, 1.0, 1e-4) << alpha << " " << theta_o;
        }
    }
}

TEST(Ggx, Reciprocity) {
    RandomStream rng(kSeed, {2});
    for (double alpha : {0.01, 0.2, 0.7, 1.0}) {
        const GgxBrdf g(alpha);
        for (int i = 0; i < 2000; ++i) {
            const Vec3 a = sample_uniform_hemisphere(rng.uniform(), rng.uniform());
            const Vec3 b = sample_uniform_hemisphere(rng.uniform(), rng.uniform());
            const double fab = g.eval(a, b), fba = g.eval(b, a);
            EXPECT_NEAR(fab, fba, 1e-12 * std::max(1.0, fab));
            EXPECT_GE(fab, 0.0);
        }
    }
}

TEST(Ggx, ChiSquareOfSampledDirections) {
    std::uint64_t stream = 100;
    for (double alpha : {0.1, 0.3, 0.6, 1.0}) {
        const GgxBrdf g(alpha);
        // Simpson panels per cell side: 48 keep the expected counts of the narrow grazing
        // lobe (α = 0.1, θo = 85°) within 0.1 standard deviation of a 128-panel reference;
        // 24 do as much for α ≥ 0.3.
        const int panels = alpha < 0.2 ? 48 : 24;
        for (double theta_o : {0.0, 30.0, 60.0, 85.0}) {
            const Vec3 wo = local_direction(theta_o, 40.0);
            const auto r = chi_square_direction_test(
                DirectionHistogram{}, kChiSamples,
                [&](double u1, double u2) -> std::optional<Vec3> {
                    const auto s = g.sample(wo, u1, u2);
                    if (!s) return std::nullopt;
                    return s->wi;
                },
                [&](const Vec3& wi) { return g.pdf_per_sr(wo, wi); }, kSeed, stream++, panels);
            EXPECT_GT(r.p_value, kChiSquarePValueThreshold)
                << "alpha " << alpha << " theta_o " << theta_o << " chi2 " << r.statistic << " dof "
                << r.dof;
            EXPECT_GT(r.dof, 10);
            ::testing::Test::RecordProperty(
                "ggx_a" + std::to_string(alpha) + "_t" + std::to_string(theta_o),
                "p=" + std::to_string(r.p_value) + " dof=" + std::to_string(r.dof));
        }
    }
}

TEST(Ggx, SampleWeightIsValueTimesCosineOverPdf) {
    RandomStream rng(kSeed, {3});
    for (double alpha : {0.001, 0.05, 0.4, 1.0}) {
        const GgxBrdf g(alpha);
        for (int i = 0; i < 2000; ++i) {
            const Vec3 wo = sample_uniform_hemisphere(rng.uniform(), rng.uniform());
            const auto s = g.sample(wo, rng.uniform(), rng.uniform());
            if (!s) continue;
            EXPECT_NEAR(norm(s->wi), 1.0, 1e-12);
            EXPECT_GT(s->wi.z, 0.0);
            const double expected = g.eval(wo, s->wi) * s->wi.z / g.pdf_per_sr(wo, s->wi);
            EXPECT_NEAR(s->weight, expected, 1e-9 * expected) << alpha;
            EXPECT_NEAR(s->pdf_per_sr, g.pdf_per_sr(wo, s->wi), 1e-12 * s->pdf_per_sr);
        }
    }
}

TEST(Ggx, WhiteFurnaceAlbedoWithinBound) {
    // Every weight G₂/G₁(wo) ≤ 1 bounds the albedo by 1; the Monte Carlo mean must respect it
    // and agree with an independent cosine-sampled estimate of ∫ f cos θi dωi.
    std::uint64_t stream = 200;
    constexpr int kN = 40000;
    for (double alpha : {0.001, 0.05, 0.3, 0.6, 1.0}) {
        const GgxBrdf g(alpha);
        for (double theta_o : {0.0, 30.0, 60.0, 80.0, 89.0}) {
            const Vec3 wo = local_direction(theta_o, 0.0);
            RandomStream rng(kSeed, {stream++});
            const Estimate e = estimate(kN, [&] {
                const auto s = g.sample(wo, rng.uniform(), rng.uniform());
                const double w = s ? s->weight : 0.0;
                EXPECT_LE(w, 1.0 + 1e-12);
                EXPECT_GE(w, 0.0);
                return w;
            });
            EXPECT_LE(e.mean, 1.0 + kSigmas * e.standard_error) << alpha << " " << theta_o;
            if (theta_o == 0.0 && alpha <= 0.05) {
                EXPECT_GT(e.mean, 0.99);
            }
            if (alpha >= 0.3) {
                const Estimate c = estimate(kN, [&] {
                    const Vec3 wi = sample_cosine_hemisphere(rng.uniform(), rng.uniform());
                    return kPi * g.eval(wo, wi);  // f cos / (cos/π)
                });
                const double se = std::hypot(e.standard_error, c.standard_error);
                EXPECT_NEAR(e.mean, c.mean, kSigmas * se) << alpha << " " << theta_o;
            }
        }
    }
}

TEST(Ggx, AnalyticAlbedoAtNormalIncidenceForAlphaOne) {
    // At α = 1, D = 1/π and, for wo = +z, G₂ = G₁(wi) = 2 cos θi/(1 + cos θi); with
    // c = cos θi = cos 2θh the albedo reduces to ∫₀¹ c/(1 + c) dc = 1 − ln 2.
    const GgxBrdf g(1.0);
    const Vec3 wo{0.0, 0.0, 1.0};
    const double exact = 1.0 - std::log(2.0);
    EXPECT_NEAR(integrate_upper_hemisphere([&](const Vec3& wi) { return g.eval(wo, wi) * wi.z; }),
                exact, 1e-6);
    RandomStream rng(kSeed, {7});
    const Estimate e = estimate(40000, [&] {
        const auto s = g.sample(wo, rng.uniform(), rng.uniform());
        return s ? s->weight : 0.0;
    });
    EXPECT_NEAR(e.mean, exact, kSigmas * e.standard_error);
}

TEST(Ggx, RejectsAlphaOutsideRange) {
    EXPECT_THROW(GgxBrdf(0.0), Error);
    EXPECT_THROW(GgxBrdf(1.5), Error);
    EXPECT_THROW(GgxBrdf(std::nan("")), Error);
    EXPECT_NO_THROW(GgxBrdf{kMinGgxAlpha});
}

// ---- Mixed material --------------------------------------------------------------------

TEST(SurfaceBrdf, ValueIsTheWeightedSumAndReciprocal) {
    const SurfaceBrdf m(0.4, 0.25, 0.5);
    EXPECT_DOUBLE_EQ(m.specular().alpha(), 0.25);
    EXPECT_DOUBLE_EQ(m.specular_probability(), 0.25);
    RandomStream rng(kSeed, {4});
    for (int i = 0; i < 2000; ++i) {
        const Vec3 a = sample_uniform_hemisphere(rng.uniform(), rng.uniform());
        const Vec3 b = sample_uniform_hemisphere(rng.uniform(), rng.uniform());
        const double f = m.eval(a, b);
        EXPECT_NEAR(f, 0.4 * (0.75 / kPi + 0.25 * m.specular().eval(a, b)), 1e-12 * f);
        EXPECT_NEAR(f, m.eval(b, a), 1e-12 * f);
    }
    EXPECT_DOUBLE_EQ(SurfaceBrdf(0.5, 0.0, 0.0).specular().alpha(), kMinGgxAlpha);
}

TEST(SurfaceBrdf, ChiSquareOfSampledDirections) {
    std::uint64_t stream = 300;
    for (double theta_o : {10.0, 50.0, 80.0}) {
        const SurfaceBrdf m(0.5, 0.3, 0.6);
        const Vec3 wo = local_direction(theta_o, 120.0);
        RandomStream lobe(kSeed, {stream + 1000});
        const auto r = chi_square_direction_test(
            DirectionHistogram{}, kChiSamples,
            [&](double u1, double u2) -> std::optional<Vec3> {
                const auto s = m.sample(wo, lobe.uniform(), u1, u2);
                if (!s) return std::nullopt;
                return s->wi;
            },
            [&](const Vec3& wi) { return m.pdf_per_sr(wo, wi); }, kSeed, stream++, 32);
        EXPECT_GT(r.p_value, kChiSquarePValueThreshold)
            << "theta_o " << theta_o << " chi2 " << r.statistic << " dof " << r.dof;
    }
}

TEST(SurfaceBrdf, SampleWeightAndAlbedoBound) {
    RandomStream rng(kSeed, {5});
    for (const auto& [rho, s, r] : {std::tuple{0.9, 0.2, 0.3}, std::tuple{1.0, 0.5, 1.0},
                                    std::tuple{0.0, 1.0, 0.1}, std::tuple{0.3, 0.0, 0.5}}) {
        const SurfaceBrdf m(rho, s, r);
        for (double theta_o : {0.0, 45.0, 85.0}) {
            const Vec3 wo = local_direction(theta_o, 0.0);
            const Estimate e = estimate(20000, [&] {
                const auto smp = m.sample(wo, rng.uniform(), rng.uniform(), rng.uniform());
                if (!smp) return 0.0;
                const double expected = m.eval(wo, smp->wi) * smp->wi.z / smp->pdf_per_sr;
                EXPECT_NEAR(smp->weight, expected, 1e-12 * std::max(1.0, expected));
                EXPECT_NEAR(smp->pdf_per_sr, m.pdf_per_sr(wo, smp->wi), 1e-12 * smp->pdf_per_sr);
                return smp->weight;
            });
            // Albedo ρ [(1 − s) + s E_GGX] ≤ ρ.
            EXPECT_LE(e.mean, rho + kSigmas * e.standard_error + 1e-12)
                << rho << " " << s << " " << r;
            if (s == 0.0) {
                EXPECT_NEAR(e.mean, rho, 1e-12);  // pure Lambertian: weight ≡ ρ
            }
        }
    }
}

TEST(SurfaceBrdf, BlackAndBelowHorizonGiveNoSample) {
    const SurfaceBrdf black(0.0, 0.0, 0.5);
    EXPECT_FALSE(black.sample(local_direction(30, 0), 0.5, 0.5, 0.5).has_value());
    EXPECT_EQ(black.eval(local_direction(30, 0), local_direction(40, 90)), 0.0);
    const SurfaceBrdf m(0.5, 0.5, 0.5);
    EXPECT_FALSE(m.sample(Vec3{0.0, 0.0, -1.0}, 0.5, 0.5, 0.5).has_value());
    EXPECT_EQ(m.pdf_per_sr(local_direction(30, 0), Vec3{0.0, 0.0, -1.0}), 0.0);
    EXPECT_THROW(SurfaceBrdf(0.5, 1.2, 0.5), Error);
    EXPECT_THROW(SurfaceBrdf(0.5, 0.5, -0.1), Error);
    EXPECT_THROW(SurfaceBrdf(2.0, 0.5, 0.5), Error);
}

TEST(SurfaceBrdf, Deterministic) {
    const SurfaceBrdf m(0.5, 0.3, 0.4);
    RandomStream a(kSeed, {6}), b(kSeed, {6});
    const Vec3 wo = local_direction(35, 10);
    for (int i = 0; i < 1000; ++i) {
        const auto sa = m.sample(wo, a.uniform(), a.uniform(), a.uniform());
        const auto sb = m.sample(wo, b.uniform(), b.uniform(), b.uniform());
        ASSERT_EQ(sa.has_value(), sb.has_value());
        if (!sa) continue;
        EXPECT_EQ(sa->wi, sb->wi);
        EXPECT_EQ(sa->weight, sb->weight);
        EXPECT_EQ(sa->pdf_per_sr, sb->pdf_per_sr);
    }
}

}  // namespace brdf_test
}  // namespace glint::radiometry
