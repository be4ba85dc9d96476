// SPDX-License-Identifier: Apache-2.0
// The directional thermal sky in the environment and the tracer (docs/thermal.md): the
// environment holds the model's sky at every 3° of zenith; a camera ray that escapes reads it
// at its own zenith angle, linearly between the nodes; a Lambertian plate reflects the
// cosine-weighted mean of the whole sky, which is the model's isotropic equivalent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/gas_absorption.h"
#include "glint/io/input_files.h"
#include "glint/radiometry/environment.h"
#include "glint/test/gas_table.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace thermal_sky_test {

using test::batch_of;
using test::direction_from;
using test::FixedRay;
using test::kSigmas;
using test::repeated_runs;
using test::RepeatedRuns;
using test::Rig;

const SpectralGrid kLwir({7.0, 8.5, 10.0, 11.5, 13.5});

const glint::atmosphere::ParametricAtmosphereModel& parametric() {
    static const glint::atmosphere::ParametricAtmosphereModel model(model::ParametricAtmosphere{},
                                                                    glint::test::gas_table());
    return model;
}

const glint::atmosphere::SolarSpectrum& solar() {
    static const glint::atmosphere::SolarSpectrum sun(
        SpectralCurve({0.3, 1.0, 20.0}, {0.2, 0.1, 1e-6}));
    return sun;
}

/// Night (no sun), the scene at sea level, the sensor at 3 km.
Environment night() {
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = inputs.sun_direction_end = direction_from(120.0, 0.0);
    inputs.sensor_altitude_m = 3000.0;
    return Environment::make(kLwir, parametric(), solar(), inputs);
}

glint::atmosphere::AtmosphereGeometry at_ground() {
    glint::atmosphere::AtmosphereGeometry g;
    g.sun_zenith_deg = 120.0;
    g.sensor_altitude_m = 3000.0;
    return g;
}

TEST(ThermalSky, TheEnvironmentHoldsTheModelsSkyByZenith) {
    const Environment env = night();
    ASSERT_EQ(env.sky_nodes(), Environment::kSkyZenithNodes);
    for (std::size_t node = 0; node < env.sky_nodes(); node += 5) {
        const double zenith = static_cast<double>(node) * Environment::kSkyZenithStepDeg;
        const auto expected =
            parametric().thermal_sky_radiance_at_zenith(kLwir, at_ground(), zenith);
        for (std::size_t b = 0; b < kLwir.size(); ++b) {
            EXPECT_NEAR(env.sky_radiance_w_per_cm2_sr_um(0, node)[b], expected[b],
                        1e-12 * expected[b])
                << zenith << "°";
        }
    }
    const AltitudeLevel at_45 = env.sky_node(std::cos(45.0 * kPi / 180.0));
    EXPECT_EQ(at_45.index, 15u);
    EXPECT_NEAR(at_45.fraction, 0.0, 1e-9);
    EXPECT_EQ(env.sky_node(-0.2).index, Environment::kSkyZenithNodes - 1);
    EXPECT_EQ(env.sky_node(1.0).index, 0u);
    // An isotropic model keeps one node.
    const glint::atmosphere::SimpleAtmosphereModel simple(model::SimpleAtmosphere{250.0});
    EnvironmentInputs inputs;
    EXPECT_EQ(Environment::make(kLwir, simple, solar(), inputs).sky_nodes(), 1u);
}

// A camera ray that meets nothing: the sky at its zenith, linear in the air mass between the
// nodes (40.5° lies between 39° and 42°).
TEST(ThermalSky, AnEscapingRayReadsTheSkyAtItsZenith) {
    model::Scene scene;
    scene.materials.push_back(model::flat_material("grey", 0.5, 1.0));
    Rig rig(scene, kLwir, night());
    for (double zenith : {0.0, 40.5, 87.0}) {
        const FixedRay source({{0.0, 0.0, 10.0}, direction_from(zenith, 30.0), 0.0, 1.0});
        const Solutions solved = solve(rig.tracer, batch_of(source, 4), Context{});
        const std::size_t lo = static_cast<std::size_t>(zenith / 3.0);
        const double m_lo = glint::atmosphere::relative_air_mass(3.0 * static_cast<double>(lo));
        const double m_hi = glint::atmosphere::relative_air_mass(3.0 * static_cast<double>(lo + 1));
        const double f = (glint::atmosphere::relative_air_mass(zenith) - m_lo) / (m_hi - m_lo);
        for (std::size_t b = 0; b < kLwir.size(); ++b) {
            const double a = rig.environment.sky_radiance_w_per_cm2_sr_um(0, lo)[b];
            const double c =
                f > 1e-12 ? rig.environment.sky_radiance_w_per_cm2_sr_um(0, lo + 1)[b] : a;
            const double expected = (1.0 - f) * a + f * c;
            EXPECT_NEAR(solved.radiance(0)[b], expected, 1e-9 * expected) << zenith << "°";
        }
    }
    // Towards the horizon the sky is brighter in the 10 µm window.
    const auto window = [&](std::size_t node) {
        return rig.environment.sky_radiance_w_per_cm2_sr_um(0, node)[2];
    };
    EXPECT_GT(window(30), 3.0 * window(0));
}

// A cold (1 K) Lambertian plate of reflectance ρ under the directional sky: L = ρ/π ∫ L_sky
// cos dΩ = ρ × the model's isotropic equivalent (its 8-point Gauss mean), seen through the
// 3 km of air to the sensor (T_v L + L_p), within 4 standard
// errors of 20,000 cosine-distributed draws (from the spread of 20 runs) plus 0.3 % for the nodes'
// linear interpolation against the model's exact zeniths.
TEST(ThermalSky, ALambertianPlateReflectsTheSkysCosineMean) {
    model::Scene scene;
    constexpr double kRho = 0.6;
    scene.materials.push_back(model::flat_material("grey", kRho, 1.0));
    test::add_primitive(scene, test::ground_plane(100.0), 0);
    Rig rig(scene, kLwir, night());
    const FixedRay source({{0.0, 0.0, 50.0}, {0.0, 0.0, -1.0}, 0.0, 1.0});
    // 20 independent runs of 1,000 draws: the mean and its standard error per band from
    // their spread.
    const RepeatedRuns runs = repeated_runs(rig.tracer, source, 1000, 20, 100, kLwir.size());
    const auto mean_sky = parametric().thermal_sky_radiance_w_per_cm2_sr_um(kLwir, at_ground());
    // Seen from the sensor 3 km up: through the air, plus its emission.
    std::vector<double> t_v(kLwir.size()), l_p(kLwir.size());
    rig.environment.sensor_path({0.0, 0.0, 1.0}, 0.0, t_v, l_p);
    for (std::size_t b = 0; b < kLwir.size(); ++b) {
        const double expected = t_v[b] * kRho * mean_sky[b] + l_p[b];
        EXPECT_NEAR(runs.mean[b], expected, kSigmas * runs.standard_error[b] + 0.003 * expected)
            << kLwir.wavelength_um(b) << " µm";
    }
}

}  // namespace thermal_sky_test
}  // namespace glint::radiometry
