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
    const double row[] = {280.0, 300.0, 290.0, 0.0, 0.0, 0.0};  // n = 1: one cell, one unused
    t.add(2, 7, 1, row);
    EXPECT_EQ(t.facets(), 1u);
    EXPECT_NEAR(t.at(2, 7, 0.2, 0.2, 30.0), 290.0, 1e-4);
    EXPECT_NEAR(t.at(2, 7, 0.9, 0.1, 90.0), 295.0, 1e-4);
    EXPECT_NEAR(t.at(2, 7, 0.0, 0.0, -5.0), 280.0, 1e-4);
    EXPECT_NEAR(t.at(2, 7, 0.0, 1.0, 500.0), 290.0, 1e-4);
    EXPECT_EQ(t.at(2, 8, 0.2, 0.2, 30.0), 0.0);
    EXPECT_EQ(t.at(3, 7, 0.2, 0.2, 30.0), 0.0);
    EXPECT_THROW(t.add(2, 7, 1, row), Error);
    const double short_row[] = {1.0};
    EXPECT_THROW(t.add(1, 1, 1, short_row), Error);
    EXPECT_THROW(FacetTemperatures({}), Error);
    EXPECT_THROW(FacetTemperatures({2.0, 1.0}), Error);
}

// A facet cut 3 times: the 9 cells of equal area; each barycentric point falls in the cell
// whose triangle holds it.
TEST(FacetTemperatures, CellsCutTheFacetIntoEqualTriangles) {
    using F = FacetTemperatures;
    EXPECT_EQ(F::cell_at(3, 0.1, 0.1), F::cell_index(3, 0, 0, false));
    EXPECT_EQ(F::cell_at(3, 0.3, 0.3), F::cell_index(3, 0, 0, true));  // above the diagonal
    EXPECT_EQ(F::cell_at(3, 0.5, 0.1), F::cell_index(3, 1, 0, false));
    EXPECT_EQ(F::cell_at(3, 0.9, 0.05), F::cell_index(3, 2, 0, false));
    EXPECT_EQ(F::cell_at(3, 0.05, 0.9), F::cell_index(3, 0, 2, false));
    EXPECT_EQ(F::cell_at(3, 1.0, 0.0), F::cell_index(3, 2, 0, false));  // the corner
    EXPECT_EQ(F::cell_at(3, 0.0, 1.0), F::cell_index(3, 0, 2, false));
    // Every cell is hit by a uniform sample of the triangle, each about 1/9 of it.
    std::vector<int> hits(F::cell_slots(3), 0);
    constexpr int kSide = 300;
    int total = 0;
    for (int a = 0; a < kSide; ++a) {
        for (int b = 0; a + b < kSide; ++b) {
            ++hits[F::cell_at(3, (a + 0.3) / kSide, (b + 0.3) / kSide)];
            ++total;
        }
    }
    int cells = 0;
    for (int h : hits) {
        if (h == 0) continue;
        ++cells;
        EXPECT_NEAR(static_cast<double>(h) / total, 1.0 / 9.0, 0.01);
    }
    EXPECT_EQ(cells, 9);
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
        const double row[] = {280.0, 320.0, 0.0, 0.0};
        temperatures->add(f.instance, f.triangle, 1, row);
        // The corners: the centroid is their mean.
        const Vec3 mean = (f.corners_m[0] + f.corners_m[1] + f.corners_m[2]) * (1.0 / 3.0);
        EXPECT_NEAR(norm(mean - f.centroid_m), 0.0, 1e-9);
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
