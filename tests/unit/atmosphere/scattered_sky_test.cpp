// SPDX-License-Identifier: Apache-2.0
// Tests of the scattered sky's radiance by direction
// (ParametricAtmosphereModel::scattered_sky_radiance_w_per_cm2_sr_um): integrated over the
// hemisphere it is the model's diffuse sky irradiance; a thin Rayleigh sky is the closed-form
// single scattering; the sky brightens towards the sun (the aureole) and towards the horizon;
// nothing with the sun down. Against DISORT in a haze: disort_haze_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/scattering_orders.h"

namespace glint::atmosphere {
namespace scattered_sky_test {

constexpr double kPi = std::numbers::pi;

model::ParametricAtmosphere exponential(double tau550) {
    model::ParametricAtmosphere p;
    p.gas_absorption = false;
    p.aerosol_optical_depth_550 = tau550;
    p.aerosol_asymmetry = 0.7;
    p.aerosol_single_scatter_albedo = 0.9;
    return p;
}

/// ∫ L(θ, φ) cos θ dΩ over the sky: Gauss–Legendre in cos θ, the midpoint rule in azimuth.
double hemisphere(const ParametricAtmosphereModel& atmosphere, const SpectralGrid& grid,
                  const AtmosphereGeometry& g) {
    std::vector<double> nodes, weights;
    gauss_legendre_unit(32, nodes, weights);
    const std::vector<double> toa{1.0};
    constexpr int kAzimuths = 90;
    double sum = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double zenith = std::acos(nodes[i]) * 180.0 / kPi;
        for (int a = 0; a < kAzimuths; ++a) {
            const double azimuth = (a + 0.5) * 360.0 / kAzimuths;
            sum +=
                weights[i] * nodes[i] * (2.0 * kPi / kAzimuths) *
                atmosphere.scattered_sky_radiance_w_per_cm2_sr_um(grid, g, toa, zenith, azimuth)[0];
        }
    }
    return sum;
}

// The radiance integrated over the hemisphere is the diffuse sky irradiance the renderer's
// isotropic sky has used: both come from the same solution, the radiance with the exact
// single scattering, the irradiance with the solver's (1 %: 32 × 90 directions through a
// Henyey–Greenstein aureole of g = 0.7, and the δ-M peak of g^16).
TEST(ScatteredSky, ItsHemisphericIntegralIsTheSkyIrradiance) {
    const SpectralGrid grid({0.45});
    for (double sun : {20.0, 60.0}) {
        for (double tau : {0.1, 0.6}) {
            const ParametricAtmosphereModel atmosphere(exponential(tau));
            AtmosphereGeometry g;
            g.sun_zenith_deg = sun;
            g.sun_azimuth_deg = 40.0;
            const double irradiance =
                atmosphere.diffuse_sky_irradiance_w_per_cm2_um(grid, g, std::vector{1.0})[0];
            const double ratio = hemisphere(atmosphere, grid, g) / irradiance;
            if (std::getenv("GLINT_SKY_PRINT")) {
                std::printf("sun %.0f tau %.1f: %+.3f%%\n", sun, tau, 100.0 * (ratio - 1.0));
            }
            EXPECT_NEAR(ratio, 1.0, 0.01) << "sun " << sun << ", tau " << tau;
        }
    }
}

// A thin Rayleigh sky without multiple scattering: the closed form of single scattering
// seen from below, E₀ P_R(Θ) τ m_v / (4π) (1 − τ(m_s + m_v)/2) to second order (τ = 0.004 at
// 1.2 µm: 0.2 %).
TEST(ScatteredSky, AThinRayleighSkyIsSingleScattering) {
    model::ParametricAtmosphere p = exponential(0.0);
    p.multiple_scattering = false;
    const ParametricAtmosphereModel atmosphere(p);
    const SpectralGrid grid({1.2});
    AtmosphereGeometry g;
    g.sun_zenith_deg = 30.0;
    g.sun_azimuth_deg = 0.0;
    const double tau = atmosphere.rayleigh_optical_depth(1.2, 0.0);
    for (const auto& [zenith, azimuth] :
         {std::pair{0.0, 0.0}, {45.0, 0.0}, {45.0, 90.0}, {70.0, 180.0}}) {
        const double t = zenith * kPi / 180.0, f = azimuth * kPi / 180.0;
        const double cos_scatter = std::sin(30.0 * kPi / 180.0) * std::sin(t) * std::cos(f) +
                                   std::cos(30.0 * kPi / 180.0) * std::cos(t);
        const double m_s = relative_air_mass(30.0), m_v = relative_air_mass(zenith);
        const double expected = 0.75 * (1.0 + cos_scatter * cos_scatter) * tau * m_v / (4.0 * kPi) *
                                (1.0 - 0.5 * tau * (m_s + m_v));
        const double ours = atmosphere.scattered_sky_radiance_w_per_cm2_sr_um(
            grid, g, std::vector{1.0}, zenith, azimuth)[0];
        EXPECT_NEAR(ours / expected, 1.0, 2e-3) << zenith << " " << azimuth;
    }
}

// The sky's shape: brighter towards the sun than away from it (the aerosol's forward
// scattering), brighter at the horizon than at the zenith away from the sun (the longer path);
// black with the sun down.
TEST(ScatteredSky, AnAureoleAndABrightHorizon) {
    const ParametricAtmosphereModel atmosphere(exponential(0.3));
    const SpectralGrid grid({0.55});
    const std::vector<double> toa{1.0};
    AtmosphereGeometry g;
    g.sun_zenith_deg = 50.0;
    g.sun_azimuth_deg = 120.0;
    const auto sky = [&](double zenith, double azimuth) {
        return atmosphere.scattered_sky_radiance_w_per_cm2_sr_um(grid, g, toa, zenith, azimuth)[0];
    };
    EXPECT_GT(sky(45.0, 120.0), 3.0 * sky(45.0, 300.0));  // 5° from the sun against 95°
    EXPECT_GT(sky(85.0, 300.0), sky(0.0, 0.0));
    g.sun_zenith_deg = 95.0;
    EXPECT_EQ(sky(45.0, 120.0), 0.0);
}

}  // namespace scattered_sky_test
}  // namespace glint::atmosphere
