// SPDX-License-Identifier: Apache-2.0
// SceneTargets: named instances as tracking targets (static translation or matrix, dynamic
// trajectory, first of a repeated name, unknown names) and make_instance_trajectories.
#include "glint/motion/scene_instances.h"

#include <gtest/gtest.h>

#include "glint/test/motions.h"

namespace glint::motion {
namespace scene_instances_test {

model::Instance named(const std::string& name) {
    model::Instance instance;
    instance.name = name;
    return instance;
}

TEST(SceneTargets, StaticDynamicRepeatedAndUnknownNames) {
    model::Scene scene;
    model::Instance a = named("tower");
    a.transform.translation_m = {1.0, 2.0, 3.0};
    model::Instance b = named("sign");
    b.transform.matrix = std::array<double, 16>{0, -1, 0, 7, 1, 0, 0, 8, 0, 0, 1, 9, 0, 0, 0, 1};
    model::Instance c = named("truck");
    c.motion = std::make_shared<const model::PlatformMotion>(test::driving_east());
    model::Instance d = named("tower");  // a second "tower": the first one is the target
    d.transform.translation_m = {-5.0, -5.0, 0.0};
    scene.instances = {a, b, c, d};
    const SceneTargets targets(scene, SceneFrame(), DateTime{});
    EXPECT_EQ(targets.size(), 3u);
    EXPECT_EQ(targets.target_position_m("tower", 0.0), (Vec3{1.0, 2.0, 3.0}));
    EXPECT_EQ(targets.target_position_m("sign", 0.0), (Vec3{7.0, 8.0, 9.0}));
    const auto truck = targets.target_position_m("truck", 1.0);
    ASSERT_TRUE(truck.has_value());
    EXPECT_NEAR(truck->x, 20.0, 1e-12);  // linear between the two entries
    EXPECT_FALSE(targets.target_position_m("bus", 0.0).has_value());
}

TEST(SceneTargets, TrajectoriesAreIndexedLikeTheInstances) {
    model::Scene scene;
    model::Instance moving = named("truck");
    moving.motion = std::make_shared<const model::PlatformMotion>(test::driving_east());
    scene.instances = {named("house"), moving};
    const auto trajectories = make_instance_trajectories(scene, SceneFrame(), DateTime{});
    ASSERT_EQ(trajectories.size(), 2u);
    EXPECT_EQ(trajectories[0], nullptr);
    ASSERT_NE(trajectories[1], nullptr);
    EXPECT_NEAR(trajectories[1]->pose_at(2.0).position_m.x, 30.0, 1e-12);
}

}  // namespace scene_instances_test
}  // namespace glint::motion
