// SPDX-License-Identifier: Apache-2.0
// Tests of the Embree geometry scene's dynamic instances against analytic answers: a box in
// straight motion hit at the window's begin, middle and end (and clamped outside it); a
// spinning rotor that gets enough time steps and stays rigid between them (slerp, not a
// linear blend of matrices), with its tip normal turning; the warning when max_time_steps is
// too few; bounds that cover the whole path; and a zero-length window.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geometry_scene_builders.h"
#include "glint/scene/geometry_scene.h"

namespace glint::scene {
namespace geometry_scene_motion_test {

using namespace glint::scene::test;
using ::testing::HasSubstr;

TEST(GeometrySceneMotion, DynamicInstanceMovesLinearlyOverTheWindow) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    add_dynamic(scene, box, straight_motion({0, 0, 0}, 90.0, 10.0), "car");  // east, 10 m/s
    const GeometryScene geometry = build(scene, options_over(0.0, 10.0));
    // Constant velocity and attitude: linear interpolation is exact, so the minimum suffices.
    EXPECT_EQ(geometry.time_steps(), std::vector<unsigned>{2});

    for (const double t_s : {0.0, 5.0, 10.0, 2.5}) {
        const double x_m = 10.0 * t_s;
        const auto hit = geometry.intersect({x_m + 0.5, 0.0, 50.0}, kDown, t_s);
        ASSERT_TRUE(hit) << t_s;
        EXPECT_NEAR(hit->distance_m, 48.0, kLocalTol_m) << t_s;
        expect_vec_near(hit->normal, kUp, kNormalTol);
        // The box's east edge is at x + 1 (the ray time is float: 1e-7 · 100 m ≈ 1e-5 m).
        EXPECT_TRUE(geometry.intersect({x_m + 0.999, 0.0, 50.0}, kDown, t_s)) << t_s;
        EXPECT_FALSE(geometry.intersect({x_m + 1.001, 0.0, 50.0}, kDown, t_s)) << t_s;
        EXPECT_FALSE(geometry.intersect({x_m - 1.001, 0.0, 50.0}, kDown, t_s)) << t_s;
    }
    // Times outside the window are clamped into it.
    EXPECT_TRUE(geometry.intersect({100.0, 0.0, 50.0}, kDown, 20.0));
    EXPECT_TRUE(geometry.intersect({0.0, 0.0, 50.0}, kDown, -5.0));
    EXPECT_FALSE(geometry.intersect({50.0, 0.0, 50.0}, kDown, -5.0));
}

TEST(GeometrySceneMotion, SpinningRotorGetsEnoughStepsAndStaysRigid) {
    model::Scene scene = scene_with_materials(1);
    // A blade 20 m long (ends at x = ±10), spinning about z at 90°/s over one second.
    const std::size_t blade = add_object(scene, box_mesh({-10, -1, 0}, {10, 1, 1}, 0), "blade");
    add_dynamic(scene, blade, spin_motion({0, 0, 0}, {0, 0, 1}, 90.0), "rotor");
    const GeometryScene geometry = build(scene, options_over(0.0, 1.0));
    // 90° at ≤ 5° per step needs ≥ 18 intervals, i.e. ≥ 19 time steps.
    ASSERT_EQ(geometry.time_steps().size(), 1u);
    const unsigned n = geometry.time_steps()[0];
    EXPECT_GE(n, 19u);
    EXPECT_LE(n, 21u);

    // Mid-step the blade must still be 10 m long: interpolating the matrices linearly would
    // shorten it by 1 − cos(2.5°) ≈ 1e-3 (≈ 9.5e-3 m at the tip); slerp keeps it rigid, up to
    // float rounding of the transform (≈ 1e-5 m). Tolerance 1e-3 m.
    for (const double step : {0.5, 7.5, static_cast<double>(n - 2) + 0.5, 3.25}) {
        const double t_s = step / static_cast<double>(n - 1);
        const double angle = 90.0 * kDeg * t_s;
        const Vec3 out{std::cos(angle), std::sin(angle), 0.0};
        const auto hit = geometry.intersect(out * 50.0 + Vec3{0, 0, 0.5}, -out, t_s);
        ASSERT_TRUE(hit) << t_s;
        EXPECT_NEAR(hit->distance_m, 40.0, 1e-3) << t_s;
        expect_vec_near(hit->normal, out, 1e-5);  // the tip face turns with the blade
    }
}

TEST(GeometrySceneMotion, MotionBeyondMaxTimeStepsWarnsAndUsesTheMaximum) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t blade = add_object(scene, box_mesh({-10, -1, 0}, {10, 1, 1}, 0), "blade");
    add_dynamic(scene, blade, spin_motion({0, 0, 0}, {0, 0, 1}, 360.0), "fast");
    BuildOptions options = options_over(0.0, 1.0);
    options.motion.max_time_steps = 5;
    Warnings warnings;
    const GeometryScene geometry = build(scene, options, warnings.log());
    EXPECT_EQ(geometry.time_steps(), std::vector<unsigned>{5});
    ASSERT_EQ(warnings.items.size(), 1u);
    EXPECT_THAT(warnings.items[0], HasSubstr("instance \"fast\": 5 time steps"));
    EXPECT_THAT(warnings.items[0], HasSubstr("above the tolerances"));
}

TEST(GeometrySceneMotion, DynamicBoundsCoverTheWholePath) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t blade = add_object(scene, box_mesh({-10, -1, 0}, {10, 1, 1}, 0), "blade");
    model::FlexMotion motion = spin_motion({0, 0, 0}, {0, 0, 1}, 200.0);
    motion.location = straight_motion({5, 0, 0}, 0.0, 20.0).location;  // north at 20 m/s
    add_dynamic(scene, blade, motion, "flying rotor");
    const GeometryScene geometry = build(scene, options_over(0.0, 2.0));
    const auto trajectories =
        motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{});
    ASSERT_TRUE(trajectories[0]);
    const Bounds& b = geometry.bounds();
    for (int k = 0; k <= 2000; ++k) {
        const motion::Pose pose = trajectories[0]->pose_at(2.0 * k / 2000.0);
        for (int c = 0; c < 8; ++c) {
            const Vec3 corner{(c & 1) ? 10.0 : -10.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : 0.0};
            const Vec3 p = pose.position_m + motion::rotate(pose.orientation, corner);
            for (std::size_t i = 0; i < 3; ++i) {
                EXPECT_LE(b.lower[i], p[i]) << k;
                EXPECT_GE(b.upper[i], p[i]) << k;
            }
        }
    }
    // And not much more: the swept disk (radius √101 ≈ 10.05 m) from y = 0 to y = 40.
    EXPECT_LT(b.upper.x, 5.0 + 10.05 + 0.5);
    EXPECT_GT(b.lower.y, -10.05 - 0.5);
    EXPECT_LT(b.upper.y, 40.0 + 10.05 + 0.5);
}

TEST(GeometrySceneMotion, InstantWindowGivesOnePoseAtItsTime) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    add_dynamic(scene, box, straight_motion({0, 0, 0}, 90.0, 10.0), "car");
    const GeometryScene geometry = build(scene, options_over(3.0, 3.0));
    EXPECT_EQ(geometry.time_steps(), std::vector<unsigned>{1});
    for (const double t_s : {0.0, 3.0, 100.0}) {
        const auto hit = geometry.intersect({30.0, 0.0, 50.0}, kDown, t_s);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->distance_m, 48.0, kLocalTol_m);
    }
}

}  // namespace geometry_scene_motion_test
}  // namespace glint::scene
