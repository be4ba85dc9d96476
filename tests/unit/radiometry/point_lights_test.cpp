// SPDX-License-Identifier: Apache-2.0
// Point sources in the path tracer (glint/radiometry/point_lights.h): a Lambertian plate lit
// by an isotropic source of intensity I at distance r and incidence θ has radiance
// L = ρ/π · I cos θ / r² (10⁻⁴ from m² to cm²), exactly — the source is sampled
// deterministically and every bounce off the plate leaves into a black sky. A box between the
// source and the plate casts its shadow; a source below the plate lights nothing seen from
// above; and bad sources are refused.
#include "glint/radiometry/point_lights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "glint/core/error.h"
#include "tracer_fixture.h"

namespace glint::radiometry {
namespace point_lights_test {

using test::batch_of;
using test::box;
using test::FixedRay;
using test::flat_material;
using test::ground_plane;

const SpectralGrid kVisible({0.45, 0.55, 0.65});
const std::vector<double> kBlack(3, 0.0);
const std::vector<double> kIntensity{100.0, 200.0, 300.0};  // W/(sr µm)
constexpr double kRho = 0.5;

/// A 1 km nadir camera ray onto `target`.
SampleRay nadir_ray(Vec3 target) { return {target + Vec3{0.0, 0.0, 1000.0}, {0.0, 0.0, -1.0}}; }

/// The radiance of the plate point `target` (z = 0) under `lights`, no sun, black sky;
/// `extra` primitives are black.
std::vector<double> plate_radiance(const PointLights& lights, Vec3 target,
                                   std::vector<model::Primitive> extra = {}) {
    model::Scene scene;
    // At 1 K the plate's own emission underflows to 0 (at 300 K it is ~1e-28 here).
    scene.materials.push_back(flat_material("plate", kRho, 1.0));
    scene.materials.push_back(flat_material("black", 0.0, 1.0));
    test::add_primitive(scene, ground_plane(), 0);
    for (const model::Primitive& p : extra) test::add_primitive(scene, p, 1);
    const auto trajectories =
        motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{});
    const scene::GeometryScene geometry =
        scene::GeometryScene::build(scene, trajectories, scene::BuildOptions{});
    const MaterialTable materials(scene.materials, kVisible);
    const Environment environment = Environment::uniform(kVisible, {0.0, 0.0, 1.0}, kBlack, kBlack);
    const PathTracer tracer(geometry, materials, environment, {}, &lights);
    const FixedRay source(nadir_ray(target));
    return solve(tracer, batch_of(source, 4), 0).radiance_w_per_cm2_sr_um;
}

TEST(PointLights, LambertianPlateFollowsIntensityCosineOverDistanceSquared) {
    const Vec3 light{3.0, 4.0, 10.0};
    PointLights lights(kVisible.size());
    lights.add("lamp", light, kIntensity);
    for (const Vec3 target : {Vec3{3.0, 4.0, 0.0}, Vec3{0.0, 0.0, 0.0}, Vec3{20.0, -7.0, 0.0}}) {
        const Vec3 to = light - target;
        const double r2 = dot(to, to);
        const double cos_theta = to.z / std::sqrt(r2);
        const std::vector<double> l = plate_radiance(lights, target);
        for (std::size_t b = 0; b < kIntensity.size(); ++b) {
            const double expected = kRho / std::numbers::pi * kIntensity[b] * cos_theta / r2 * 1e-4;
            // Exact but for round-off (nothing random contributes).
            EXPECT_NEAR(l[b], expected, 1e-12 * expected) << target.x << " " << b;
        }
    }
}

TEST(PointLights, TwoSourcesAdd) {
    PointLights one(kVisible.size());
    one.add("a", {0.0, 0.0, 5.0}, kIntensity);
    PointLights two = one;
    two.add("b", {4.0, 0.0, 3.0}, kIntensity);
    const Vec3 target{0.0, 0.0, 0.0};
    const std::vector<double> a = plate_radiance(one, target);
    const std::vector<double> ab = plate_radiance(two, target);
    // Source b: r = 5 m, cos θ = 0.6.
    for (std::size_t b = 0; b < kIntensity.size(); ++b) {
        const double second = kRho / std::numbers::pi * kIntensity[b] * 0.6 / 25.0 * 1e-4;
        EXPECT_NEAR(ab[b] - a[b], second, 1e-12 * ab[b]) << b;
    }
}

TEST(PointLights, ABoxCastsItsShadowAndASourceBelowThePlateLightsNothing) {
    PointLights lights(kVisible.size());
    lights.add("lamp", {0.0, 0.0, 10.0}, kIntensity);
    const std::vector<model::Primitive> blocker{box({-1.0, -1.0, 4.0}, {1.0, 1.0, 5.0})};
    // The box's shadow on the ground reaches 10/6 m (its lower edge) to 2 m (its upper edge)
    // from the axis; (1.4, 0) is in it and not under the box.
    const std::vector<double> shadowed = plate_radiance(lights, {1.4, 0.0, 0.0}, blocker);
    const std::vector<double> lit = plate_radiance(lights, {8.0, 0.0, 0.0}, blocker);
    for (const double v : shadowed) EXPECT_EQ(v, 0.0);  // a black box reflects nothing back
    const double r2 = 64.0 + 100.0;
    EXPECT_NEAR(lit[0], kRho / std::numbers::pi * kIntensity[0] * 10.0 / r2 / std::sqrt(r2) * 1e-4,
                1e-12 * lit[0]);

    PointLights below(kVisible.size());
    below.add("under", {0.0, 0.0, -2.0}, kIntensity);
    for (const double v : plate_radiance(below, {0.0, 0.0, 0.0})) EXPECT_EQ(v, 0.0);
}

TEST(PointLights, BadSourcesAreRefusedNamingThem) {
    PointLights lights(3);
    try {
        lights.add("headlight", {0.0, 0.0, 1.0}, std::vector<double>{1.0, -2.0, 3.0});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.message(),
                  "point source \"headlight\" has intensity -2 W/(sr um); it must be finite and "
                  ">= 0");
    }
    EXPECT_THROW(lights.add("x", {0.0, 0.0, 1.0}, std::vector<double>{1.0}), Error);
    EXPECT_THROW(lights.add("x", {0.0, std::nan(""), 1.0}, kIntensity), Error);
    EXPECT_EQ(lights.size(), 0u);
}

}  // namespace point_lights_test
}  // namespace glint::radiometry
