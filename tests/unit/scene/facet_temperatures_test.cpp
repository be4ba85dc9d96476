// SPDX-License-Identifier: Apache-2.0
// Tests of facet temperatures over time (glint/scene/facet_temperatures.h) and of a scene
// reporting them at its hits: linear between the times, held beyond, 0 for other facets; a
// temperature map's value wins; the static facets a material selects, with their centroids
// and normals in scene ENU.
#include "glint/scene/facet_temperatures.h"

#include <gtest/gtest.h>

#include <vector>

#include "geometry_scene_builders.h"
#include "glint/core/error.h"

namespace glint::scene {
namespace facet_temperatures_test {

using namespace glint::scene::test;

TEST(FacetTemperatures, LinearBetweenTimesHeldBeyondZeroElsewhere) {
    FacetTemperatures t({0.0, 60.0, 120.0});
    const double row[] = {280.0, 300.0, 290.0};
    t.add(2, 7, row);
    EXPECT_EQ(t.facets(), 1u);
    EXPECT_NEAR(t.at(2, 7, 30.0), 290.0, 1e-4);
    EXPECT_NEAR(t.at(2, 7, 90.0), 295.0, 1e-4);
    EXPECT_NEAR(t.at(2, 7, -5.0), 280.0, 1e-4);
    EXPECT_NEAR(t.at(2, 7, 500.0), 290.0, 1e-4);
    EXPECT_EQ(t.at(2, 8, 30.0), 0.0);
    EXPECT_EQ(t.at(3, 7, 30.0), 0.0);
    EXPECT_THROW(t.add(2, 7, row), Error);
    const double short_row[] = {1.0};
    EXPECT_THROW(t.add(1, 1, short_row), Error);
    EXPECT_THROW(FacetTemperatures({}), Error);
    EXPECT_THROW(FacetTemperatures({2.0, 1.0}), Error);
}

// A ground plane (two triangles) of material 1 and a box of material 0: the plane's facets
// are selected, face up at z 0; a ray down onto the plane reports the plane's temperature at
// its time, one onto the box none.
TEST(FacetTemperatures, TheSceneReportsThemAtItsHits) {
    model::Scene scene = scene_with_materials(2);
    add_static(scene, add_object(scene, ground_plane_mesh(100.0, 1), "ground"));
    add_static(scene, add_object(scene, box_mesh({20.0, 20.0, 0.0}, {30.0, 30.0, 10.0}, 0), "box"));
    GeometryScene geometry = build(scene);
    const auto facets = geometry.static_facets([](std::uint32_t m) { return m == 1; });
    ASSERT_EQ(facets.size(), 2u);
    for (const auto& f : facets) {
        EXPECT_EQ(f.instance, 0u);
        EXPECT_EQ(f.material, 1u);
        EXPECT_NEAR(f.normal.z, 1.0, 1e-12);
        EXPECT_NEAR(f.centroid_m.z, 0.0, 1e-9);
        EXPECT_GT(f.spawn_offset_m, 0.0);
    }
    auto temperatures = std::make_shared<FacetTemperatures>(std::vector<double>{0.0, 100.0});
    for (const auto& f : facets) {
        const double row[] = {280.0, 320.0};
        temperatures->add(f.instance, f.triangle, row);
    }
    geometry.set_facet_temperatures(temperatures);
    const auto on_ground = geometry.intersect({-10.0, -10.0, 50.0}, {0.0, 0.0, -1.0}, 25.0);
    ASSERT_TRUE(on_ground);
    EXPECT_NEAR(on_ground->temperature_k, 290.0, 1e-4);
    const auto on_box = geometry.intersect({25.0, 25.0, 50.0}, {0.0, 0.0, -1.0}, 25.0);
    ASSERT_TRUE(on_box);
    EXPECT_EQ(on_box->temperature_k, 0.0);
}

}  // namespace facet_temperatures_test
}  // namespace glint::scene
