// SPDX-License-Identifier: Apache-2.0
// Tests of Ward's lobe, DIRSIG's Ward BRDF and the Ross–Li kernels (glint/radiometry/
// brdf_models.h).
// Ward: the slope distribution integrates to 1 (the normalisation Ward's formula rests on);
// reciprocity; chi-square fits of the sampler (10 θ × 20 φ cells plus the "lost" cell,
// pooling below 5 expected, p-value threshold 1e-3, fixed seeds) isotropic and anisotropic
// at θo up to 80°; sample weight = f cos/pdf; white furnace: directional albedo ≤ 1 at every
// θo (the 1992 form loses energy at oblique incidence, it never gains it) and, at normal
// incidence, within 1 % of 1 for α = 0.05 (the lobe's small-α normalisation).
// Ross–Li: both kernels vanish when sun and view are at nadir; reciprocity; the white-sky
// (bihemispherical) integrals of the two kernels against Lucht, Schaaf & Strahler (2000),
// Table 1: 0.189184 (Ross-Thick) and −1.377622 (Li-Sparse-Reciprocal); their black-sky
// polynomials g₀ + g₁θ² + g₂θ³ at 0–60°; the sampler's chi-square.
#include "glint/radiometry/brdf_models.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <utility>

#include "chi_square.h"
#include "glint/core/error.h"
#include "glint/core/rng.h"

