// SPDX-License-Identifier: Apache-2.0
// Tests of the air's thermal emission in the parametric atmosphere (docs/thermal.md): an
// isothermal absorbing layer emits (1 − T) B(T); a black surface at the air's temperature seen
// through an isothermal atmosphere keeps its radiance at every altitude; the sky is
// directional (brighter towards the horizon, B(T_air) there in opaque bands, cold at the
// zenith in the window) and its isotropic equivalent is its cosine-weighted mean; the
// temperature profile follows the standard atmosphere, shifted at the ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/gas_absorption.h"
#include "glint/io/input_files.h"
#include "glint/model/standard_atmospheres.h"
#include "glint/test/gas_table.h"

namespace glint::atmosphere {
namespace air_emission_test {

const SpectralGrid kThermal = SpectralGrid::regular(7.0, 14.0, 0.25);

using test::gas_table;

AtmosphereGeometry looking_down(double sensor_altitude_m, double view_zenith_deg = 0.0) {
    AtmosphereGeometry g;
    g.sun_zenith_deg = 120.0;  // night: only emission
    g.surface_altitude_m = 0.0;
    g.sensor_altitude_m = sensor_altitude_m;
    g.view_zenith_deg = view_zenith_deg;
    return g;
}

/// An isothermal atmosphere at `temperature_k` with gases and an absorbing aerosol.
model::ParametricAtmosphere isothermal(double temperature_k, double omega = 0.0) {
    model::ParametricAtmosphere p;
    p.profile = model::StandardAtmosphere::isothermal;
    p.air_temperature_k = temperature_k;
    p.aerosol_optical_depth_550 = 0.5;
    p.aerosol_single_scatter_albedo = omega;
    p.multiple_scattering = false;
    return p;
}

double planck(double wavelength_um, double temperature_k) {
    return planck_radiance_w_per_cm2_sr_um(wavelength_um, temperature_k);
}

// With no scatterer at all (no Rayleigh: sea-level pressure 0, which also leaves out the
// mixed gases; a purely absorbing aerosol), the layers' emissivities telescope: the path
// emits (1 − T) B(T) with T the path's own transmittance, to rounding.
TEST(AirEmission, IsothermalAbsorbingLayerEmitsOneMinusTTimesB) {
    auto p = isothermal(290.0);
    p.sea_level_pressure_hpa = 0.0;
    const ParametricAtmosphereModel m(p, gas_table());
    for (double sensor_m : {300.0, 3000.0, 20'000.0}) {
        for (double view_deg : {0.0, 60.0}) {
            const auto g = looking_down(sensor_m, view_deg);
            const auto t = m.sensor_transmittance(kThermal, g);
            const auto l = m.path_radiance_w_per_cm2_sr_um(
                kThermal, g, std::vector<double>(kThermal.size(), 0.0));
            for (std::size_t i = 0; i < kThermal.size(); ++i) {
                const double expected = (1.0 - t[i]) * planck(kThermal.wavelength_um(i), 290.0);
                EXPECT_NEAR(l[i], expected, 1e-12 * planck(kThermal.wavelength_um(i), 290.0))
                    << sensor_m << " m, " << view_deg << "°, " << kThermal.wavelength_um(i);
            }
        }
    }
}

// A black surface at the air's temperature seen through an isothermal atmosphere: T B + L_p =
// B at every altitude (Kirchhoff). Exact without scatterers; with Rayleigh (τ ≈ 1e-5 at
// 7-14 µm) and a scattering aerosol the path loses the light scattered out of it and, with
// multiple scattering off as here, gains none scattered in: the deficit is positive and below
// the path's scattering optical depth (the next test turns the in-scatter on).
TEST(AirEmission, BlackSurfaceAtAirTemperatureKeepsItsRadianceAtEveryAltitude) {
    for (double omega : {0.0, 0.9}) {
        auto p = isothermal(300.0, omega);
        if (omega == 0.0) p.sea_level_pressure_hpa = 0.0;
        const ParametricAtmosphereModel m(p, gas_table());
        for (double sensor_m : {100.0, 1000.0, 5000.0, 30'000.0, 100'000.0, 700'000.0}) {
            const auto g = looking_down(sensor_m, 30.0);
            const auto t = m.sensor_transmittance(kThermal, g);
            const auto l = m.path_radiance_w_per_cm2_sr_um(
                kThermal, g, std::vector<double>(kThermal.size(), 0.0));
            for (std::size_t i = 0; i < kThermal.size(); ++i) {
                const double wl = kThermal.wavelength_um(i);
                const double b = planck(wl, 300.0);
                const double seen = t[i] * b + l[i];
                if (omega == 0.0) {
                    EXPECT_NEAR(seen, b, 1e-12 * b) << sensor_m << " m, " << wl << " µm";
                } else {
                    const double scattering = (m.rayleigh_optical_depth(wl, 0.0) +
                                               omega * m.aerosol_optical_depth(wl, 0.0)) *
                                              relative_air_mass(30.0);
                    EXPECT_LE(seen, b * (1.0 + 1e-12)) << sensor_m << " m, " << wl << " µm";
                    EXPECT_GE(seen, b * (1.0 - scattering)) << sensor_m << " m, " << wl << " µm";
                }
            }
        }
    }
}

// Thermal multiple scattering: in a dusty isothermal atmosphere (τ 2 at every wavelength,
// ω 0.9, g 0.7) a black surface at the air's temperature seen from above loses the light its
// path scatters out and, with multiple scattering on, gains what the path scatters in. The
// gain is ≥ 0 and does not lift it above B (the field is nowhere above B: the space above is
// black); in the 10-11 µm window it closes more than 85 % of the deficit (measured at 10 µm:
// from 67 % to 3.6 % of B seen from 1 km, 74 % to 5.3 % from 5 km, 63 % to 8.6 % from 30 km) --
// what is left is the dust's view of the cold space above, through the window. The sky: with
// scattering it is warmer at every zenith, and not above B.
TEST(AirEmission, ThermalMultipleScatteringFillsTheDeficitOfADustyPath) {
    auto p = isothermal(300.0, 0.9);
    p.aerosol_optical_depth_550 = 2.0;
    p.angstrom_exponent = 0.0;
    p.aerosol_asymmetry = 0.7;
    p.aerosol_scale_height_m = 1000.0;
    const ParametricAtmosphereModel without(p, gas_table());
    p.multiple_scattering = true;
    const ParametricAtmosphereModel with(p, gas_table());
    const std::vector<double> dark(kThermal.size(), 0.0);
    // The emission integral (slant band-model transmittances) and the solver's layers
    // (vertical −ln T, slanted as 1/μ) treat a band model's curve of growth differently: in
    // the opaque water band at 7 µm their sum overshoots B by up to 0.3 % (measured).
    constexpr double kOvershoot = 5e-3;
    for (double sensor_m : {1000.0, 5000.0, 30'000.0}) {
        const auto g = looking_down(sensor_m, 30.0);
        const auto t = with.sensor_transmittance(kThermal, g);
        const auto l0 = without.path_radiance_w_per_cm2_sr_um(kThermal, g, dark);
        const auto l1 = with.path_radiance_w_per_cm2_sr_um(kThermal, g, dark);
        for (std::size_t i = 0; i < kThermal.size(); ++i) {
            const double wl = kThermal.wavelength_um(i);
            const double b = planck(wl, 300.0);
            const double seen0 = t[i] * b + l0[i];
            const double seen1 = t[i] * b + l1[i];
            if (std::abs(wl - 10.0) < 1e-9) {
                std::printf("%g m, 10 um: deficit %.4f without, %.4f with\n", sensor_m,
                            1.0 - seen0 / b, 1.0 - seen1 / b);
            }
            EXPECT_GE(seen1, seen0) << sensor_m << " m, " << wl << " µm";
            EXPECT_LE(seen1, b * (1.0 + kOvershoot)) << sensor_m << " m, " << wl << " µm";
            if (wl >= 10.0 && wl <= 11.0) {
                EXPECT_LT(b - seen1, 0.15 * (b - seen0)) << sensor_m << " m, " << wl << " µm";
            }
        }
    }
    const AtmosphereGeometry ground = looking_down(0.0);
    for (double zenith : {0.0, 60.0, 85.0}) {
        const auto s0 = without.thermal_sky_radiance_at_zenith(kThermal, ground, zenith);
        const auto s1 = with.thermal_sky_radiance_at_zenith(kThermal, ground, zenith);
        for (std::size_t i = 0; i < kThermal.size(); ++i) {
            const double b = planck(kThermal.wavelength_um(i), 300.0);
            EXPECT_GT(s1[i], s0[i]) << zenith << "°, " << kThermal.wavelength_um(i) << " µm";
            EXPECT_LE(s1[i], b * (1.0 + kOvershoot))
                << zenith << "°, " << kThermal.wavelength_um(i);
        }
    }
}

// The directional sky: brighter towards the horizon in every band; B(T_air) at the horizon
// in the opaque bands (7 µm water, 14 µm carbon dioxide); in the window at the zenith far
// below it; the isotropic sky is its cosine-weighted mean 2∫L(μ)μ dμ (here by a 2,000-point
// midpoint sum, independent of the model's 8-point Gauss rule).
TEST(AirEmission, SkyIsDirectionalAndWarmAtTheHorizon) {
    const ParametricAtmosphereModel m(model::ParametricAtmosphere{}, gas_table());
    AtmosphereGeometry g = looking_down(0.0);
    const double t_air = m.air_temperature_k(0.0);
    EXPECT_NEAR(t_air, 288.15, 1e-9);
    std::vector<double> previous(kThermal.size(), 0.0);
    for (double zenith : {0.0, 30.0, 60.0, 80.0, 89.0, 90.0}) {
        const auto l = m.thermal_sky_radiance_at_zenith(kThermal, g, zenith);
        for (std::size_t i = 0; i < kThermal.size(); ++i) {
            EXPECT_GE(l[i], previous[i]) << zenith << "° " << kThermal.wavelength_um(i);
            EXPECT_LE(l[i], planck(kThermal.wavelength_um(i), t_air));
        }
        previous = l;
    }
    const auto horizon = m.thermal_sky_radiance_at_zenith(kThermal, g, 90.0);
    const auto zenith = m.thermal_sky_radiance_at_zenith(kThermal, g, 0.0);
    // 7 µm (index 0) and 14 µm (the last): within 2 % of the near-ground air's B.
    EXPECT_NEAR(horizon.front() / planck(7.0, t_air), 1.0, 0.02);
    EXPECT_NEAR(horizon.back() / planck(14.0, t_air), 1.0, 0.02);
    // 10 µm window at the zenith: well under half of B(T_air).
    const std::size_t window = 12;  // 10.0 µm
    ASSERT_NEAR(kThermal.wavelength_um(window), 10.0, 1e-12);
    EXPECT_LT(zenith[window], 0.5 * planck(10.0, t_air));
    EXPECT_GT(zenith[window], 0.0);

    const auto isotropic = m.thermal_sky_radiance_w_per_cm2_sr_um(kThermal, g);
    constexpr int kSteps = 2000;
    std::vector<double> zeniths;
    for (int k = 0; k < kSteps; ++k) {
        zeniths.push_back(std::acos((k + 0.5) / kSteps) * 180.0 / M_PI);
    }
    const auto sky = m.thermal_sky_at_zeniths(kThermal, g, zeniths);
    for (std::size_t i = 0; i < kThermal.size(); ++i) {
        double mean = 0.0;
        for (int k = 0; k < kSteps; ++k) mean += 2.0 * ((k + 0.5) / kSteps) * sky[k][i] / kSteps;
        EXPECT_NEAR(isotropic[i], mean, 2e-3 * mean) << kThermal.wavelength_um(i);
    }
}

// The sky of an isothermal atmosphere without scatterers is B(T)(1 − T_zenith path), and the
// temperature profile: the standard atmosphere's, shifted at sea level by air_temperature_k,
// the shift gone at 11 km.
TEST(AirEmission, TemperatureProfileAndIsothermalSky) {
    auto p = isothermal(280.0);
    p.sea_level_pressure_hpa = 0.0;
    const ParametricAtmosphereModel iso(p, gas_table());
    auto g = looking_down(0.0);
    const auto sky = iso.thermal_sky_radiance_at_zenith(kThermal, g, 0.0);
    g.sensor_altitude_m = 100'000.0;
    const auto t = iso.sensor_transmittance(kThermal, g);
    for (std::size_t i = 0; i < kThermal.size(); ++i) {
        const double b = planck(kThermal.wavelength_um(i), 280.0);
        EXPECT_NEAR(sky[i], (1.0 - t[i]) * b, 1e-12 * b);
    }

    model::ParametricAtmosphere us;
    us.air_temperature_k = 298.2;  // 10 K over the 1976 standard's sea level (288.2 K)
    const ParametricAtmosphereModel m(us, gas_table());
    const auto levels = model::standard_atmosphere(model::StandardAtmosphere::us_standard_1976);
    EXPECT_EQ(model::profile_temperature_k(levels.levels, 0.0), 288.2);
    EXPECT_NEAR(m.air_temperature_k(0.0), 298.2, 1e-9);
    EXPECT_NEAR(m.air_temperature_k(5500.0),
                model::profile_temperature_k(levels.levels, 5500.0) + 5.0, 1e-9);
    EXPECT_NEAR(m.air_temperature_k(20'000.0),
                model::profile_temperature_k(levels.levels, 20'000.0), 1e-9);
}

}  // namespace air_emission_test
}  // namespace glint::atmosphere
