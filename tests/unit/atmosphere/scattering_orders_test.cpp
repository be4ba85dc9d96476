// SPDX-License-Identifier: Apache-2.0
// Tests of the successive-orders-of-scattering solver (glint/atmosphere/scattering_orders.h)
// against published plane-parallel tables: Rayleigh scattering (R. D. Sweigart, "Radiative
// transfer in atmospheres scattering according to the Rayleigh phase function with
// absorption", Astrophysical Journal Supplement 22, 1970, 1–80, Table 1) and
// Henyey–Greenstein scattering (H. C. van de Hulst, "Multiple Light Scattering", Academic
// Press, 1980, Table 37), both as reproduced by DISORT's test problems 2 and 3 (K. Stamnes,
// S.-C. Tsay, W. Wiscombe, K. Jayaweera, Applied Optics 27, 1988, 2502–2509), and energy
// conservation.
#include "glint/atmosphere/scattering_orders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/test/angles.h"

namespace glint::atmosphere {
namespace scattering_orders_test {

using glint::test::kPi;

ScatteringProblem one_layer(double tau, double omega, std::vector<double> moments, double mu0) {
    ScatteringProblem p;
    p.layers = {ScatteringLayer{tau, omega, std::move(moments)}};
    p.sun_cos_zenith = mu0;
    p.streams = 16;
    p.azimuth_modes = 1;
    p.max_sublayer_depth = 0.01;
    p.tolerance = 1e-7;
    return p;
}

const std::vector<double> kRayleigh{1.0, 0.0, 0.1};

/// ThickAtmospheres…: the linear source within a sublayer errs as Δτ²; measured at Δτ 0.049:
/// −0.19 % (ω 0.9) and −0.16 % (ω 0.99) of the reflected flux; asserted to 0.5 % — the tables' own
/// bound, a quarter of the 2 % asked of the atmosphere model.
constexpr double kThickTolerance = 0.005;

std::vector<double> henyey_greenstein(double g, int count) {
    std::vector<double> out;
    for (int l = 0; l < count; ++l) out.push_back(std::pow(g, l));
    return out;
}

/// The published values are for a beam of irradiance π (fluxes in units of π·F); ours are
/// for 1. Measured: every flux within 0.05 % (the tables give 5-6 digits; the rest is the
/// solver's discretization, 16 streams and sublayers of 0.01). Tolerance 0.5 %, a quarter
/// of the 2 % asked of the atmosphere model.
void expect_flux(double ours, double published_for_pi, const char* what) {
    std::printf("%s: %.6g vs %.6g (%+.3f %%)\n", what, ours * kPi, published_for_pi,
                100.0 * (ours * kPi / published_for_pi - 1.0));
    EXPECT_NEAR(ours, published_for_pi / kPi, 0.005 * published_for_pi / kPi) << what;
}

TEST(ScatteringOrders, RayleighThinAtmosphereLowSunMatchesSweigart) {
    // τ = 0.2, μ₀ = 0.080442, black ground (Sweigart Table 1; DISORT test 2b and 2a).
    const auto b = solve_scattering_orders(one_layer(0.2, 1.0, kRayleigh, 0.080442));
    expect_flux(b.direct_flux(1), 2.10311e-2, "direct at the ground");
    expect_flux(b.diffuse_down_flux(1), 1.06123e-1, "diffuse down at the ground");
    expect_flux(b.diffuse_up_flux(0), 1.25561e-1, "up at the top");
    const auto a = solve_scattering_orders(one_layer(0.2, 0.5, kRayleigh, 0.080442));
    expect_flux(a.diffuse_down_flux(1), 4.41791e-2, "diffuse down, omega 0.5");
    expect_flux(a.diffuse_up_flux(0), 5.35063e-2, "up, omega 0.5");
}

TEST(ScatteringOrders, RayleighThickAtmosphereMatchesSweigart) {
    // τ = 5 (DISORT test 2d and 2c).
    const auto d = solve_scattering_orders(one_layer(5.0, 1.0, kRayleigh, 0.080442));
    expect_flux(d.diffuse_down_flux(1), 2.68008e-2, "diffuse down at the ground");
    expect_flux(d.diffuse_up_flux(0), 2.25915e-1, "up at the top");
    const auto c = solve_scattering_orders(one_layer(5.0, 0.5, kRayleigh, 0.080442));
    expect_flux(c.diffuse_down_flux(1), 2.51683e-4, "diffuse down, omega 0.5");
    expect_flux(c.diffuse_up_flux(0), 6.24730e-2, "up, omega 0.5");
}

TEST(ScatteringOrders, ThickAtmospheresGetThickerSublayersAndStayRight) {
    // Past a total optical depth of 41 the sublayers grow (at most 2,048). At τ = 100, the
    // most aerosol the reader takes, they are 0.049 thick where 0.02 was asked. Reference:
    // the same layer at τ = 40 in sublayers of 0.02 (under the cap): both are semi-infinite
    // for what they reflect (e^-40 ≈ 4e-18 of the beam reaches the bottom).
    for (const double omega : {0.9, 0.99}) {
        ScatteringProblem thick = one_layer(100.0, omega, henyey_greenstein(0.7, 16), 0.5);
        ScatteringProblem reference = one_layer(40.0, omega, henyey_greenstein(0.7, 16), 0.5);
        thick.streams = reference.streams = 8;
        thick.max_sublayer_depth = reference.max_sublayer_depth = 0.02;
        const double up = solve_scattering_orders(thick).diffuse_up_flux(0);
        const double want = solve_scattering_orders(reference).diffuse_up_flux(0);
        std::printf("omega %.2f: reflected %.6g vs %.6g (%+.3f %%)\n", omega, up, want,
                    100.0 * (up / want - 1.0));
        EXPECT_NEAR(up, want, kThickTolerance * want) << omega;
    }
}

TEST(ScatteringOrders, AnOpaqueAtmosphereStaysBoundedAndDark) {
    // τ = 10^6 and 3·10^9 (beyond INT_MAX sublayers of 0.01: the count is bounded before it
    // becomes an int). At most 2,048 sublayers: it solves in a moment, lets nothing through
    // and stays finite (its sublayers of ~500 make what it reflects coarse: only bounds are
    // asserted; the reader refuses aerosol depths past 100).
    for (const double tau : {1e6, 3e9}) {
        ScatteringProblem p = one_layer(tau, 0.9, kRayleigh, 0.5);
        p.streams = 4;
        const auto s = solve_scattering_orders(p);
        EXPECT_EQ(s.direct_flux(1), 0.0) << tau;
        EXPECT_LT(s.diffuse_down_flux(1), 1e-12) << tau;
        EXPECT_GT(s.diffuse_up_flux(0), 0.0) << tau;
        EXPECT_LT(s.diffuse_up_flux(0), 0.5) << tau;
        EXPECT_DOUBLE_EQ(s.optical_depth(1), tau);
    }
    ScatteringProblem infinite = one_layer(1e308, 0.9, kRayleigh, 0.5);
    infinite.layers.push_back(infinite.layers.front());
    EXPECT_THROW((void)solve_scattering_orders(infinite), Error);
}

TEST(ScatteringOrders, HenyeyGreensteinMatchesVanDeHulst) {
    // g = 0.75, τ = 1, overhead sun (van de Hulst Table 37; DISORT test 3a), 32 moments.
    const auto s = solve_scattering_orders(one_layer(1.0, 1.0, henyey_greenstein(0.75, 32), 1.0));
    expect_flux(s.direct_flux(1), 1.15573, "direct at the ground");
    expect_flux(s.diffuse_down_flux(1), 1.73849, "diffuse down at the ground");
    expect_flux(s.diffuse_up_flux(0), 2.47374e-1, "up at the top");
}

TEST(ScatteringOrders, ConservesEnergyAndCouplesToTheGround) {
    // Conservative scattering: what enters leaves at the top or reaches the ground, where an
    // albedo A sends A times it back up.
    for (double albedo : {0.0, 0.3, 0.8}) {
        ScatteringProblem p;
        p.layers = {ScatteringLayer{0.3, 1.0, kRayleigh},
                    ScatteringLayer{0.2, 1.0, henyey_greenstein(0.7, 16)}};
        p.sun_cos_zenith = 0.6;
        p.ground_albedo = albedo;
        p.tolerance = 1e-9;
        const auto s = solve_scattering_orders(p);
        const double down = s.direct_flux(2) + s.diffuse_down_flux(2);
        EXPECT_NEAR(s.diffuse_up_flux(2), albedo * down, 1e-6);
        EXPECT_NEAR(s.diffuse_up_flux(0) + down - s.diffuse_up_flux(2), 0.6, 2e-4) << albedo;
    }
}

TEST(ScatteringOrders, FirstOrderMatchesTheSingleScatterFormula) {
    // Rayleigh, sensor above the atmosphere looking down at μ: single scattering gives
    // P(Θ) μ₀ (1 − e^{−τ(1/μ₀ + 1/μ)}) / (4π (μ₀ + μ)) per unit beam.
    const double tau = 0.3;
    const double mu0 = 0.7;
    ScatteringProblem p = one_layer(tau, 1.0, kRayleigh, mu0);
    p.azimuth_modes = 3;  // the Rayleigh phase function has modes 0-2
    const auto s = solve_scattering_orders(p);
    for (double mu : {0.2, 0.6, 1.0}) {
        for (double phi : {0.0, 1.0, kPi}) {
            const double cos_theta =
                -mu * mu0 + std::sqrt(1 - mu * mu) * std::sqrt(1 - mu0 * mu0) * std::cos(phi);
            const double phase = 0.75 * (1.0 + cos_theta * cos_theta);
            const double expected =
                phase * mu0 * -std::expm1(-tau * (1 / mu0 + 1 / mu)) / (4.0 * kPi * (mu0 + mu));
            EXPECT_NEAR(s.single_scatter_up_radiance(0, mu, phi), expected, 1e-12);
            // Multiple scattering adds to it, less than single scattering at this depth.
            const double ms = s.multiple_scatter_up_radiance(0, mu, phi);
            EXPECT_GT(ms, 0.0);
            EXPECT_LT(ms, expected * 1.2);
        }
    }
}

TEST(ScatteringOrders, BadProblemsAreRefused) {
    const auto message = [](const ScatteringProblem& p) {
        try {
            (void)solve_scattering_orders(p);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(ScatteringProblem{}), "scattering problem without layers");
    EXPECT_EQ(message(one_layer(0.1, 1.0, kRayleigh, 0.0)),
              "scattering problem: sun cos zenith must lie in (0, 1]");
    ScatteringProblem albedo = one_layer(0.1, 1.0, kRayleigh, 0.5);
    albedo.ground_albedo = 1.2;
    EXPECT_EQ(message(albedo), "scattering problem: ground albedo must lie in [0, 1]");
    const std::string layer =
        "scattering layer needs an optical depth >= 0, a single-scatter "
        "albedo in [0, 1] and moments starting with 1";
    EXPECT_EQ(message(one_layer(-0.1, 1.0, kRayleigh, 0.5)), layer);
    EXPECT_EQ(message(one_layer(0.1, 1.5, kRayleigh, 0.5)), layer);
    EXPECT_EQ(message(one_layer(0.1, 1.0, {0.5}, 0.5)), layer);
    ScatteringProblem streams = one_layer(0.1, 1.0, kRayleigh, 0.5);
    streams.streams = 1;
    EXPECT_NE(message(streams).find("streams >= 2"), std::string::npos);
    ScatteringProblem planck = one_layer(0.1, 1.0, kRayleigh, 0.5);
    planck.level_planck = {1.0};
    EXPECT_EQ(message(planck), "scattering problem: 1 level Planck radiances for 2 levels");
    planck.level_planck = {1.0, -1.0};
    EXPECT_EQ(message(planck), "scattering problem: level Planck radiances must be >= 0");
    planck.level_planck.clear();
    planck.beam_irradiance = -1.0;
    EXPECT_NE(message(planck).find("must be finite and >= 0"), std::string::npos);
}

/// ∫ B_ν dν over [lo, hi] cm⁻¹, W/(m² sr): 2hc²ν³/(e^(hcν/kT) − 1) by Simpson's rule on 20,000
/// intervals (DISORT's PLKAVG, the unit of its test problems' answers).
double band_planck(double lo_cm, double hi_cm, double temperature_k) {
    if (temperature_k <= 0.0) return 0.0;
    constexpr double kC1 = 1.191042972e-8;  // 2hc², W m⁻² sr⁻¹ cm⁴
    constexpr double kC2 = 1.438776877;     // hc/k, cm K
    const auto b = [&](double nu) {
        return nu <= 0.0 ? 0.0 : kC1 * nu * nu * nu / std::expm1(kC2 * nu / temperature_k);
    };
    constexpr int kSteps = 20'000;
    const double h = (hi_cm - lo_cm) / kSteps;
    double sum = b(lo_cm) + b(hi_cm);
    for (int k = 1; k < kSteps; ++k) sum += (k % 2 ? 4.0 : 2.0) * b(lo_cm + k * h);
    return sum * h / 3.0;
}

/// Henyey–Greenstein moments g^l, l < count.
std::vector<double> hg_moments(double g, int count) {
    std::vector<double> out;
    for (int l = 0; l < count; ++l) out.push_back(std::pow(g, l));
    return out;
}

// Equilibrium: an isothermal slab (τ 2 in three layers, ω 0.6, Henyey–Greenstein g 0.7) at B
// over a black ground at B, lit from above by an isotropic B, holds B in every direction, so
// the source function is B everywhere; what scattering adds along a path of slant optical
// depth τ/μ is then exactly ω B (1 − e^(−τ/μ)) (the rest, the unscattered B e^(−τ/μ) and the
// emission (1 − ω) B (1 − e^(−τ/μ)), is not in it). Within 2e-4 of B: the field's
// discretisation (16 streams, sublayers of 0.01, the series stopped at 1e-9).
TEST(ScatteringOrdersThermal, InScatteredRadianceOfAnIsothermalSlabInEquilibrium) {
    const double b = 7.0;
    ScatteringProblem p;
    for (int k = 0; k < 3; ++k) {
        p.layers.push_back(ScatteringLayer{2.0 / 3.0, 0.6, hg_moments(0.7, 32)});
    }
    p.streams = 16;
    p.beam_irradiance = 0.0;
    p.level_planck.assign(4, b);
    p.ground_planck = b;
    p.top_isotropic_radiance = b;
    p.tolerance = 1e-9;
    p.max_sublayer_depth = 0.01;
    const ScatteringSolution s = solve_scattering_orders(p);
    EXPECT_NEAR(s.diffuse_up_flux(0), kPi * b, 2e-4 * kPi * b);
    EXPECT_NEAR(s.diffuse_down_flux(3), kPi * b, 2e-4 * kPi * b);
    for (double mu : {0.1, 0.35, 0.8, 1.0}) {
        for (std::size_t level : {std::size_t{1}, std::size_t{3}}) {
            const double down_depth = s.optical_depth(level);
            EXPECT_NEAR(s.multiple_scatter_down_radiance(level, mu, 0.0),
                        0.6 * b * -std::expm1(-down_depth / mu), 2e-4 * b)
                << "down, level " << level << ", mu " << mu;
        }
        for (std::size_t level : {std::size_t{0}, std::size_t{2}}) {
            const double up_depth = s.optical_depth(3) - s.optical_depth(level);
            EXPECT_NEAR(s.multiple_scatter_up_radiance(level, mu, 0.0),
                        0.6 * b * -std::expm1(-up_depth / mu), 2e-4 * b)
                << "up, level " << level << ", mu " << mu;
        }
    }
    EXPECT_EQ(s.multiple_scatter_down_radiance(0, 0.5, 0.0), 0.0);  // nothing above the top
    EXPECT_THROW((void)s.multiple_scatter_down_radiance(1, 0.0, 0.0), Error);
}

// DISORT's test problem 7A (K. Stamnes et al. 1988; its answers are Kylling & Stamnes's,
// J. Comp. Phys. 102, 1992, Table I): one absorbing, weakly scattering layer (τ 1, ω 0.1,
// Henyey–Greenstein g 0.05) emitting at 200 K at its top and 300 K at its bottom over
// 300-800 cm⁻¹, B linear in τ, a black ground at 0 K, nothing from above. Fluxes within
// 0.1 % (ten times the largest difference measured, 0.006 %; DISORT's own test criterion is
// 1 %).
TEST(ScatteringOrdersThermal, DisortProblem7AEmittingLayer) {
    EXPECT_NEAR(band_planck(300.0, 800.0, 200.0), 18.085, 0.001);  // the notes' PLKAVG
    ScatteringProblem p;
    p.layers = {ScatteringLayer{1.0, 0.1, hg_moments(0.05, 32)}};
    p.streams = 16;
    p.beam_irradiance = 0.0;
    p.level_planck = {band_planck(300.0, 800.0, 200.0), band_planck(300.0, 800.0, 300.0)};
    p.tolerance = 1e-9;
    p.max_sublayer_depth = 0.01;
    const ScatteringSolution s = solve_scattering_orders(p);
    std::printf("7A: up at the top %.5g (DISORT 86.2936), down at the ground %.5g (121.204)\n",
                s.diffuse_up_flux(0), s.diffuse_down_flux(1));
    EXPECT_NEAR(s.diffuse_up_flux(0), 86.2936, 1e-3 * 86.2936);
    EXPECT_NEAR(s.diffuse_down_flux(1), 121.204, 1e-3 * 121.204);
    EXPECT_NEAR(s.diffuse_down_flux(0), 0.0, 1e-12);
    EXPECT_NEAR(s.diffuse_up_flux(1), 0.0, 1e-12);
}

// DISORT's test problems 6G and 6H: no scattering (ω 0), a layer of τ 1 (6G) or 10 (6H)
// emitting at 250 K at its top and 300 K at its bottom, an isotropic 100/π plus B(250 K) from
// above, a beam of 200 at μ₀ 0.5, over 0-50,000 cm⁻¹. Their ground is Hapke's BRDF, which
// glint's Lambertian ground is not: only the downward fluxes, which no ground touches, are
// compared (0.1 %).
TEST(ScatteringOrdersThermal, DisortProblems6GAnd6HEmissionWithoutScattering) {
    const auto b = [](double t) { return band_planck(0.0, 50'000.0, t); };
    const struct {
        double tau;
        double middle;  // the level inside the layer
        double down[3];
    } cases[] = {{1.0, 0.5, {321.497, 304.775, 363.632}}, {10.0, 1.0, {321.497, 255.455, 443.444}}};
    for (const auto& c : cases) {
        ScatteringProblem p;
        p.layers = {ScatteringLayer{c.middle, 0.0, {1.0}},
                    ScatteringLayer{c.tau - c.middle, 0.0, {1.0}}};
        p.streams = 16;
        p.sun_cos_zenith = 0.5;
        p.beam_irradiance = 200.0;
        const double f = c.middle / c.tau;
        p.level_planck = {b(250.0), (1.0 - f) * b(250.0) + f * b(300.0), b(300.0)};
        p.top_isotropic_radiance = 100.0 / std::numbers::pi + b(250.0);
        p.max_sublayer_depth = 0.01;
        const ScatteringSolution s = solve_scattering_orders(p);
        for (std::size_t level = 0; level < 3; ++level) {
            EXPECT_NEAR(s.diffuse_down_flux(level), c.down[level], 1e-3 * c.down[level])
                << "tau " << c.tau << ", level " << level;
        }
    }
}

// DISORT's test problem 7C: every source at once — a beam of 200 at μ₀ 0.5, an isotropic
// radiance of 100 plus B(100 K) from above, a layer (τ 1, ω 0.5, g 0.8) at 300 K at its top
// and 200 K at its bottom, a black ground at 320 K, over 0-50,000 cm⁻¹. Direct and diffuse
// fluxes at τ 0, 0.5 and 1 within 0.1 % (measured ≤ 0.006 %; DISORT's test criterion is
// 1 %; DISORT answered with 6 streams per hemisphere and delta-M scaling, glint with 16 and
// the phase function's first 32 moments).
TEST(ScatteringOrdersThermal, DisortProblem7CAllSources) {
    const auto b = [](double t) { return band_planck(0.0, 50'000.0, t); };
    ScatteringProblem p;
    p.layers = {ScatteringLayer{0.5, 0.5, hg_moments(0.8, 32)},
                ScatteringLayer{0.5, 0.5, hg_moments(0.8, 32)}};
    p.streams = 16;
    p.sun_cos_zenith = 0.5;
    p.beam_irradiance = 200.0;
    p.level_planck = {b(300.0), 0.5 * (b(300.0) + b(200.0)), b(200.0)};
    p.ground_planck = b(320.0);
    p.top_isotropic_radiance = 100.0 + b(100.0);
    p.tolerance = 1e-9;
    p.max_sublayer_depth = 0.01;
    const ScatteringSolution s = solve_scattering_orders(p);
    const double direct[] = {100.0, 36.7879, 13.5335};
    const double down[] = {319.830, 354.099, 301.334};
    const double up[] = {429.572, 447.018, 594.576};
    for (std::size_t level = 0; level < 3; ++level) {
        std::printf("7C level %zu: down %.6g (DISORT %.6g), up %.6g (%.6g)\n", level,
                    s.diffuse_down_flux(level), down[level], s.diffuse_up_flux(level), up[level]);
        EXPECT_NEAR(s.direct_flux(level), direct[level], 1e-5 * direct[level]);
        EXPECT_NEAR(s.diffuse_down_flux(level), down[level], 1e-3 * down[level]) << level;
        EXPECT_NEAR(s.diffuse_up_flux(level), up[level], 1e-3 * up[level]) << level;
    }
}

}  // namespace scattering_orders_test
}  // namespace glint::atmosphere
