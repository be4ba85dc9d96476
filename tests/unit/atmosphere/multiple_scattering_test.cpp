// SPDX-License-Identifier: Apache-2.0
// The parametric atmosphere with multiple scattering, against Sweigart's plane-parallel
// Rayleigh table (R. D. Sweigart, Astrophysical Journal Supplement 22, 1970, 1–80, Table 1;
// as reproduced by DISORT's test problem 2): a Rayleigh-only atmosphere of optical depth 0.2
// at one wavelength, the sun at μ₀ = 0.080442, a black ground. In a plane-parallel atmosphere
// of one scatterer the fluxes depend on the total optical depth alone, so the model's
// exponential profile and its layering must reproduce the table: the diffuse irradiance at
// the ground (the sky) and the upward flux at the top (the hemispheric integral of the
// path radiance, single plus multiple scattering).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/scattering_orders.h"
#include "glint/test/angles.h"

namespace glint::atmosphere {
namespace multiple_scattering_test {

using glint::test::kPi;
constexpr double kMu0 = 0.080442;
constexpr double kWavelengthUm = 0.40;

/// Rayleigh only, scaled to τ = 0.2 at kWavelengthUm; no gases, black ground.
ParametricAtmosphereModel sweigart_atmosphere() {
    model::ParametricAtmosphere p;
    p.gas_absorption = false;
    p.aerosol_optical_depth_550 = 0.0;
    p.ground_albedo = 0.0;
    p.air_temperature_k = 0.0;  // no thermal emission
    const double l2 = 1.0 / (kWavelengthUm * kWavelengthUm);
    const double at_standard = 0.008569 * l2 * l2 * (1.0 + 0.0113 * l2 + 0.00013 * l2 * l2);
    p.sea_level_pressure_hpa = 1013.25 * 0.2 / at_standard;
    return ParametricAtmosphereModel(p);
}

TEST(MultipleScattering, SkyIrradianceMatchesSweigart) {
    const ParametricAtmosphereModel m = sweigart_atmosphere();
    ASSERT_NEAR(m.rayleigh_optical_depth(kWavelengthUm, 0.0), 0.2, 1e-12);
    const SpectralGrid grid({kWavelengthUm});
    AtmosphereGeometry g;
    g.sun_zenith_deg = zenith_for_relative_air_mass(1.0 / kMu0);
    const double e0 = 1.0;
    const std::vector<double> toa{e0};
    const double diffuse = m.diffuse_sky_irradiance_w_per_cm2_um(grid, g, toa)[0];
    std::printf("sky: %.6g vs Sweigart %.6g (%+.3f %%)\n", diffuse * kPi, 0.106123,
                100.0 * (diffuse * kPi / 0.106123 - 1.0));
    // Sweigart: 0.106123 for a beam of irradiance π. Measured +0.05 % with the model's 8
    // streams, 24 layers and the sun's zenith rounded to 0.05°; tolerance 1 %.
    EXPECT_NEAR(diffuse, 0.106123 / kPi, 0.01 * 0.106123 / kPi);
    // The direct beam: T = e^{−τ/μ₀}.
    EXPECT_NEAR(m.sun_transmittance(grid, g)[0], std::exp(-0.2 / kMu0), 1e-9);
}

TEST(MultipleScattering, UpwardFluxAtTheTopMatchesSweigart) {
    // F↑ = ∫ L μ dΩ over the upper hemisphere from the path radiance seen by a sensor above
    // the atmosphere: Gauss–Legendre in μ (24 points), 72 azimuths (the single-scatter part
    // is exact; both are smooth in azimuth; the rule is the solver's own, whose fluxes
    // scattering_orders_test.cpp checks).
    const ParametricAtmosphereModel m = sweigart_atmosphere();
    const SpectralGrid grid({kWavelengthUm});
    const std::vector<double> toa{1.0};
    AtmosphereGeometry g;
    g.sun_zenith_deg = zenith_for_relative_air_mass(1.0 / kMu0);
    g.sun_azimuth_deg = 0.0;
    g.sensor_altitude_m = 200'000.0;
    std::vector<double> azimuths;
    for (int k = 0; k < 72; ++k) azimuths.push_back(5.0 * k);
    std::vector<double> nodes, weights;
    gauss_legendre_unit(24, nodes, weights);
    double flux = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double mu = nodes[i];
        const double weight = weights[i];
        g.view_zenith_deg = std::acos(mu) * 180.0 / kPi;
        const auto radiance = m.path_radiance_at_azimuths(grid, g, toa, azimuths);
        double mean = 0.0;
        for (const auto& l : radiance) mean += l[0] / static_cast<double>(radiance.size());
        flux += weight * mu * 2.0 * kPi * mean;
    }
    std::printf("upward flux: %.6g vs Sweigart %.6g (%+.3f %%)\n", flux * kPi, 0.125561,
                100.0 * (flux * kPi / 0.125561 - 1.0));
    // Sweigart: 0.125561 for a beam of irradiance π. The model's view paths use the
    // Kasten–Young air mass, not 1/μ, near the horizon: measured −0.8 %, tolerance 2 %.
    EXPECT_NEAR(flux, 0.125561 / kPi, 0.02 * 0.125561 / kPi);
}

TEST(MultipleScattering, AddsToSingleScatteringAndGrowsWithGroundAlbedo) {
    model::ParametricAtmosphere p;
    p.gas_absorption = false;
    p.aerosol_optical_depth_550 = 0.3;
    p.multiple_scattering = false;
    const ParametricAtmosphereModel single(p);
    p.multiple_scattering = true;
    p.ground_albedo = 0.0;
    const ParametricAtmosphereModel black(p);
    p.ground_albedo = 0.5;
    const ParametricAtmosphereModel bright(p);
    const SpectralGrid grid({0.4, 0.55, 0.8});
    const std::vector<double> toa{0.17, 0.19, 0.11};
    AtmosphereGeometry g;
    g.sun_zenith_deg = 40.0;
    g.sensor_altitude_m = 5000.0;
    g.view_zenith_deg = 20.0;
    g.view_azimuth_deg = 100.0;
    const auto l1 = single.path_radiance_w_per_cm2_sr_um(grid, g, toa);
    const auto l2 = black.path_radiance_w_per_cm2_sr_um(grid, g, toa);
    const auto l3 = bright.path_radiance_w_per_cm2_sr_um(grid, g, toa);
    const auto e2 = black.diffuse_sky_irradiance_w_per_cm2_um(grid, g, toa);
    const auto e3 = bright.diffuse_sky_irradiance_w_per_cm2_um(grid, g, toa);
    for (std::size_t i = 0; i < grid.size(); ++i) {
        EXPECT_GT(l2[i], l1[i]);  // more orders, more light
        EXPECT_GT(l3[i], l2[i]);  // the ground's light scattered into the view
        EXPECT_GT(e3[i], e2[i]);  // and back down as sky
    }
}

}  // namespace multiple_scattering_test
}  // namespace glint::atmosphere
