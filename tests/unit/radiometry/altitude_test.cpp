// SPDX-License-Identifier: Apache-2.0
// The atmosphere at each surface's own altitude: the levels a scene's environment is computed
// at (altitude_levels), and plates from 0 to 60 km (and one above the model's 100 km top)
// seen from 700 km under the parametric atmosphere, each lit by the sun and sky of its own
// altitude and seen through the air above it: the tracer's radiance is
// T_v(h) ρ (E_sun(h) cos θs / π + L_sky(h)) + L_p(h), every term asked of the model at h.
// Also the interpolation between levels, and a level above the sensor (the reversed path).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/core/error.h"
#include "glint/core/spectral.h"
#include "glint/radiometry/environment.h"
#include "glint/radiometry/sampling.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace altitude_test {

using test::batch_of;
using test::direction_from;
using test::FixedRay;
using test::flat_material;
using test::Rig;

constexpr double kOriginAltitude_m = 150.0;
constexpr double kSensorHeight_m = 700'000.0;        // above the scene origin
const SpectralGrid kGrid({0.45, 0.55, 0.76, 0.94});  // 0.76: O₂ A band; 0.94: water

/// The parametric model with its default aerosol and multiple scattering (gases off: the
/// band-model table has its own tests, and the terms compared here are the model's either way),
/// the isotropic sky (a Lambertian plate then reflects it exactly with every draw;
/// directional_sky_test.cpp tests the directional one).
glint::atmosphere::ParametricAtmosphereModel parametric() {
    model::ParametricAtmosphere parameters;
    parameters.gas_absorption = false;
    parameters.directional_sky = false;
    return glint::atmosphere::ParametricAtmosphereModel(parameters);
}

const glint::atmosphere::SolarSpectrum& solar() {
    static const glint::atmosphere::SolarSpectrum sun(
        SpectralCurve({0.3, 1.0, 4.0}, {0.2, 0.1, 0.001}));
    return sun;
}

/// A 100 m plate facing up at height `z_m`, `x_m` east of the origin.
void add_plate(model::Scene& scene, double x_m, double z_m) {
    model::Primitive plate = test::ground_plane(100.0);
    plate.center_m = {x_m, 0.0, z_m};
    test::add_primitive(scene, plate, 0);
}

std::vector<double> levels_of(const model::Scene& scene) {
    const auto trajectories =
        motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{});
    return altitude_levels(scene::GeometryScene::build(scene, trajectories, {}));
}

/// The model's geometry at height `z_m` above the origin, seen from the sensor overhead.
glint::atmosphere::AtmosphereGeometry at_height(double z_m) {
    glint::atmosphere::AtmosphereGeometry g;
    g.sun_zenith_deg = 40.0;
    g.sun_azimuth_deg = 160.0;
    g.surface_altitude_m = kOriginAltitude_m + z_m;
    g.sensor_altitude_m = kOriginAltitude_m + kSensorHeight_m;
    g.view_zenith_deg = 0.0;
    g.view_azimuth_deg = 160.0;
    return g;
}

Environment environment_for(const glint::atmosphere::AtmosphereModel& model,
                            std::vector<double> levels, double sensor_height_m) {
    EnvironmentInputs inputs;
    inputs.sun_direction_begin = inputs.sun_direction_end = direction_from(40.0, 160.0);
    inputs.surface_altitude_m = kOriginAltitude_m;
    inputs.sensor_altitude_m = kOriginAltitude_m + sensor_height_m;
    inputs.levels_z_m = std::move(levels);
    return Environment::make(kGrid, model, solar(), inputs);
}

TEST(AltitudeLevels, FollowTheSurfacesOfTheScene) {
    model::Scene scene;
    scene.materials.push_back(flat_material("grey", 0.3, 300.0));
    EXPECT_EQ(levels_of(scene), std::vector<double>{0.0});  // no surfaces
    add_plate(scene, 0.0, 0.0);
    // A 30 m box on the ground: one range 0–30 m, less than a step tall, one level at 15 m.
    test::add_primitive(scene, test::box({10, 10, 0}, {20, 20, 30}), 0);
    EXPECT_EQ(levels_of(scene), std::vector<double>{15.0});
    // A 2 m box 50 km up: its own level, at its middle.
    test::add_primitive(scene, test::box({9000, 9000, 50000}, {9002, 9002, 50002}), 0);
    EXPECT_EQ(levels_of(scene), (std::vector<double>{15.0, 50001.0}));
    // A 1 km hill: levels 250 m apart or closer from its foot to its top.
    test::add_primitive(scene, test::box({-500, -500, 0}, {-400, -400, 1000}), 0);
    EXPECT_EQ(levels_of(scene), (std::vector<double>{0.0, 250.0, 500.0, 750.0, 1000.0, 50001.0}));
}

