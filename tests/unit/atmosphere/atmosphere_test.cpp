// SPDX-License-Identifier: Apache-2.0
// Tests of the atmosphere models: none is transparent with a black sky; parametric has the
// Hansen–Travis Rayleigh depth, behaves monotonically with optical depth, path length and
// zenith, and tends to none as the optical depth goes to 0; tabulated and simple return their
// inputs; the reader's output builds the right model.
#include "glint/atmosphere/atmosphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace glint::atmosphere {
namespace atmosphere_test {

const SpectralGrid kGrid = SpectralGrid::regular(0.4, 2.4, 0.1);

/// A flat TOA irradiance of 0.15 W/(cm² µm) on kGrid.
std::vector<double> toa() { return std::vector<double>(kGrid.size(), 0.15); }

AtmosphereGeometry nadir(double sun_zenith_deg, double sensor_altitude_m) {
    AtmosphereGeometry g;
    g.sun_zenith_deg = sun_zenith_deg;
    g.sun_azimuth_deg = 135.0;
    g.surface_altitude_m = 0.0;
    g.sensor_altitude_m = sensor_altitude_m;
    return g;
}

/// Rayleigh and aerosol, single scattering and the Bird–Hulstrom sky: these tests check
/// those formulas; the gases and multiple scattering have their own tests
/// (gas_absorption_test.cpp, multiple_scattering_test.cpp).
model::ParametricAtmosphere with_aod(double tau_550) {
    model::ParametricAtmosphere p;
    p.aerosol_optical_depth_550 = tau_550;
    p.gas_absorption = false;
    p.multiple_scattering = false;
    return p;
}

TEST(NoAtmosphere, TransparentBlackSky) {
    const NoAtmosphere none;
    const auto g = nadir(30.0, 3000.0);
    for (double v : none.sun_transmittance(kGrid, g)) EXPECT_EQ(v, 1.0);
    for (double v : none.sensor_transmittance(kGrid, g)) EXPECT_EQ(v, 1.0);
    for (double v : none.path_radiance_w_per_cm2_sr_um(kGrid, g, toa())) EXPECT_EQ(v, 0.0);
    for (double v : none.sky_radiance_w_per_cm2_sr_um(kGrid, g, toa())) EXPECT_EQ(v, 0.0);
    for (double v : none.diffuse_sky_irradiance_w_per_cm2_um(kGrid, g, toa())) EXPECT_EQ(v, 0.0);
    for (double v : none.sun_transmittance(kGrid, nadir(95.0, 0.0))) EXPECT_EQ(v, 0.0);
    EXPECT_THROW((void)none.path_radiance_w_per_cm2_sr_um(kGrid, g, std::vector<double>(3)), Error);
}

TEST(ParametricAtmosphere, RayleighOpticalDepthAt550nm) {
    const ParametricAtmosphereModel m(with_aod(0.0));
    // Hansen & Travis (1974): ≈ 0.0973 at 0.55 µm, sea level, 1013.25 hPa.
    EXPECT_NEAR(m.rayleigh_optical_depth(0.55, 0.0), 0.097, 0.001);
    // Above 8 km: the U.S. Standard profile's pressure ratio there, 356.5 / 1013 hPa (the 8 km
    // exponential's 1/e with rayleigh_scale_height_m).
    EXPECT_NEAR(m.rayleigh_optical_depth(0.55, 8000.0) / m.rayleigh_optical_depth(0.55, 0.0),
                356.5 / 1013.0, 1e-9);
    model::ParametricAtmosphere exponential = with_aod(0.0);
    exponential.rayleigh_scale_height_m = 8000.0;
    const ParametricAtmosphereModel e(exponential);
    EXPECT_NEAR(e.rayleigh_optical_depth(0.55, 8000.0) / e.rayleigh_optical_depth(0.55, 0.0),
                1.0 / M_E, 1e-12);
    EXPECT_DOUBLE_EQ(e.rayleigh_optical_depth(0.55, 0.0), m.rayleigh_optical_depth(0.55, 0.0));
    // The isothermal profile has no pressures: 8 km.
    model::ParametricAtmosphere isothermal = with_aod(0.0);
    isothermal.profile = model::StandardAtmosphere::isothermal;
    EXPECT_NEAR(ParametricAtmosphereModel(isothermal).air_share_above(8000.0), 1.0 / M_E, 1e-12);
    EXPECT_NEAR(m.rayleigh_optical_depth(1.0, 0.0), 0.0087, 0.0003);
    const ParametricAtmosphereModel a(with_aod(0.3));
    EXPECT_DOUBLE_EQ(a.aerosol_optical_depth(0.55, 0.0), 0.3);
    EXPECT_NEAR(a.aerosol_optical_depth(1.1, 0.0), 0.3 * std::pow(2.0, -1.3), 1e-12);
    EXPECT_NEAR(a.aerosol_optical_depth(0.55, 1200.0), 0.3 / M_E, 1e-12);
}

TEST(ParametricAtmosphere, AirMass) {
    EXPECT_NEAR(relative_air_mass(0.0), 1.0, 1e-3);
    EXPECT_NEAR(relative_air_mass(60.0), 2.0, 0.01);
    EXPECT_NEAR(relative_air_mass(90.0), 37.9, 0.5);  // finite at the horizon
    EXPECT_EQ(relative_air_mass(120.0), relative_air_mass(90.0));
}

TEST(ParametricAtmosphere, SunTransmittanceIsBeerLambert) {
    const ParametricAtmosphereModel m(with_aod(0.2));
    const auto t = m.sun_transmittance(kGrid, nadir(60.0, 0.0));
    for (std::size_t i = 0; i < kGrid.size(); ++i) {
        const double wl = kGrid.wavelength_um(i);
        const double tau = m.rayleigh_optical_depth(wl, 0.0) + m.aerosol_optical_depth(wl, 0.0);
        EXPECT_NEAR(t[i], std::exp(-tau * relative_air_mass(60.0)), 1e-12);
        if (i > 0) {
            EXPECT_GT(t[i], t[i - 1]);  // bluer light is extinguished more
        }
    }
}

TEST(ParametricAtmosphere, MonotonicInOpticalDepth) {
    // Transmittances fall and the sky brightens as the aerosol optical depth grows.
    const auto g = nadir(40.0, 100'000.0);
    std::vector<double> last_sun(kGrid.size(), 2.0), last_view(kGrid.size(), 2.0);
    std::vector<double> last_sky(kGrid.size(), -1.0);
    for (double tau : {0.0, 0.05, 0.1, 0.2, 0.4, 0.8}) {
        const ParametricAtmosphereModel m(with_aod(tau));
        const auto sun = m.sun_transmittance(kGrid, g);
        const auto view = m.sensor_transmittance(kGrid, g);
        const auto sky = m.diffuse_sky_irradiance_w_per_cm2_um(kGrid, g, toa());
        for (std::size_t i = 0; i < kGrid.size(); ++i) {
            EXPECT_LT(sun[i], last_sun[i]) << tau;
            EXPECT_LT(view[i], last_view[i]) << tau;
            EXPECT_GT(sky[i], last_sky[i]) << tau;
        }
        last_sun = sun;
        last_view = view;
        last_sky = sky;
    }
}

TEST(ParametricAtmosphere, PathRadianceGrowsWithOpticalDepth) {
    // Aerosol only (no Rayleigh), sensor at the top and at 1 km; and the whole atmosphere
    // (Rayleigh and aerosol scaled together) seen from the top. (Adding weakly
    // back-scattering aerosol to a Rayleigh sky may lower the blue path radiance in
    // back-scatter geometry: that is physical, so it is not asserted.)
    const auto top = nadir(40.0, 100'000.0);
    const auto low = nadir(40.0, 1000.0);
    std::vector<double> last_top(kGrid.size(), -1.0), last_low(kGrid.size(), -1.0);
    std::vector<double> last_all(kGrid.size(), -1.0);
    for (double tau : {0.0, 0.05, 0.1, 0.2, 0.4, 0.8}) {
        auto p = with_aod(tau);
        p.sea_level_pressure_hpa = 0.0;
        const ParametricAtmosphereModel aerosol(p);
        const auto l_top = aerosol.path_radiance_w_per_cm2_sr_um(kGrid, top, toa());
        const auto l_low = aerosol.path_radiance_w_per_cm2_sr_um(kGrid, low, toa());
        auto q = with_aod(tau);
        q.sea_level_pressure_hpa = 1013.25 * tau / 0.1;
        const ParametricAtmosphereModel all(q);
        const auto l_all = all.path_radiance_w_per_cm2_sr_um(kGrid, top, toa());
        for (std::size_t i = 0; i < kGrid.size(); ++i) {
            if (tau == 0.0) {
                EXPECT_EQ(l_top[i], 0.0);
                EXPECT_EQ(l_all[i], 0.0);
            } else {
                EXPECT_GT(l_top[i], last_top[i]) << tau;
                EXPECT_GT(l_low[i], last_low[i]) << tau;
                EXPECT_GT(l_all[i], last_all[i]) << tau;
            }
        }
        last_top = l_top;
        last_low = l_low;
        last_all = l_all;
    }
}

TEST(ParametricAtmosphere, MonotonicInPathLengthAndZenith) {
    const ParametricAtmosphereModel m(with_aod(0.2));
    std::vector<double> last_t(kGrid.size(), 2.0), last_l(kGrid.size(), -1.0);
    for (double altitude : {100.0, 500.0, 1000.0, 3000.0, 10000.0, 30000.0, 100000.0}) {
        const auto g = nadir(30.0, altitude);
        const auto t = m.sensor_transmittance(kGrid, g);
        const auto l = m.path_radiance_w_per_cm2_sr_um(kGrid, g, toa());
        for (std::size_t i = 0; i < kGrid.size(); ++i) {
            EXPECT_LT(t[i], last_t[i]) << altitude;
            EXPECT_GT(l[i], last_l[i]) << altitude;
        }
        last_t = t;
        last_l = l;
    }
    std::vector<double> last_sun(kGrid.size(), 2.0), last_view(kGrid.size(), 2.0);
    for (double zenith : {0.0, 30.0, 60.0, 80.0, 89.0}) {
        auto g = nadir(zenith, 5000.0);
        g.view_zenith_deg = zenith;
        const auto sun = m.sun_transmittance(kGrid, g);
        const auto view = m.sensor_transmittance(kGrid, g);
        for (std::size_t i = 0; i < kGrid.size(); ++i) {
            EXPECT_LT(sun[i], last_sun[i]) << zenith;
            EXPECT_LT(view[i], last_view[i]) << zenith;
        }
        last_sun = sun;
        last_view = view;
    }
}

TEST(ParametricAtmosphere, TendsToNoneAsOpticalDepthVanishes) {
    const NoAtmosphere none;
    const auto g = nadir(35.0, 700'000.0);
    for (double scale : {1e-2, 1e-4, 1e-6}) {
        auto p = with_aod(0.3 * scale);
        p.sea_level_pressure_hpa = 1013.25 * scale;
        p.air_temperature_k = 0.0;  // no thermal sky either
        const ParametricAtmosphereModel m(p);
        const auto sun = m.sun_transmittance(kGrid, g);
        const auto view = m.sensor_transmittance(kGrid, g);
        const auto path = m.path_radiance_w_per_cm2_sr_um(kGrid, g, toa());
        const auto sky = m.sky_radiance_w_per_cm2_sr_um(kGrid, g, toa());
        for (std::size_t i = 0; i < kGrid.size(); ++i) {
            // Deviations shrink in proportion to the optical depth (τ ≤ 0.5 at 0.4 µm).
            EXPECT_NEAR(sun[i], 1.0, 2.0 * scale);
            EXPECT_NEAR(view[i], 1.0, 2.0 * scale);
            EXPECT_NEAR(path[i], 0.0, 0.15 * scale);
            EXPECT_NEAR(sky[i], 0.0, 0.15 * scale);
        }
    }
    const ParametricAtmosphereModel zero([] {
        model::ParametricAtmosphere p;
        p.gas_absorption = false;
        p.multiple_scattering = false;
        p.aerosol_optical_depth_550 = 0.0;
        p.sea_level_pressure_hpa = 0.0;
        p.air_temperature_k = 0.0;
        return p;
    }());
    EXPECT_EQ(zero.sun_transmittance(kGrid, g), none.sun_transmittance(kGrid, g));
    EXPECT_EQ(zero.sensor_transmittance(kGrid, g), none.sensor_transmittance(kGrid, g));
    EXPECT_EQ(zero.path_radiance_w_per_cm2_sr_um(kGrid, g, toa()),
              none.path_radiance_w_per_cm2_sr_um(kGrid, g, toa()));
    EXPECT_EQ(zero.sky_radiance_w_per_cm2_sr_um(kGrid, g, toa()),
              none.sky_radiance_w_per_cm2_sr_um(kGrid, g, toa()));
}

TEST(ParametricAtmosphere, SingleScatterMatchesTheHomogeneousLayerFormula) {
    // Rayleigh only, sensor above the atmosphere, sun and view at zenith: single scattering
    // gives L = E0 P μs (1 − exp(−τ(1/μs + 1/μv))) / (4π (μs + μv)) for any vertical profile,
    // i.e. E0 P(180°) (1 − exp(−2τ)) / (8π) with P(180°) = 1.5.
    auto p = with_aod(0.0);
    const ParametricAtmosphereModel m(p);
    const auto g = nadir(0.0, 100'000.0);
    const auto l = m.path_radiance_w_per_cm2_sr_um(kGrid, g, toa());
    for (std::size_t i = 0; i < kGrid.size(); ++i) {
        const double tau =
            m.rayleigh_optical_depth(kGrid.wavelength_um(i), 0.0) * relative_air_mass(0.0);
        const double expected = 0.15 * 1.5 * (1.0 - std::exp(-2.0 * tau)) / (8.0 * M_PI);
        EXPECT_NEAR(l[i], expected, 0.01 * expected);
    }
}

TEST(ParametricAtmosphere, ThermalSkyFromAirTemperature) {
    const ParametricAtmosphereModel m(with_aod(0.1));
    EXPECT_NEAR(m.sky_emissivity(), 1.24 * std::pow(10.0 / 288.15, 1.0 / 7.0), 1e-12);
    const SpectralGrid thermal = SpectralGrid::regular(8.0, 12.0, 1.0);
    const auto l = m.thermal_sky_radiance_w_per_cm2_sr_um(thermal, nadir(30.0, 0.0));
    for (std::size_t i = 0; i < thermal.size(); ++i) {
        EXPECT_NEAR(
            l[i],
            m.sky_emissivity() * planck_radiance_w_per_cm2_sr_um(thermal.wavelength_um(i), 288.15),
            1e-15);
    }
    EXPECT_THROW(ParametricAtmosphereModel(with_aod(-0.1)), Error);
}

TEST(SimpleAtmosphere, SkyAtApparentTemperature) {
    const SimpleAtmosphereModel m(model::SimpleAtmosphere{260.0});
    const SpectralGrid thermal = SpectralGrid::regular(8.0, 12.0, 1.0);
    const auto g = nadir(30.0, 1000.0);
    const std::vector<double> zero(thermal.size(), 0.0);
    const auto sky = m.sky_radiance_w_per_cm2_sr_um(thermal, g, zero);
    for (std::size_t i = 0; i < thermal.size(); ++i) {
        EXPECT_DOUBLE_EQ(sky[i], planck_radiance_w_per_cm2_sr_um(thermal.wavelength_um(i), 260.0));
    }
    for (double v : m.sensor_transmittance(thermal, g)) EXPECT_EQ(v, 1.0);
}

TEST(TabulatedAtmosphere, InterpolatesTheTableAndRefusesToExtrapolate) {
    // The table of tests/data/atmosphere/table.txt, as the reader gives it.
    model::Atmosphere atmosphere;
    atmosphere.kind = model::AtmosphereKind::tabulated;
    model::TabulatedAtmosphere& table = atmosphere.tabulated;
    table.wavelengths_um = {0.40, 0.55, 1.00, 2.50};
    table.sun_transmittance = {0.60, 0.75, 0.90, 0.95};
    table.sensor_transmittance = {0.70, 0.82, 0.93, 0.97};
    table.path_radiance_w_per_cm2_sr_um = {0.0030, 0.0015, 0.0004, 0.0001};
    table.sky_irradiance_w_per_cm2_um = {0.030, 0.020, 0.006, 0.001};
    table.sky_temperature_k = 250.0;
    const auto model = make_atmosphere_model(atmosphere);
    const SpectralGrid grid({0.4, 0.475, 1.0});
    const auto g = nadir(30.0, 1000.0);
    const std::vector<double> e0(3, 0.1);
    const auto sun = model->sun_transmittance(grid, g);
    EXPECT_NEAR(sun[0], 0.60, 1e-12);
    EXPECT_NEAR(sun[1], 0.675, 1e-12);
    EXPECT_NEAR(sun[2], 0.90, 1e-12);
    EXPECT_NEAR(model->path_radiance_w_per_cm2_sr_um(grid, g, e0)[1], 0.00225, 1e-12);
    EXPECT_NEAR(model->diffuse_sky_irradiance_w_per_cm2_um(grid, g, e0)[2], 0.006, 1e-12);
    EXPECT_NEAR(model->thermal_sky_radiance_w_per_cm2_sr_um(grid, g)[2],
                planck_radiance_w_per_cm2_sr_um(1.0, 250.0), 1e-20);
    EXPECT_THROW((void)model->sun_transmittance(SpectralGrid({0.3, 0.5}), g), Error);
}

TEST(ParametricAtmosphere, AirMassInverse) {
    // Air mass 1.5 at 48.26° by Kasten–Young (ASTM G173 quotes 48.236° from another air-mass
    // formula), and the inverse of every value: the air mass at the angle found is the one
    // asked for. (Kasten–Young has a shallow minimum, 0.99966, 0.03° from the zenith.)
    EXPECT_NEAR(zenith_for_relative_air_mass(1.5), 48.26, 0.01);
    for (double z : {0.0, 10.0, 48.2, 70.0, 85.0, 89.5, 90.0}) {
        const double m = relative_air_mass(z);
        EXPECT_NEAR(relative_air_mass(zenith_for_relative_air_mass(m)), m, 1e-9 * m) << z;
    }
    EXPECT_THROW((void)zenith_for_relative_air_mass(0.5), Error);
    EXPECT_THROW((void)zenith_for_relative_air_mass(40.0), Error);
    EXPECT_THROW((void)zenith_for_relative_air_mass(NAN), Error);
}

TEST(AtmosphereFactory, BuildsTheSelectedModel) {
    model::Atmosphere a;
    a.kind = model::AtmosphereKind::none;
    EXPECT_NE(dynamic_cast<NoAtmosphere*>(make_atmosphere_model(a).get()), nullptr);
    a.kind = model::AtmosphereKind::parametric;
    a.parametric.gas_absorption = false;
    EXPECT_NE(dynamic_cast<ParametricAtmosphereModel*>(make_atmosphere_model(a).get()), nullptr);
    a.kind = model::AtmosphereKind::simple;
    EXPECT_NE(dynamic_cast<SimpleAtmosphereModel*>(make_atmosphere_model(a).get()), nullptr);
    a.kind = model::AtmosphereKind::parametric;
    a.parametric.aerosol_scale_height_m = 0.0;
    a.where = ErrorContext{"x.yaml", 3, {}};
    try {
        (void)make_atmosphere_model(a);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.context().file, "x.yaml");
    }
}

}  // namespace atmosphere_test
}  // namespace glint::atmosphere
