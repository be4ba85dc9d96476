// SPDX-License-Identifier: Apache-2.0
// The light of a run (glint/radiometry/illumination.h): by day the sun at both ends of the
// window, by night the moon (its irradiance the sun's times the lunar ratio, its angular
// radius), both through the atmosphere (none here: the irradiance is the top of the
// atmosphere's); the point sources where they are at the time asked; the tabulated
// atmosphere's one-geometry warning; and the data tables it cannot do without.
#include "glint/radiometry/illumination.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "glint/atmosphere/lunar.h"
#include "glint/atmosphere/refraction.h"
#include "glint/core/error.h"
#include "glint/test/captured_log.h"
#include "glint/test/errors.h"
#include "glint/test/motions.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace illumination_test {

using ::testing::HasSubstr;

const SpectralGrid kGrid({0.45, 0.55, 0.65});

/// A flat solar table (1e-3 W/(cm² µm) at 1 AU over 0.3–2.5 µm).
std::shared_ptr<const glint::atmosphere::SolarSpectrum> flat_sun() {
    return std::make_shared<const glint::atmosphere::SolarSpectrum>(
        SpectralCurve({0.3, 2.5}, {1e-3, 1e-3}, {}));
}

glint::atmosphere::DataTables tables() { return {flat_sun(), nullptr, nullptr}; }

/// Rochester, NY at sea level.
const motion::SceneFrame kRochester(43.16, -77.61, 0.0);

/// A scene with one point-source material (100 W/(sr µm) at 0.4 µm to 300 at 0.7 µm) and a
/// static lamp at (1, 2, 3) and a moving one riding glint::test::driving_east().
model::Scene lamps() {
    model::Scene scene;
    model::Material lamp = model::flat_material("lamp", 0.0);
    lamp.point_source = true;
    lamp.intensity_w_per_sr_um.wavelengths_um = {0.4, 0.7};
    lamp.intensity_w_per_sr_um.values = {100.0, 300.0};
    scene.materials.push_back(lamp);
    model::PointSource fixed;
    fixed.name = "post";
    fixed.position_m = {1.0, 2.0, 3.0};
    model::PointSource moving;
    moving.name = "car";
    moving.motion = std::make_shared<const model::PlatformMotion>(glint::test::driving_east());
    scene.point_sources = {fixed, moving};
    return scene;
}

