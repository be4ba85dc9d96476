// SPDX-License-Identifier: Apache-2.0
// A scene's motion over a run (glint/scene/scene_motion.h): a scene where nothing moves says
// so and builds the same geometry whatever the window; a moving box is where its trajectory
// puts it in the window built; a scene other than the one the motion was made for is refused.
#include "glint/scene/scene_motion.h"

#include <gtest/gtest.h>

#include <string>

#include "geometry_scene_builders.h"
#include "glint/core/error.h"
#include "glint/test/errors.h"

namespace glint::scene {
namespace scene_motion_test {

using namespace glint::scene::test;

TEST(SceneMotion, AStaticSceneDoesNotMove) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    add_static(scene, box, translated({5.0, 0.0, 0.0}));
    const SceneMotion motion = SceneMotion::make(scene, motion::SceneFrame(), DateTime{});
    EXPECT_FALSE(motion.moves());
    const GeometryScene geometry = motion.build(scene, options_over(0.0, 10.0));
    EXPECT_TRUE(geometry.intersect({5.5, 0.0, 50.0}, kDown, 0.0));
    EXPECT_TRUE(geometry.intersect({5.5, 0.0, 50.0}, kDown, 10.0));
}

TEST(SceneMotion, AMovingBoxIsWhereItsTrajectoryPutsIt) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    add_static(scene, box, translated({-50.0, 0.0, 0.0}));
    add_dynamic(scene, box, straight_motion({0, 0, 0}, 90.0, 10.0), "car");  // east, 10 m/s
    const SceneMotion motion = SceneMotion::make(scene, motion::SceneFrame(), DateTime{});
    EXPECT_TRUE(motion.moves());
    const GeometryScene geometry = motion.build(scene, options_over(20.0, 30.0));
    for (const double t_s : {20.0, 25.0, 30.0}) {
        const auto hit = geometry.intersect({10.0 * t_s + 0.5, 0.0, 50.0}, kDown, t_s);
        ASSERT_TRUE(hit) << t_s;
        EXPECT_NEAR(hit->distance_m, 48.0, kLocalTol_m) << t_s;
    }
    EXPECT_FALSE(geometry.intersect({0.5, 0.0, 50.0}, kDown, 20.0));  // left its start
}

// static_only (THERM's shadow scene): the moving box is left out, so no ray meets it and
// static_facets() lists only the static box, whose instance keeps its index (1 after the car).
TEST(SceneMotion, StaticOnlyLeavesTheMovingInstancesOut) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    add_dynamic(scene, box, straight_motion({0, 0, 0}, 90.0, 10.0), "car");
    add_static(scene, box, translated({-50.0, 0.0, 0.0}));
    const SceneMotion motion = SceneMotion::make(scene, motion::SceneFrame(), DateTime{});
    BuildOptions options = options_over(0.0, 0.0);
    options.static_only = true;
    const GeometryScene geometry = motion.build(scene, options);
    EXPECT_FALSE(geometry.intersect({0.5, 0.0, 50.0}, kDown, 0.0));
    EXPECT_FALSE(geometry.occluded({0.5, 0.0, 50.0}, kDown, 0.0));
    EXPECT_TRUE(geometry.intersect({-49.5, 0.0, 50.0}, kDown, 0.0));
    EXPECT_EQ(geometry.instanced_triangle_count(), 12u);
    const auto facets = geometry.static_facets([](std::uint32_t) { return true; });
    ASSERT_EQ(facets.size(), 12u);
    for (const auto& f : facets) EXPECT_EQ(f.instance, 1u);
    // Without static_only the car is there.
    EXPECT_TRUE(
        motion.build(scene, options_over(0.0, 0.0)).intersect({0.5, 0.0, 50.0}, kDown, 0.0));
}

TEST(SceneMotion, RefusesAnotherScene) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    add_static(scene, box, translated({0.0, 0.0, 0.0}));
    const SceneMotion motion = SceneMotion::make(scene, motion::SceneFrame(), DateTime{});
    add_static(scene, box, translated({9.0, 0.0, 0.0}));
    EXPECT_EQ(glint::test::error_text([&] { (void)motion.build(scene, options_over(0.0, 1.0)); }),
              "internal error: the scene has 2 instances, its motion was made for 1");
}

}  // namespace scene_motion_test
}  // namespace glint::scene