namespace glint::radiometry {
namespace brdf_models_test {

using testing::chi_square_direction_test;
using testing::DirectionHistogram;
using testing::integrate_upper_hemisphere;
using testing::kChiSquarePValueThreshold;
using testing::local_direction;

constexpr std::uint64_t kSeed = 20261128;
constexpr int kChiSamples = 200000;

// ---- Ward ------------------------------------------------------------------------------

TEST(Ward, SlopeDistributionIsNormalised) {
    // ∫ p_h dω_h = 1 exactly (closed form); Simpson on the grid resolves it to 1e-4.
    for (const auto& [ax, ay] : {std::pair{0.1, 0.1}, std::pair{0.3, 0.1}, std::pair{0.5, 0.5}}) {
        const WardLobe lobe(ax, ay);
        EXPECT_NEAR(integrate_upper_hemisphere(
                        [&](const Vec3& h) { return lobe.half_vector_pdf_per_sr(h); }, 16),
                    1.0, 1e-4)
            << ax << " " << ay;
    }
}

TEST(Ward, Reciprocity) {
    const WardLobe lobe(0.2, 0.08);
    for (const auto& [a, b] : {std::pair{local_direction(10, 0), local_direction(40, 170)},
                               std::pair{local_direction(70, 30), local_direction(65, 200)},
                               std::pair{local_direction(5, 90), local_direction(85, 271)}}) {
        EXPECT_DOUBLE_EQ(lobe.eval(a, b), lobe.eval(b, a));
        EXPECT_GT(lobe.eval(a, b), 0.0);
    }
    EXPECT_EQ(lobe.eval(local_direction(30, 0), Vec3{0.0, 0.6, -0.8}), 0.0);
}

TEST(Ward, ChiSquareOfSampledDirections) {
    std::uint64_t stream = 10;
    for (const auto& [ax, ay] : {std::pair{0.1, 0.1}, std::pair{0.3, 0.3}, std::pair{0.25, 0.08}}) {
        const WardLobe lobe(ax, ay);
        for (double theta_o : {0.0, 40.0, 80.0}) {
            const Vec3 wo = local_direction(theta_o, 35.0);
            const auto r = chi_square_direction_test(
                DirectionHistogram{}, kChiSamples,
                [&](double u1, double u2) -> std::optional<Vec3> {
                    const auto s = lobe.sample(wo, u1, u2);
                    if (!s) return std::nullopt;
                    return s->wi;
                },
                [&](const Vec3& wi) { return lobe.pdf_per_sr(wo, wi); }, kSeed, stream++, 48);
            EXPECT_GT(r.p_value, kChiSquarePValueThreshold)
                << ax << "," << ay << " theta_o " << theta_o << " chi2 " << r.statistic << " dof "
                << r.dof;
            EXPECT_GE(r.dof, 10);
        }
    }
}

TEST(Ward, SampleWeightIsValueTimesCosineOverPdfAndAlbedoAtMostOne) {
    RandomStream rng(kSeed, {77});
    for (const auto& [ax, ay] : {std::pair{0.05, 0.05}, std::pair{0.3, 0.1}, std::pair{0.5, 0.5}}) {
        const WardLobe lobe(ax, ay);
        for (double theta_o : {0.0, 30.0, 60.0, 85.0}) {
            const Vec3 wo = local_direction(theta_o, 10.0);
            // The albedo by quadrature of f cos θi (a fine grid for the narrow lobes).
            const double albedo = integrate_upper_hemisphere(
                [&](const Vec3& wi) { return lobe.eval(wo, wi) * wi.z; }, 32);
            EXPECT_LE(albedo, 1.0 + 1e-3) << ax << " theta_o " << theta_o;
            for (int i = 0; i < 200; ++i) {
                const auto s = lobe.sample(wo, rng.uniform(), rng.uniform());
                if (!s) continue;
                EXPECT_NEAR(s->weight, lobe.eval(wo, s->wi) * s->wi.z / s->pdf_per_sr,
                            1e-12 * (1.0 + s->weight));
            }
            if (ax == 0.05 && theta_o == 0.0) {
                EXPECT_NEAR(albedo, 1.0, 0.01);
            }
        }
    }
}

TEST(Ward, MixtureIsTheWeightedSumAndSamplesItsPdf) {
    const WardBrdf brdf(0.4, 0.6, 0.15, 0.15);
    const Vec3 wo = local_direction(50.0, 200.0);
    const Vec3 wi = local_direction(30.0, 10.0);
    EXPECT_DOUBLE_EQ(brdf.eval(wo, wi), 0.4 / kPi + 0.6 * brdf.lobe().eval(wo, wi));
    RandomStream lobe_choice(kSeed, {900});
    const auto r = chi_square_direction_test(
        DirectionHistogram{}, kChiSamples,
        [&](double u1, double u2) -> std::optional<Vec3> {
            const auto s = brdf.sample(wo, lobe_choice.uniform(), u1, u2);
            if (!s) return std::nullopt;
            return s->wi;
        },
        [&](const Vec3& w) { return brdf.pdf_per_sr(wo, w); }, kSeed, 901, 32);
    EXPECT_GT(r.p_value, kChiSquarePValueThreshold) << r.statistic << " dof " << r.dof;
}

TEST(Ward, RefusesOutOfRangeParameters) {
    EXPECT_THROW(WardLobe(0.0, 0.1), Error);
    EXPECT_THROW(WardLobe(0.1, 1.5), Error);
    EXPECT_THROW(WardBrdf(0.5, 0.6, 0.1, 0.1), Error);
    EXPECT_THROW(WardBrdf(-0.1, 1.1, 0.1, 0.1), Error);
}

// ---- Ross–Li ---------------------------------------------------------------------------

double k_vol(const Vec3& a, const Vec3& b) { return ross_thick_kernel(a, b); }
double k_geo(const Vec3& a, const Vec3& b) {
    return li_sparse_reciprocal_kernel(a, b, kRossLiHeightOverBreadth, kRossLiBreadthOverRadius);
}

/// The black-sky integral (1/π) ∫ K(wo, wi) cos θi dωi at sun zenith θ.
double black_sky(double (*kernel)(const Vec3&, const Vec3&), double theta_deg) {
    const Vec3 sun = local_direction(theta_deg, 0.0);
    return integrate_upper_hemisphere([&](const Vec3& v) { return kernel(sun, v) * v.z; }, 8) / kPi;
}

TEST(RossLi, KernelsVanishAtNadirAndAreReciprocal) {
    const Vec3 nadir{0.0, 0.0, 1.0};
    EXPECT_NEAR(k_vol(nadir, nadir), 0.0, 1e-15);
    EXPECT_NEAR(k_geo(nadir, nadir), 0.0, 1e-15);
    for (const auto& [a, b] : {std::pair{local_direction(10, 0), local_direction(40, 170)},
                               std::pair{local_direction(70, 30), local_direction(65, 200)}}) {
        EXPECT_NEAR(k_vol(a, b), k_vol(b, a), 1e-14);
        EXPECT_NEAR(k_geo(a, b), k_geo(b, a), 1e-14);
    }
    // The hot spot (view = sun): D = 0, t = π/2, O = sec θ', so K_geo = sec θ' (sec θ' − 1).
    const Vec3 s = local_direction(45.0, 0.0);
    EXPECT_NEAR(k_geo(s, s), std::sqrt(2.0) * (std::sqrt(2.0) - 1.0), 1e-12);
}

TEST(RossLi, WhiteSkyIntegralsMatchLuchtEtAl2000) {
    // White-sky = 2 ∫₀^{π/2} black-sky(θ) sin θ cos θ dθ; Gauss–Legendre in μ = cos θ² …
    // here Simpson in θ over 45 panels of the black-sky integral.
    for (const auto& [kernel, published] :
         {std::pair{&k_vol, 0.189184}, std::pair{&k_geo, -1.377622}}) {
        const int n = 90;
        double sum = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double t = (kPi / 2.0) * i / n;
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            const double theta_deg = std::min(t * 180.0 / kPi, 89.9);
            sum += w * black_sky(kernel, theta_deg) * std::sin(t) * std::cos(t);
        }
        const double white_sky = 2.0 * sum * (kPi / 2.0 / n) / 3.0;
        // 2e-4: the published values are quadratures to 6 digits; this grid (90 × 16 cells of
        // 8 × 8 Simpson panels, 46 sun zeniths) resolves ours to about 1e-4.
        EXPECT_NEAR(white_sky, published, 2e-4);
    }
}

TEST(RossLi, BlackSkyIntegralsFollowThePublishedPolynomials) {
    // Lucht et al. (2000), Table 1: black-sky(θ) ≈ g₀ + g₁ θ² + g₂ θ³ (θ in radians). The
    // polynomial is a three-term fit over 0–90°, not an identity: against these kernels (whose
    // white-sky integrals match the paper to 5 digits, above) its residual up to 60° is at
    // most 0.0184 (Ross-Thick at 40°) and 0.0061 (Li-Sparse-R at 60°), the same by an
    // independent NumPy quadrature; hence 0.02.
    for (double theta_deg : {0.0, 20.0, 40.0, 60.0}) {
        const double t = theta_deg * kPi / 180.0;
        EXPECT_NEAR(black_sky(&k_vol, theta_deg),
                    -0.007574 - 0.070987 * t * t + 0.307588 * t * t * t, 0.02)
            << theta_deg;
        EXPECT_NEAR(black_sky(&k_geo, theta_deg),
                    -1.284909 - 0.166314 * t * t + 0.041840 * t * t * t, 0.02)
            << theta_deg;
    }
}

TEST(RossLi, ValueSamplingAndClamp) {
    const RossLiBrdf brdf(0.4, 0.1);
    const Vec3 wo = local_direction(35.0, 0.0);
    const Vec3 wi = local_direction(50.0, 120.0);
    EXPECT_DOUBLE_EQ(brdf.eval(wo, wi), (1.0 + 0.4 * k_vol(wo, wi) + 0.1 * k_geo(wo, wi)) / kPi);
    EXPECT_DOUBLE_EQ(brdf.eval(wo, wi), brdf.eval(wi, wo));
    // A strongly negative geometric weight would give a negative value: clamped to 0.
    EXPECT_EQ(RossLiBrdf(0.0, 5.0).eval(local_direction(80, 0), local_direction(80, 180)), 0.0);
    const auto r = chi_square_direction_test(
        DirectionHistogram{}, kChiSamples,
        [&](double u1, double u2) -> std::optional<Vec3> {
            const auto s = brdf.sample(wo, u1, u2);
            if (!s) return std::nullopt;
            return s->wi;
        },
        [&](const Vec3& w) { return brdf.pdf_per_sr(wo, w); }, kSeed, 950, 16);
    EXPECT_GT(r.p_value, kChiSquarePValueThreshold);
    const auto s = brdf.sample(wo, 0.3, 0.7);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->weight, kPi * brdf.eval(wo, s->wi), 1e-12);
    EXPECT_THROW(RossLiBrdf(std::nan(""), 0.0), Error);
}

}  // namespace brdf_models_test
}  // namespace glint::radiometry