TEST(Illumination, ByDayTheSunAtBothEndsOfTheWindow) {
    const model::Scene scene;
    const Illumination light =
        Illumination::make(model::Atmosphere{}, tables(), scene, kRochester, DateTime{});
    const DateTime reference = parse_iso8601("2026-06-21T16:00:00Z");
    const Environment env =
        light.environment(kGrid, {reference, 0.0, 600.0}, 1000.0, {}, 1, nullptr);
    const motion::SunPosition begin = light.sun_at(reference);
    const motion::SunPosition end = light.sun_at(add_seconds(reference, 600.0));
    ASSERT_LT(begin.zenith_deg, 40.0);
    EXPECT_NEAR(motion::dot(env.sun_direction(0.0), begin.direction_enu), 1.0, 1e-12);
    EXPECT_NEAR(motion::dot(env.sun_direction(600.0), end.direction_enu), 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(env.sun_half_angle_rad(), kSunAngularRadiusRad);
    // No atmosphere: the beam's irradiance is the top of the atmosphere's at the sun's
    // distance (1e-3 / d², d ≈ 1.016 AU at the June solstice).
    for (std::size_t b = 0; b < kGrid.size(); ++b) {
        EXPECT_NEAR(env.sun_irradiance_w_per_cm2_um()[b],
                    1e-3 / (begin.distance_au * begin.distance_au), 1e-12);
    }
}

// With the parametric atmosphere's refraction the sun's direction is its apparent one (the
// tracer's inverse refraction from the scene origin, at the grid's middle wavelength: 1e-9
// in the direction's cosine), raised towards the zenith with its azimuth kept; a sensor above
// the origin gets view rays bent at the wavelength asked, cached by rounded altitude and
// wavelength; without refraction (the option off, or the isothermal profile) nothing.
TEST(Illumination, RefractionRaisesTheSunAndBendsViewRays) {
    const model::Scene scene;
    model::Atmosphere air;
    air.kind = model::AtmosphereKind::parametric;
    air.parametric.gas_absorption = false;
    air.parametric.multiple_scattering = false;
    air.parametric.air_temperature_k = 288.2;  // the profile's own: no shift
    const Illumination light = Illumination::make(air, tables(), scene, kRochester, DateTime{});
    ASSERT_TRUE(light.refracts());
    // Late afternoon: the sun low in the west.
    const DateTime reference = parse_iso8601("2026-06-21T23:50:00Z");
    const motion::SunPosition sun = light.sun_at(reference);
    ASSERT_GT(sun.zenith_deg, 80.0);
    ASSERT_LT(sun.zenith_deg, 89.0);
    const Environment env = light.environment(kGrid, {reference, 0.0, 0.0}, 1000.0, {}, 1, nullptr);
    const Vec3 apparent = env.sun_direction(0.0);
    const glint::atmosphere::RefractionTracer tracer(glint::atmosphere::RefractiveProfile(
        model::standard_atmosphere(model::StandardAtmosphere::us_standard_1976), 0.55));
    const double expected_zenith = *tracer.apparent_zenith_for_true_deg(0.0, sun.zenith_deg);
    EXPECT_NEAR(std::acos(apparent.z) * 180.0 / kPi, expected_zenith, 1e-6);
    EXPECT_GT(sun.zenith_deg - expected_zenith, 0.05);  // several arcminutes near the horizon
    EXPECT_NEAR(std::atan2(apparent.x, apparent.y),
                std::atan2(sun.direction_enu.x, sun.direction_enu.y), 1e-12);

    radiometry::SensorPathCache cache;
    const auto blue = light.view_refraction(0.45, 20'000.0, &cache);
    ASSERT_NE(blue, nullptr);
    EXPECT_DOUBLE_EQ(blue->wavelength_um(), 0.45);
    EXPECT_GT(blue->displacement_m(70.0), 10.0);
    EXPECT_EQ(light.view_refraction(0.45, 20'000.2, &cache), blue);  // the same rounded key
    const auto nir = light.view_refraction(0.90, 20'000.0, &cache);
    EXPECT_LT(nir->displacement_m(70.0), blue->displacement_m(70.0));
    EXPECT_EQ(light.view_refraction(0.45, 0.5, &cache), nullptr);  // on the ground: straight

    // A hotter day: the profile's temperatures shifted +20 K at sea level, the shift fading to
    // 0 at 11 km (as the air's emission shifts them); thinner air near the ground bends less.
    model::Atmosphere hot = air;
    hot.parametric.air_temperature_k = 308.2;
    const Illumination hot_light = Illumination::make(hot, tables(), scene, kRochester, DateTime{});
    std::vector<model::AtmosphereLevel> shifted(
        model::standard_atmosphere(model::StandardAtmosphere::us_standard_1976).levels.begin(),
        model::standard_atmosphere(model::StandardAtmosphere::us_standard_1976).levels.end());
    for (model::AtmosphereLevel& level : shifted) {
        level.temperature_k += 20.0 * std::max(0.0, 1.0 - level.altitude_km / 11.0);
    }
    const radiometry::ViewRefraction expected_hot(
        glint::atmosphere::RefractionTracer(glint::atmosphere::RefractiveProfile(shifted, 0.45)),
        0.0, 20'000.0);
    const auto hot_blue = hot_light.view_refraction(0.45, 20'000.0, nullptr);
    ASSERT_NE(hot_blue, nullptr);
    EXPECT_NEAR(hot_blue->displacement_m(70.0) / expected_hot.displacement_m(70.0), 1.0, 1e-12);
    EXPECT_LT(hot_blue->displacement_m(70.0), 0.99 * blue->displacement_m(70.0));
    EXPECT_GT(hot_blue->displacement_m(70.0), 0.9 * blue->displacement_m(70.0));

    model::Atmosphere straight = air;
    straight.parametric.refraction = false;
    const Illumination off = Illumination::make(straight, tables(), scene, kRochester, DateTime{});
    EXPECT_FALSE(off.refracts());
    EXPECT_EQ(off.view_refraction(0.45, 20'000.0, nullptr), nullptr);
    EXPECT_NEAR(motion::dot(off.environment(kGrid, {reference, 0.0, 0.0}, 1000.0, {}, 1, nullptr)
                                .sun_direction(0.0),
                            sun.direction_enu),
                1.0, 1e-12);
    model::Atmosphere isothermal = air;
    isothermal.parametric.profile = model::StandardAtmosphere::isothermal;
    EXPECT_FALSE(
        Illumination::make(isothermal, tables(), scene, kRochester, DateTime{}).refracts());
}

TEST(Illumination, ByNightTheMoon) {
    const model::Scene scene;
    const Illumination light =
        Illumination::make(model::Atmosphere{}, tables(), scene, kRochester, DateTime{});
    const DateTime reference = parse_iso8601("2026-06-21T04:00:00Z");  // local midnight
    ASSERT_GT(light.sun_at(reference).zenith_deg, 90.0);
    const Environment env = light.environment(kGrid, {reference, 0.0, 1.0}, 1000.0, {}, 1, nullptr);
    const motion::MoonPosition moon = light.moon_at(reference);
    const double distance_au = light.sun_at(reference).distance_au;
    EXPECT_NEAR(motion::dot(env.sun_direction(0.0), moon.direction_enu), 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(env.sun_half_angle_rad(),
                     glint::atmosphere::lunar_angular_radius_rad(moon.distance_km));
    const double ratio =
        glint::atmosphere::lunar_irradiance_ratio(moon.phase_angle_deg, moon.distance_km);
    ASSERT_GT(ratio, 0.0);
    ASSERT_LT(ratio, 1e-5);
    // Within the relative step the environment rounds the source's scale to
    // (SensorPathCache::kSourceScaleStep, 1e-6), so no result depends on what was cached.
    for (std::size_t b = 0; b < kGrid.size(); ++b) {
        const double sun = 1e-3 / (distance_au * distance_au);
        EXPECT_NEAR(env.sun_irradiance_w_per_cm2_um()[b], sun * ratio,
                    SensorPathCache::kSourceScaleStep * sun * ratio);
    }
}

TEST(Illumination, PointSourcesWhereTheyAreAtTheTimeAsked) {
    const model::Scene scene = lamps();
    const Illumination light =
        Illumination::make(model::Atmosphere{}, tables(), scene, motion::SceneFrame(), DateTime{});
    const PointLights at2 = light.point_lights_at(scene, kGrid, 2.0);
    ASSERT_EQ(at2.size(), 2u);
    EXPECT_EQ(at2.position_m(0), (motion::Vec3{1.0, 2.0, 3.0}));
    EXPECT_NEAR(at2.position_m(1).x, 30.0, 1e-12);  // halfway from 10 to 50 m
    // The intensity resampled on the grid: linear between 100 at 0.4 and 300 at 0.7 µm.
    EXPECT_NEAR(at2.intensity_w_per_sr_um(0)[0], 100.0 + 200.0 * (0.05 / 0.3), 1e-9);
    EXPECT_NEAR(at2.intensity_w_per_sr_um(1)[2], 100.0 + 200.0 * (0.25 / 0.3), 1e-9);
    EXPECT_NEAR(light.point_lights_at(scene, kGrid, 4.0).position_m(1).x, 50.0, 1e-12);
}

TEST(Illumination, RefusesASourceWithoutAPointSourceMaterial) {
    model::Scene scene = lamps();
    scene.materials[0].point_source = false;
    const Illumination light =
        Illumination::make(model::Atmosphere{}, tables(), scene, motion::SceneFrame(), DateTime{});
    EXPECT_THAT(glint::test::error_text([&] { (void)light.point_lights_at(scene, kGrid, 0.0); }),
                HasSubstr("internal error: point source \"post\" does not name a point-source "
                          "material"));
}

TEST(Illumination, ATabulatedAtmosphereWarnsOnceForSurfacesAtSeveralHeights) {
    model::Atmosphere tabulated;
    tabulated.kind = model::AtmosphereKind::tabulated;
    tabulated.tabulated.wavelengths_um = {0.4, 0.7};
    tabulated.tabulated.sun_transmittance = {0.8, 0.9};
    tabulated.tabulated.sensor_transmittance = {0.8, 0.9};
    tabulated.tabulated.path_radiance_w_per_cm2_sr_um = {0.0, 0.0};
    tabulated.tabulated.sky_irradiance_w_per_cm2_um = {0.0, 0.0};
    tabulated.where = {"sky.atm.yaml", 3, {}};
    model::Scene scene;
    scene.materials.push_back(model::flat_material("grey", 0.5));
    test::add_primitive(scene, test::ground_plane(), 0);
    model::Primitive roof = test::box({0.0, 0.0, 990.0}, {1.0, 1.0, 1000.0});
    test::add_primitive(scene, roof, 0);
    const auto trajectories =
        motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{});
    const scene::GeometryScene geometry =
        scene::GeometryScene::build(scene, trajectories, scene::BuildOptions{});
    // Levels: the ground's (0 m) and the roof's, 10 m tall, at its middle (995 m).
    const glint::test::CapturedLog tabulated_log;
    Illumination::make(tabulated, tables(), scene, motion::SceneFrame(), DateTime{})
        .warn_if_one_geometry(geometry, tabulated_log.log());
    EXPECT_EQ(tabulated_log.text(),
              "warning: sky.atm.yaml:3: a tabulated atmosphere is one geometry: its sun, sky and "
              "path terms are applied at every height, but the scene has surfaces from 0 m to "
              "995 m above its origin (docs/scene.md, \"At which altitude each light path sees "
              "the atmosphere\")\n");
    const glint::test::CapturedLog none_log;
    Illumination::make(model::Atmosphere{}, tables(), scene, motion::SceneFrame(), DateTime{})
        .warn_if_one_geometry(geometry, none_log.log());
    EXPECT_EQ(none_log.text(), "");
    EXPECT_FALSE(Illumination::make(tabulated, tables(), scene, motion::SceneFrame(), DateTime{})
                     .gas_table_range_um());
}

TEST(Illumination, RefusesToMakeLightWithoutTheSolarSpectrum) {
    EXPECT_THAT(glint::test::error_text([] {
                    (void)Illumination::make(model::Atmosphere{}, {}, model::Scene{},
                                             motion::SceneFrame(), DateTime{});
                }),
                HasSubstr("internal error: glint's data tables were not read "
                          "(inputs::read_data_tables)"));
}

}  // namespace illumination_test
}  // namespace glint::radiometry
