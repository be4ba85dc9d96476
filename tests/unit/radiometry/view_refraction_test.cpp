// SPDX-License-Identifier: Apache-2.0
// Tests of the refracted view rays (glint/radiometry/view_refraction.h): the table is the
// tracer's ground intersection at its nodes; a bent ray crosses the ground plane where the
// refracted ray lands and arrives at its zenith; the blue and near-infrared channels of a
// sensor 700 km up see ground points 1.155 m apart at a 70° view zenith (the tracer's own
// dispersion, tests/unit/atmosphere/refraction_test.cpp); rays that rise, look straight down
// or graze are left alone; bad altitudes are input errors.
#include "glint/radiometry/view_refraction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "glint/core/error.h"
#include "glint/model/standard_atmospheres.h"

namespace glint::radiometry {
namespace view_refraction_test {

using glint::atmosphere::RefractionTracer;
using glint::atmosphere::RefractiveProfile;

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kSensorM = 700e3;

RefractionTracer tracer(double wavelength_um) {
    return RefractionTracer(RefractiveProfile(
        model::standard_atmosphere(model::StandardAtmosphere::us_standard_1976), wavelength_um));
}

/// The straight ray's nadir angle at the sensor for view zenith `zenith_deg` at the ground.
double nadir_for(double zenith_deg, double ground_m = 0.0) {
    const double a = glint::atmosphere::kMeanEarthRadiusM;
    return std::asin((a + ground_m) * std::sin(zenith_deg * kDeg) / (a + kSensorM)) / kDeg;
}

/// A ray descending northwards at zenith `zenith_deg` whose straight line meets the ground
/// plane at `(x, y)`, starting `range_m` back along it.
SampleRay ray_to(double x, double y, double zenith_deg, double range_m = 1.5e6) {
    const Vec3 d{0.0, std::sin(zenith_deg * kDeg), -std::cos(zenith_deg * kDeg)};
    return {Vec3{x, y, 0.0} - d * range_m, d, 2.5, 0.75};
}

// At its nodes the table is the tracer's ground intersection (1e-9 relative: the same calls,
// the nadir angle rounded); between them within 1 mm of the tracer at 70.1° (measured 0.17 mm)
// and 5e-4 of it at 85.1° (measured 0.8 m of 2,614 m: the Earth's curvature bends the ratio to
// the flat law fastest near the horizon, where a pixel from orbit spans kilometres).
TEST(ViewRefraction, TheTableIsTheTracersGroundIntersection) {
    const RefractionTracer blue = tracer(0.45);
    const ViewRefraction view(blue, 0.0, kSensorM);
    EXPECT_DOUBLE_EQ(view.wavelength_um(), 0.45);
    for (const double zenith : {0.0, 30.0, 70.0, 85.0}) {
        const auto g = blue.ground_intersection(kSensorM, nadir_for(zenith));
        EXPECT_NEAR(view.displacement_m(zenith), g.displacement_m,
                    1e-9 * std::abs(g.displacement_m) + 1e-9)
            << zenith;
        EXPECT_NEAR(view.zenith_change_deg(zenith), g.view_zenith_deg - g.straight_view_zenith_deg,
                    1e-9)
            << zenith;
    }
    for (const auto& [zenith, tolerance] : {std::pair{70.1, 0.001}, std::pair{85.1, 1.31}}) {
        const auto between = blue.ground_intersection(kSensorM, nadir_for(zenith));
        EXPECT_NEAR(view.displacement_m(zenith), between.displacement_m, tolerance) << zenith;
        std::printf("  %.1f°: table %.6f m, tracer %.6f m\n", zenith, view.displacement_m(zenith),
                    between.displacement_m);
    }
    // Refraction brings the ground point towards the sensor and the ray arrives steeper.
    EXPECT_GT(view.displacement_m(70.0), 50.0);
    EXPECT_LT(view.zenith_change_deg(70.0), 0.0);
    EXPECT_EQ(view.displacement_m(0.0), 0.0);
    EXPECT_EQ(view.displacement_m(89.5), 0.0);  // beyond the table: straight
}

// A bent ray crosses the ground plane displacement_m nearer the sensor, at the refracted
// zenith, in the straight ray's vertical plane; its origin is as far back as the sensor was;
// its time and weight are the straight ray's.
TEST(ViewRefraction, ABentRayLandsWhereTheRefractedRayDoes) {
    const ViewRefraction view(tracer(0.45), 0.0, kSensorM);
    const SampleRay straight = ray_to(120.0, -40.0, 70.0);
    const SampleRay bent = view.bend(straight);
    const double t = -bent.origin_m.z / bent.direction.z;
    const Vec3 crossing = bent.origin_m + bent.direction * t;
    EXPECT_NEAR(crossing.x, 120.0, 1e-6);
    EXPECT_NEAR(crossing.y, -40.0 - view.displacement_m(70.0), 1e-6);
    EXPECT_NEAR(crossing.z, 0.0, 1e-6);
    EXPECT_NEAR(std::acos(-bent.direction.z) / kDeg, 70.0 + view.zenith_change_deg(70.0), 1e-9);
    EXPECT_NEAR(norm(bent.direction), 1.0, 1e-15);
    EXPECT_NEAR(bent.direction.x, 0.0, 1e-15);
    EXPECT_NEAR(norm(bent.origin_m - crossing), 1.5e6, 1e-3);
    EXPECT_EQ(bent.time_s, 2.5);
    EXPECT_EQ(bent.weight, 0.75);
}

// Dispersion: the same pixel's ray at 0.45 and at 0.90 µm lands 1.155 m apart at a 70° view
// zenith from 700 km (the tracer's measured difference, within 2 mm of interpolation), 0.025
// of a 10 µrad pixel (46.3 m there); each channel of a split render traces its own.
TEST(ViewRefraction, ChannelsAtDifferentWavelengthsSeeDifferentGround) {
    const ViewRefraction blue(tracer(0.45), 0.0, kSensorM);
    const ViewRefraction nir(tracer(0.90), 0.0, kSensorM);
    const SampleRay straight = ray_to(0.0, 0.0, 70.0);
    const auto land = [](const SampleRay& r) {
        const double t = -r.origin_m.z / r.direction.z;
        return r.origin_m + r.direction * t;
    };
    const double apart_m = land(nir.bend(straight)).y - land(blue.bend(straight)).y;
    EXPECT_NEAR(apart_m, 1.155, 0.002);
}

// Left straight: a rising or level ray, one from below the plane, a nadir ray, a ray beyond
// the table's 89°.
TEST(ViewRefraction, RaysThatDoNotDescendOntoTheGroundAreLeftStraight) {
    const ViewRefraction view(tracer(0.55), 0.0, kSensorM);
    const auto same = [](const SampleRay& a, const SampleRay& b) {
        return a.origin_m.x == b.origin_m.x && a.origin_m.y == b.origin_m.y &&
               a.origin_m.z == b.origin_m.z && a.direction.x == b.direction.x &&
               a.direction.y == b.direction.y && a.direction.z == b.direction.z;
    };
    const SampleRay up{{0.0, 0.0, 10.0}, {0.0, 0.6, 0.8}, 0.0, 1.0};
    const SampleRay level{{0.0, 0.0, 10.0}, {0.0, 1.0, 0.0}, 0.0, 1.0};
    const SampleRay below{{0.0, 0.0, -5.0}, {0.0, 0.6, -0.8}, 0.0, 1.0};
    const SampleRay nadir{{0.0, 0.0, 7e5}, {0.0, 0.0, -1.0}, 0.0, 1.0};
    const SampleRay grazing = ray_to(0.0, 0.0, 89.5);
    for (const SampleRay& r : {up, level, below, nadir, grazing}) {
        EXPECT_TRUE(same(view.bend(r), r));
    }
}

// A source that bends another's rays.
TEST(ViewRefraction, ARefractedSourceBendsTheStraightSourcesRays) {
    struct Fixed final : RaySource {
        SampleRay generate(std::uint64_t, std::uint64_t, RandomStream&) const override {
            return ray_to(0.0, 0.0, 60.0);
        }
    } straight;
    const ViewRefraction view(tracer(0.55), 0.0, kSensorM);
    const RefractedRaySource bent(straight, view);
    RandomStream rng(1, {0});
    const SampleRay r = bent.generate(0, 0, rng);
    const SampleRay expected = view.bend(ray_to(0.0, 0.0, 60.0));
    EXPECT_EQ(r.direction.y, expected.direction.y);
    EXPECT_EQ(r.origin_m.y, expected.origin_m.y);
}

TEST(ViewRefraction, ASensorBelowTheGroundIsAnInputError) {
    try {
        (void)ViewRefraction(tracer(0.55), 500.0, 200.0);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(std::string(e.what()).find("refracted view rays need a sensor above the ground"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace view_refraction_test
}  // namespace glint::radiometry