TEST(AltitudeLevels, AScenePastTheLevelLimitIsRefused) {
    // One joined range 200 km tall would need 801 levels 250 m apart (at most 512).
    model::Scene scene;
    scene.materials.push_back(flat_material("grey", 0.3, 300.0));
    test::add_primitive(scene, test::box({0, 0, 0}, {1, 1, 200'000}), 0);
    try {
        levels_of(scene);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(std::string(e.what()).find("the scene's surfaces span 200000 m of height: more "
                                             "than the 512 atmosphere levels glint computes"),
                  std::string::npos)
            << e.what();
    }
    // The environment refuses more levels than that too.
    const auto model = parametric();
    EXPECT_THROW(environment_for(model, std::vector<double>(513, 0.0), kSensorHeight_m), Error);
}

TEST(AltitudeLevels, EachPlateIsLitAndSeenThroughTheAtmosphereAtItsAltitude) {
    const std::vector<double> heights_m = {0.0,      10'000.0, 20'000.0, 30'000.0,
                                           40'000.0, 50'000.0, 60'000.0, 120'000.0};
    model::Scene scene;
    constexpr double kRho = 0.3;
    scene.materials.push_back(flat_material("grey", kRho, 1.0));  // 1 K: no emission
    // 100 km apart: no plate shades another or is seen by another's sky rays.
    for (std::size_t i = 0; i < heights_m.size(); ++i) {
        add_plate(scene, 100'000.0 * static_cast<double>(i), heights_m[i]);
    }
    ASSERT_EQ(levels_of(scene), heights_m);
    const auto model = parametric();
    Rig rig(scene, kGrid, environment_for(model, levels_of(scene), kSensorHeight_m));
    const Environment& env = rig.environment;
    ASSERT_EQ(env.levels_z_m().size(), heights_m.size());

    const std::vector<double> toa = solar().resample(kGrid, 1.0);
    const double cos_sun = std::cos(40.0 * kPi / 180.0);
    for (std::size_t i = 0; i < heights_m.size(); ++i) {
        const double h = heights_m[i];
        const glint::atmosphere::AtmosphereGeometry g = at_height(h);
        const std::vector<double> t_sun = model.sun_transmittance(kGrid, g);
        const std::vector<double> sky = model.sky_radiance_w_per_cm2_sr_um(kGrid, g, toa);
        const std::vector<double> t_v = model.sensor_transmittance(kGrid, g);
        const std::vector<double> l_p = model.path_radiance_w_per_cm2_sr_um(kGrid, g, toa);
        // The environment's terms at the plate's level are the model's at its altitude
        // (1e-12: the same calls; the tables' view zenith 0 and sun geometry are nodes).
        std::vector<double> env_t(kGrid.size()), env_p(kGrid.size());
        env.sensor_path({0.0, 0.0, 1.0}, 0.0, h, env_t, env_p);
        for (std::size_t b = 0; b < kGrid.size(); ++b) {
            EXPECT_NEAR(env.sun_irradiance_w_per_cm2_um(i)[b], toa[b] * t_sun[b], 1e-12 * toa[b]);
            EXPECT_NEAR(env.sky_radiance_w_per_cm2_sr_um(i)[b], sky[b], 1e-12 * toa[b]);
            EXPECT_NEAR(env_t[b], t_v[b], 1e-12);
            EXPECT_NEAR(env_p[b], l_p[b], 1e-12 * toa[b]);
        }
        // The tracer at the plate: every continuation ray escapes to the sky (no other
        // surface in reach), so the radiance is exact but for the sun disk's draw (its mean
        // cosine differs from cos θs by ≈ 5e-6 relative).
        const FixedRay source(
            {{100'000.0 * static_cast<double>(i), 0.0, kSensorHeight_m}, {0, 0, -1}, 0.0, 1.0});
        const Solutions solved = solve(rig.tracer, batch_of(source, 2000), Context{});
        for (std::size_t b = 0; b < kGrid.size(); ++b) {
            const double expected =
                t_v[b] * kRho * (toa[b] * t_sun[b] * cos_sun / kPi + sky[b]) + l_p[b];
            EXPECT_NEAR(solved.radiance(0)[b], expected, 1e-4 * expected)
                << "plate at " << h << " m, band " << b;
        }
        if (h >= 100'000.0) {
            // Above the model's top: the exo-atmospheric sun, a black sky, no sensor path.
            for (std::size_t b = 0; b < kGrid.size(); ++b) {
                EXPECT_EQ(t_sun[b], 1.0);
                EXPECT_EQ(sky[b], 0.0);
                EXPECT_EQ(t_v[b], 1.0);
                EXPECT_EQ(l_p[b], 0.0);
                EXPECT_NEAR(solved.radiance(0)[b], kRho * toa[b] * cos_sun / kPi,
                            1e-4 * kRho * toa[b] * cos_sun / kPi);
            }
        }
    }
    // Up the column the sun grows brighter and the sky and path radiance fade; at the water
    // band the change from 0 to 10 km is largest.
    const std::size_t water = 3;
    EXPECT_GT(env.sun_irradiance_w_per_cm2_um(1)[water],
              1.02 * env.sun_irradiance_w_per_cm2_um(0)[water]);
    EXPECT_LT(env.sky_radiance_w_per_cm2_sr_um(6)[0],
              0.05 * env.sky_radiance_w_per_cm2_sr_um(0)[0]);
}

TEST(AltitudeLevels, BetweenLevelsTheTermsAreInterpolatedLinearly) {
    const auto model = parametric();
    const Environment env = environment_for(model, {0.0, 1000.0}, kSensorHeight_m);
    const AltitudeLevel at = env.level_at(250.0);
    EXPECT_EQ(at.index, 0u);
    EXPECT_DOUBLE_EQ(at.fraction, 0.25);
    EXPECT_EQ(env.level_at(-5.0).fraction, 0.0);
    EXPECT_EQ(env.level_at(2000.0).index, 1u);
    EXPECT_EQ(env.level_at(2000.0).fraction, 0.0);
    std::vector<double> t0(kGrid.size()), p0(kGrid.size()), t1(kGrid.size()), p1(kGrid.size()),
        t(kGrid.size()), p(kGrid.size());
    const Vec3 up = direction_from(30.0, 100.0);
    env.sensor_path(up, 0.0, 0.0, t0, p0);
    env.sensor_path(up, 0.0, 1000.0, t1, p1);
    env.sensor_path(up, 0.0, 250.0, t, p);
    for (std::size_t b = 0; b < kGrid.size(); ++b) {
        EXPECT_NEAR(t[b], 0.75 * t0[b] + 0.25 * t1[b], 1e-15);
        EXPECT_NEAR(p[b], 0.75 * p0[b] + 0.25 * p1[b], 1e-18);
        EXPECT_GT(t1[b], t0[b]);  // less air above 1 km
    }
    // Linear interpolation over 250 m (the widest spacing altitude_levels leaves) against the
    // model at the midpoint: the sun's transmittance within 0.1 %.
    const Environment fine = environment_for(model, {0.0, 250.0}, kSensorHeight_m);
    const std::vector<double> mid = model.sun_transmittance(kGrid, at_height(125.0));
    const std::vector<double> toa = solar().resample(kGrid, 1.0);
    for (std::size_t b = 0; b < kGrid.size(); ++b) {
        const double interpolated =
            0.5 * (fine.sun_irradiance_w_per_cm2_um(0)[b] + fine.sun_irradiance_w_per_cm2_um(1)[b]);
        EXPECT_NEAR(interpolated, toa[b] * mid[b], 1e-3 * toa[b] * mid[b]) << b;
    }
}

TEST(AltitudeLevels, ALevelAboveTheSensorSeesItThroughTheAirBetween) {
    // A sensor 1 km up looking at a surface 10 km up: the path's transmittance is the
    // model's between the two (reciprocity), from the direction reversed; no path radiance
    // (the model's is the downward view's).
    const auto model = parametric();
    const Environment env = environment_for(model, {0.0, 10'000.0}, 1000.0);
    const Vec3 down = direction_from(150.0, 20.0);  // surface → sensor, 30° from the nadir
    std::vector<double> t(kGrid.size()), p(kGrid.size());
    env.sensor_path(down, 0.0, 10'000.0, t, p);
    glint::atmosphere::AtmosphereGeometry g = at_height(1000.0);
    g.sensor_altitude_m = kOriginAltitude_m + 10'000.0;
    g.view_zenith_deg = 28.0;  // the tables' nodes around 30°: 28° and 32°
    const std::vector<double> t28 = model.sensor_transmittance(kGrid, g);
    g.view_zenith_deg = 32.0;
    const std::vector<double> t32 = model.sensor_transmittance(kGrid, g);
    for (std::size_t b = 0; b < kGrid.size(); ++b) {
        EXPECT_NEAR(t[b], 0.5 * (t28[b] + t32[b]), 1e-12);
        EXPECT_LT(t[b], 1.0);
        EXPECT_EQ(p[b], 0.0);
    }
}

}  // namespace altitude_test
}  // namespace glint::radiometry
