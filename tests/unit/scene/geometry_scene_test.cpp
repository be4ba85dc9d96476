// SPDX-License-Identifier: Apache-2.0
// Tests of the Embree geometry scene against analytic answers: distances to a ground plane
// from 1 m to 700 km (double-precision clipping), hit normals, materials and indices, static
// instancing (translation, rotation orders, non-uniform and mirroring scales, 4×4 matrices),
// occluded() against intersect(), queries from many threads (on a moving scene), spawn
// origins, the empty scene, the device settings, the memory cap and every bad setting or
// scene build() refuses. Dynamic instances: geometry_scene_motion_test.cpp.
#include "glint/scene/geometry_scene.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <regex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "geometry_scene_builders.h"
#include "glint/core/error.h"
#include "glint/motion/euler.h"

namespace glint::scene {
namespace geometry_scene_test {

using namespace glint::scene::test;
using ::testing::HasSubstr;

// ---- precision and hit data -----------------------------------------------------------------

TEST(GeometryScene, GroundPlaneDistanceIsExactFromOneMetreTo700Km) {
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, ground_plane_mesh(100'000.0, 0), "ground"));
    const GeometryScene geometry = build(scene);
    // A float-only trace from 700 km would round the origin to 0.0625 m steps; clipping in
    // double leaves the float rounding of a ≈ 140 m remainder (≈ 1e-5 m). 1 mm is the budget.
    constexpr double kTol_m = 1e-3;
    for (const double height_m : {1.0, 100.0, 10'000.0, 700'000.0}) {
        const Vec3 origin{1234.5, -987.25, height_m};
        const auto hit = geometry.intersect(origin, kDown, 0.0);
        ASSERT_TRUE(hit) << height_m;
        EXPECT_NEAR(hit->distance_m, height_m, kTol_m) << height_m;
        expect_vec_near(hit->position_m, {1234.5, -987.25, 0.0}, kTol_m);
        // Oblique, 30° off nadir, aimed at a fixed ground point.
        const double zenith = 30.0 * kDeg;
        const Vec3 d =
            normalized(Vec3{std::sin(zenith) * 0.6, std::sin(zenith) * 0.8, -std::cos(zenith)});
        const Vec3 target{3000.25, -1500.5, 0.0};
        const double slant_m = height_m / std::cos(zenith);
        const auto oblique = geometry.intersect(target - d * slant_m, d, 0.0);
        ASSERT_TRUE(oblique) << height_m;
        EXPECT_NEAR(oblique->distance_m, slant_m, kTol_m) << height_m;
        expect_vec_near(oblique->position_m, target, kTol_m);
    }
    // Pointing away, or stopped short by tmax: no hit.
    EXPECT_FALSE(geometry.intersect({0.0, 0.0, 700'000.0}, kUp, 0.0));
    EXPECT_FALSE(geometry.intersect({0.0, 0.0, 700'000.0}, kDown, 0.0, 0.0, 699'999.0));
    EXPECT_TRUE(geometry.intersect({0.0, 0.0, 700'000.0}, kDown, 0.0, 0.0, 700'001.0));
    // Rays that cannot be traced hit nothing rather than reaching Embree.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(geometry.intersect({nan, 0.0, 10.0}, kDown, 0.0));
    EXPECT_FALSE(geometry.intersect({0.0, 0.0, 10.0}, {0.0, 0.0, 0.0}, 0.0));
    EXPECT_FALSE(geometry.occluded({0.0, 0.0, 10.0}, {nan, 0.0, -1.0}, 0.0));
}

TEST(GeometryScene, HitReportsNormalMaterialInstanceAndTriangle) {
    model::Scene scene = scene_with_materials(3);
    const std::size_t ground = add_object(scene, ground_plane_mesh(1000.0, 0), "ground");
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 2), "box");
    add_static(scene, ground, {}, "ground");
    const std::size_t box_instance = add_static(scene, box, {}, "box");
    const GeometryScene geometry = build(scene);
    EXPECT_EQ(geometry.instanced_triangle_count(), 2u + 12u);

    const auto top = geometry.intersect({0.25, 0.5, 100.0}, kDown, 0.0);
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->distance_m, 98.0, kLocalTol_m);
    expect_vec_near(top->normal, kUp, kNormalTol);
    EXPECT_EQ(top->material, 2u);
    EXPECT_EQ(top->instance, box_instance);
    // The triangle reported is one whose three vertices lie on the top face z = 2.
    const model::Mesh& mesh = scene.objects[box].mesh;
    ASSERT_LT(top->triangle, mesh.triangles.size());
    for (const std::uint32_t v : mesh.triangles[top->triangle]) {
        EXPECT_EQ(mesh.vertices_m[v][2], 2.0f);
    }

    const auto side = geometry.intersect({50.0, 0.3, 1.0}, {-1.0, 0.0, 0.0}, 0.0);
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->distance_m, 49.0, kLocalTol_m);
    expect_vec_near(side->normal, {1.0, 0.0, 0.0}, kNormalTol);

    const auto floor = geometry.intersect({10.0, 10.0, 100.0}, kDown, 0.0);
    ASSERT_TRUE(floor);
    EXPECT_NEAR(floor->distance_m, 100.0, kLocalTol_m);
    EXPECT_EQ(floor->material, 0u);
    EXPECT_EQ(floor->instance, 0u);
    EXPECT_LT(floor->triangle, 2u);
    expect_vec_near(floor->normal, kUp, kNormalTol);

    // The normal is the front face's, not flipped towards the ray: from below the ground.
    const auto under = geometry.intersect({10.0, 10.0, -5.0}, kUp, 0.0);
    ASSERT_TRUE(under);
    expect_vec_near(under->normal, kUp, kNormalTol);
}

// ---- static instancing ----------------------------------------------------------------------

TEST(GeometryScene, StaticInstancesPlaceOneObjectWhereTheirTransformsSay) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    // A 2 m × 6 m plate in the object's xy-plane, front +z.
    const std::size_t plate =
        add_object(scene, quad_mesh({-1, -3, 0}, {1, -3, 0}, {1, 3, 0}, {-1, 3, 0}, 0), "plate");
    // A slope z = x over [0, 1]², front (−1, 0, 1)/√2.
    const std::size_t slope =
        add_object(scene, quad_mesh({0, 0, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}, 0), "slope");

    const std::size_t moved = add_static(scene, box, translated({100, 0, 0}), "moved");
    model::StaticTransform xyz;  // R = Rz(90°) · Rx(90°): front +z → +x, plate y → z
    xyz.rotation_rad = {90 * kDeg, 0.0, 90 * kDeg};
    xyz.rotation_order = "xyz";
    xyz.translation_m = {300, 0, 0};
    const std::size_t xyz_instance = add_static(scene, plate, xyz, "xyz");
    model::StaticTransform zyx = xyz;  // R = Rx(90°) · Rz(90°): front +z → −y, plate y → −x
    zyx.rotation_order = "zyx";
    zyx.translation_m = {0, 300, 0};
    const std::size_t zyx_instance = add_static(scene, plate, zyx, "zyx");
    model::StaticTransform stretched;  // scale (2, 1, 1): slope z = x/2, front ∝ (−1, 0, 2)
    stretched.scale = {2.0, 1.0, 1.0};
    stretched.translation_m = {0, -300, 0};
    const std::size_t stretched_instance = add_static(scene, slope, stretched, "stretched");
    model::StaticTransform tall;  // scale (1, 1, 10): top at z = 20
    tall.scale = {1.0, 1.0, 10.0};
    tall.translation_m = {-300, 0, 0};
    add_static(scene, box, tall, "tall");
    model::StaticTransform flipped;  // 4×4: Rx(180°) then y − 600: box hangs in z ∈ [−2, 0]
    flipped.matrix = std::array<double, 16>{1, 0, 0, 0, 0, -1, 0, -600, 0, 0, -1, 0, 0, 0, 0, 1};
    const std::size_t flipped_instance = add_static(scene, box, flipped, "flipped");
    model::StaticTransform mirrored;  // scale z by −1: also z ∈ [−2, 0], outside stays outside
    mirrored.scale = {1.0, 1.0, -1.0};
    mirrored.translation_m = {600, 0, 0};
    const std::size_t mirrored_instance = add_static(scene, box, mirrored, "mirrored");
    const GeometryScene geometry = build(scene);

    auto hit = geometry.intersect({100.5, 0.5, 50.0}, kDown, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, moved);
    EXPECT_NEAR(hit->distance_m, 48.0, kLocalTol_m);
    EXPECT_FALSE(geometry.intersect({0.5, 0.5, 50.0}, kDown, 0.0));  // nothing at the origin

    // "xyz": the plate stands in the plane x = 300, 2 m wide in y, 6 m tall in z, facing +x.
    hit = geometry.intersect({350.0, 0.0, 2.5}, {-1, 0, 0}, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, xyz_instance);
    EXPECT_NEAR(hit->distance_m, 50.0, kLocalTol_m);
    expect_vec_near(hit->normal, {1, 0, 0}, kNormalTol);
    EXPECT_FALSE(geometry.intersect({350.0, 2.5, 0.0}, {-1, 0, 0}, 0.0));
    // "zyx": in the plane y = 300, 6 m wide in x, 2 m tall, facing −y.
    hit = geometry.intersect({2.5, 250.0, 0.0}, {0, 1, 0}, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, zyx_instance);
    EXPECT_NEAR(hit->distance_m, 50.0, kLocalTol_m);
    expect_vec_near(hit->normal, {0, -1, 0}, kNormalTol);
    EXPECT_FALSE(geometry.intersect({0.0, 250.0, 2.5}, {0, 1, 0}, 0.0));

    // Non-uniform scale: the surface z = x/2 and its true normal (inverse transpose).
    hit = geometry.intersect({1.0, -299.5, 50.0}, kDown, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, stretched_instance);
    EXPECT_NEAR(hit->distance_m, 49.5, kLocalTol_m);
    expect_vec_near(hit->normal, normalized(Vec3{-1, 0, 2}), kNormalTol);
    hit = geometry.intersect({-300.0, 0.0, 50.0}, kDown, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->distance_m, 30.0, kLocalTol_m);

    // The 4×4 matrix: the old top (z = 2) is now the bottom at z = −2, facing −z.
    hit = geometry.intersect({0.0, -600.0, -50.0}, kUp, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, flipped_instance);
    EXPECT_NEAR(hit->distance_m, 48.0, kLocalTol_m);
    expect_vec_near(hit->normal, {0, 0, -1}, kNormalTol);
    // Mirroring: the faces keep pointing out of the box (−z below, +z above).
    hit = geometry.intersect({600.0, 0.0, -50.0}, kUp, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, mirrored_instance);
    EXPECT_NEAR(hit->distance_m, 48.0, kLocalTol_m);
    expect_vec_near(hit->normal, {0, 0, -1}, kNormalTol);
    hit = geometry.intersect({600.0, 0.0, 50.0}, kDown, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->distance_m, 50.0, kLocalTol_m);
    expect_vec_near(hit->normal, {0, 0, 1}, kNormalTol);

    // Bounds: the union of the instances' boxes.
    EXPECT_NEAR(geometry.bounds().lower.x, -301.0, 1e-9);
    EXPECT_NEAR(geometry.bounds().upper.x, 601.0, 1e-9);
    EXPECT_NEAR(geometry.bounds().lower.y, -601.0, 1e-9);
    EXPECT_NEAR(geometry.bounds().upper.y, 300.0, 1e-9);
    EXPECT_NEAR(geometry.bounds().lower.z, -3.0, 1e-9);
    EXPECT_NEAR(geometry.bounds().upper.z, 20.0, 1e-9);
}

// ---- queries --------------------------------------------------------------------------------

TEST(GeometryScene, OccludedAgreesWithIntersect) {
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, ground_plane_mesh(200.0, 0), "ground"));
    const std::size_t box = add_object(scene, box_mesh({-3, -2, 0}, {3, 2, 8}, 0), "box");
    add_static(scene, box, translated({10, 5, 0}));
    add_static(scene, add_object(scene, sphere_mesh(4.0, 24, 12, 0), "ball"),
               translated({-10, -5, 6}));
    add_dynamic(scene, box, straight_motion({0, -20, 0}, 0.0, 4.0), "truck");
    const GeometryScene geometry = build(scene, options_over(0.0, 5.0));
    int hits = 0, misses = 0;
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 10; ++j) {
            const Vec3 origin{-30.0 + 1.5 * i, -25.0 + 5.0 * j, 2.0 + 0.7 * j};
            const double a = 0.37 * i + 1.1 * j;
            const Vec3 d = normalized(Vec3{std::cos(a), std::sin(a), -0.6 + 0.13 * (i % 10)});
            const double t_s = 0.125 * ((i + j) % 40);
            const auto hit = geometry.intersect(origin, d, t_s);
            EXPECT_EQ(geometry.occluded(origin, d, t_s), hit.has_value()) << i << " " << j;
            if (!hit) {
                ++misses;
                continue;
            }
            ++hits;
            EXPECT_TRUE(geometry.occluded(origin, d, t_s, 0.0, hit->distance_m + 1e-3));
            EXPECT_FALSE(geometry.occluded(origin, d, t_s, 0.0, hit->distance_m - 1e-3));
            EXPECT_FALSE(geometry.intersect(origin, d, t_s, 0.0, hit->distance_m - 1e-3));
        }
    }
    EXPECT_GT(hits, 50);  // the sample exercises both outcomes
    EXPECT_GT(misses, 50);
}

/// Every field of two hits, bit for bit.
void expect_same_hit(const std::optional<RayHit>& a, const std::optional<RayHit>& b,
                     const std::string& where) {
    ASSERT_EQ(a.has_value(), b.has_value()) << where;
    if (!a) return;
    EXPECT_EQ(a->distance_m, b->distance_m) << where;
    EXPECT_EQ(a->position_m.x, b->position_m.x) << where;
    EXPECT_EQ(a->position_m.y, b->position_m.y) << where;
    EXPECT_EQ(a->position_m.z, b->position_m.z) << where;
    EXPECT_EQ(a->normal.x, b->normal.x) << where;
    EXPECT_EQ(a->normal.y, b->normal.y) << where;
    EXPECT_EQ(a->normal.z, b->normal.z) << where;
    EXPECT_EQ(a->material, b->material) << where;
    EXPECT_EQ(a->instance, b->instance) << where;
    EXPECT_EQ(a->triangle, b->triangle) << where;
}

/// Packets of `size` rays from `rays`, each answer compared with intersect()'s and
/// occluded()'s.
void expect_packets_match_single_rays(const GeometryScene& geometry,
                                      const std::vector<PacketRay>& rays, std::size_t size) {
    std::vector<std::optional<RayHit>> hits(size);
    std::array<bool, kPacketSize> blocked{};
    for (std::size_t first = 0; first < rays.size(); first += size) {
        const std::size_t count = std::min(size, rays.size() - first);
        const std::span<const PacketRay> packet(rays.data() + first, count);
        geometry.intersect_packet(packet, std::span(hits).first(count));
        geometry.occluded_packet(packet, std::span(blocked).first(count));
        for (std::size_t k = 0; k < count; ++k) {
            const PacketRay& r = packet[k];
            const std::string where =
                "ray " + std::to_string(first + k) + " in packets of " + std::to_string(size);
            expect_same_hit(
                hits[k], geometry.intersect(r.origin_m, r.direction, r.time_s, r.tmin_m, r.tmax_m),
                where);
            EXPECT_EQ(blocked[k],
                      geometry.occluded(r.origin_m, r.direction, r.time_s, r.tmin_m, r.tmax_m))
                << where;
        }
    }
}

TEST(GeometryScene, PacketQueriesGiveTheBitsOfSingleQueries) {
    // Static scene: Embree's packet kernel must give exactly the single-ray answers (the
    // renderer's bits depend on it). Coherent camera rays from 3 km and 700 km, incoherent
    // rays from near the surfaces with finite intervals, rays that miss the scene box, and
    // partial packets (sizes 1, 5, 16).
    model::Scene scene = scene_with_materials(3);
    add_static(scene, add_object(scene, ground_plane_mesh(400.0, 0), "ground"));
    const std::size_t box = add_object(scene, box_mesh({-3, -2, 0}, {3, 2, 8}, 1), "box");
    for (int i = 0; i < 12; ++i) {
        model::StaticTransform t = translated({-60.0 + 11.0 * i, 7.0 * (i % 5) - 14.0, 0.0});
        t.rotation_rad = {0.0, 0.0, 0.3 * i};
        t.scale = {1.0 + 0.1 * i, 1.0, 0.5 + 0.2 * (i % 3)};
        add_static(scene, box, t);
    }
    add_static(scene, add_object(scene, sphere_mesh(6.0, 24, 12, 2), "ball"),
               translated({20, -30, 9}));
    const GeometryScene geometry = build(scene);
    std::vector<PacketRay> rays;
    for (const double height_m : {3000.0, 700'000.0}) {
        for (int y = 0; y < 24; ++y) {
            for (int x = 0; x < 32; ++x) {
                const Vec3 d = normalized(Vec3{(x - 15.5) * 0.0015, (y - 11.5) * 0.0015, -1.0});
                rays.push_back({{3.0, -2.0, height_m}, d, 0.0});
            }
        }
    }
    for (int k = 0; k < 400; ++k) {
        const double a = 0.61 * k;
        const Vec3 origin{-70.0 + 0.35 * k, 40.0 * std::sin(0.3 * k), 0.5 + (k % 9)};
        const Vec3 d = normalized(Vec3{std::cos(a), std::sin(a), -0.7 + 0.09 * (k % 17)});
        rays.push_back({origin, d, 0.0, 0.01 * (k % 3),
                        k % 4 == 0 ? 25.0 : std::numeric_limits<double>::infinity()});
    }
    rays.push_back({{1e6, 0.0, 10.0}, kUp, 0.0});              // outside the box, away
    rays.push_back({{0.0, 0.0, 10.0}, kDown, 0.0, 0.0, 5.0});  // stopped short
    for (const std::size_t size : {1u, 5u, 16u}) {
        expect_packets_match_single_rays(geometry, rays, size);
    }
    std::size_t hits = 0;
    for (const PacketRay& r : rays)
        hits += geometry.intersect(r.origin_m, r.direction, 0.0).has_value();
    EXPECT_GT(hits, rays.size() / 2);  // both outcomes are exercised
    EXPECT_LT(hits, rays.size());

    // More rays than a packet holds, or a result span of another size: internal errors.
    std::vector<std::optional<RayHit>> out(17);
    EXPECT_EQ(
        error_of([&] { geometry.intersect_packet(std::span(rays).first(17), out); }).message(),
        "internal error: packet query of 17 rays into 17 results (at most 16)");
    EXPECT_EQ(error_of([&] {
                  geometry.intersect_packet(std::span(rays).first(4), std::span(out).first(3));
              }).category(),
              ErrorCategory::internal);
    std::array<bool, 17> flags{};
    EXPECT_EQ(
        error_of([&] { geometry.occluded_packet(std::span(rays).first(17), flags); }).message(),
        "internal error: packet query of 17 rays into 17 results (at most 16)");
}

/// A ground plane under a 20 m blade spinning at 90°/s about (0, 0, 5), over [0, 1] s.
GeometryScene rotor_scene() {
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, ground_plane_mesh(200.0, 0), "ground"));
    const std::size_t blade = add_object(scene, box_mesh({-10, -1, 0}, {10, 1, 1}, 0), "blade");
    add_dynamic(scene, blade, spin_motion({0, 0, 5}, {0, 0, 1}, 90.0), "rotor");
    return build(scene, options_over(0.0, 1.0));
}

TEST(GeometryScene, PacketQueriesOnAMovingSceneGiveTheBitsOfSingleQueries) {
    const GeometryScene geometry = rotor_scene();
    std::vector<PacketRay> rays;
    for (int k = 0; k < 320; ++k) {
        const double a = 0.61 * k;
        rays.push_back({{8.0 * std::cos(a), 8.0 * std::sin(a), 30.0}, kDown, (k % 97) / 96.0});
    }
    expect_packets_match_single_rays(geometry, rays, 16);
}

TEST(GeometryScene, QueriesFromManyThreadsMatchOneThread) {
    const GeometryScene geometry = rotor_scene();
    const auto trace = [&geometry](int k) {
        const double a = 0.61 * k;
        const Vec3 origin{8.0 * std::cos(a), 8.0 * std::sin(a), 30.0};
        const auto hit = geometry.intersect(origin, kDown, (k % 97) / 96.0);
        return hit ? hit->distance_m : -1.0;
    };
    constexpr int kRays = 4000;
    std::vector<double> expected(kRays);
    for (int k = 0; k < kRays; ++k) expected[k] = trace(k);
    std::vector<std::vector<double>> got(4, std::vector<double>(kRays));
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < got.size(); ++t) {
        threads.emplace_back([&, t] {
            for (int k = 0; k < kRays; ++k) got[t][k] = trace(k);
        });
    }
    for (auto& thread : threads) thread.join();
    for (const auto& results : got) EXPECT_EQ(results, expected);
    // Both the blade (top at z = 6, 24 m down) and the ground (30 m down) are hit.
    EXPECT_GT(std::count_if(expected.begin(), expected.end(),
                            [](double d) { return std::abs(d - 30.0) < 1e-4; }),
              0);
    EXPECT_GT(std::count_if(expected.begin(), expected.end(),
                            [](double d) { return std::abs(d - 24.0) < 1e-4; }),
              0);
}

TEST(GeometryScene, SpawnOriginLeavesTheSurface) {
    // A tilted 2 km plate, 40 km from the origin, hit at grazing and steep angles.
    model::Scene scene = scene_with_materials(1);
    const std::size_t plate = add_object(
        scene, quad_mesh({-1000, -1000, 0}, {1000, -1000, 0}, {1000, 1000, 0}, {-1000, 1000, 0}, 0),
        "plate");
    model::StaticTransform far;
    far.rotation_rad = {10 * kDeg, -20 * kDeg, 30 * kDeg};
    far.translation_m = {40'000.0, -25'000.0, 350.0};
    add_static(scene, plate, far);
    const GeometryScene geometry = build(scene);
    const motion::Mat3 r =
        motion::euler_to_matrix(motion::to_vec3(far.rotation_rad), motion::EulerOrder::xyz);
    int hits = 0;
    for (int i = 0; i < 200; ++i) {
        const double elevation = (1.0 + 0.44 * i) * kDeg;  // 1° to 89° below the horizon
        const double azimuth = 2.4 * i;
        const Vec3 d{std::cos(elevation) * std::cos(azimuth),
                     std::cos(elevation) * std::sin(azimuth), -std::sin(elevation)};
        // A point on the plate, up to 900 m from its centre.
        const Vec3 target = motion::to_vec3(far.translation_m) +
                            r * Vec3{(i % 7) * 150.0 - 450.0, (i % 5) * 200.0 - 400.0, 0.0};
        const auto hit = geometry.intersect(target - d * 5000.0, d, 0.0);
        if (!hit) continue;
        ++hits;
        const Vec3 n = hit->normal;
        const Vec3 reflected = d - n * (2.0 * dot(d, n));
        const Vec3 up = geometry.spawn_origin(*hit, reflected);
        EXPECT_NEAR(dot(up - hit->position_m, n) * (dot(reflected, n) > 0 ? 1 : -1),
                    hit->spawn_offset_m, 1e-9);
        // Nothing else is in the scene: leaving the plate must find nothing.
        EXPECT_FALSE(geometry.intersect(up, reflected, 0.0)) << i;
        EXPECT_FALSE(geometry.occluded(up, reflected, 0.0)) << i;
        const Vec3 through = geometry.spawn_origin(*hit, d);
        EXPECT_FALSE(geometry.intersect(through, d, 0.0)) << i;
    }
    EXPECT_EQ(hits, 200);
}

TEST(GeometryScene, EmptySceneMissesEverything) {
    model::Scene scene = scene_with_materials(1);
    add_object(scene, box_mesh({-1, -1, -1}, {1, 1, 1}, 0), "unused");  // no instance
    const GeometryScene geometry = build(scene);
    EXPECT_TRUE(geometry.bounds().empty());
    EXPECT_EQ(geometry.instanced_triangle_count(), 0u);
    EXPECT_TRUE(geometry.time_steps().empty());
    EXPECT_FALSE(geometry.intersect({0, 0, 10}, kDown, 0.0));
    EXPECT_FALSE(geometry.intersect({0, 0, 0}, kDown, 0.0));
    EXPECT_FALSE(geometry.occluded({0, 0, 10}, kDown, 0.0));
}

TEST(GeometryScene, MovedSceneKeepsWorking) {
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, ground_plane_mesh(100.0, 0), "ground"));
    GeometryScene first = build(scene);
    GeometryScene second = std::move(first);
    first = build(scene_with_materials(0));
    EXPECT_TRUE(second.intersect({0, 0, 5}, kDown, 0.0));
    EXPECT_FALSE(first.intersect({0, 0, 5}, kDown, 0.0));
}

// ---- device, memory cap and bad settings ----------------------------------------------------

TEST(GeometryScene, DeviceSettingsReachEmbree) {
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box"));
    BuildOptions options;
    options.device.threads = 1;
    options.device.isa = "SSE4.2";
    const GeometryScene geometry = build(scene, options);
    EXPECT_EQ(geometry.device().config, "threads=1,isa=sse4.2");
    EXPECT_EQ(geometry.device().threads, 1u);
    EXPECT_TRUE(std::regex_match(geometry.device().embree_version, std::regex(R"(3\.\d+\.\d+)")))
        << geometry.device().embree_version;
    const auto hit = geometry.intersect({0, 0, 10}, kDown, 0.0);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->distance_m, 8.0, kLocalTol_m);
    EXPECT_EQ(build(scene).device().config, "");
}

TEST(GeometryScene, MemoryCapIsEnforced) {
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, sphere_mesh(10.0, 500, 100, 0), "ball"));  // 99 000 tri.
    ASSERT_EQ(scene.objects[0].mesh.triangles.size(), 99'000u);
    BuildOptions options;
    options.device.max_memory_bytes = 1024;
    const Error e = error_of([&] { build(scene, options); });
    // glint::ErrorCategory has no "resource" category; runtime is the closest.
    EXPECT_EQ(e.category(), ErrorCategory::runtime);
    EXPECT_THAT(e.message(), HasSubstr("the scene needs more than the 1 KiB allowed by "
                                       "--max-memory (Embree asked for "));
    EXPECT_THAT(e.message(), HasSubstr("building object \"ball\""));

    options.device.max_memory_bytes = std::uint64_t{256} << 20;  // ample
    const GeometryScene geometry = build(scene, options);
    EXPECT_TRUE(geometry.intersect({0, 0, 100}, kDown, 0.0));
}

TEST(GeometryScene, BadSettingsAreUsageErrors) {
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box"));
    const auto expect_usage = [&](const BuildOptions& options, const std::string& text) {
        const Error e = error_of([&] { build(scene, options); });
        EXPECT_EQ(e.category(), ErrorCategory::usage) << e.what();
        EXPECT_THAT(e.message(), HasSubstr(text));
    };
    BuildOptions options;
    options.device.isa = "avx3";
    expect_usage(options,
                 "unknown Embree ISA \"avx3\", expected one of sse2, sse4.2, avx, avx2, "
                 "avx512");
    options = {};
    options.motion.min_time_steps = 1;
    expect_usage(options, "min_time_steps is 1, expected at least 2");
    options = {};
    options.motion.max_time_steps = 130;
    expect_usage(options, "max_time_steps is 130, expected 2 (min_time_steps) to 129");
    options = {};
    options.motion.max_step_rotation_deg = 0.0;
    expect_usage(options, "max_step_rotation_deg is 0");
    options = options_over(5.0, 4.0);
    expect_usage(options, "the time window ends (4 s) before it begins (5 s)");
}

TEST(GeometryScene, BadScenesAreInputErrors) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    add_dynamic(scene, box, straight_motion({0, 0, 0}, 0.0, 1.0), "car");
    // A dynamic instance without its trajectory.
    Error e = error_of([&] { GeometryScene::build(scene, {}, {}); });
    EXPECT_EQ(e.category(), ErrorCategory::input);
    EXPECT_EQ(e.message(), "dynamic instance \"car\" has no trajectory");
    EXPECT_EQ(e.context().file, "test.yaml");
    EXPECT_EQ(e.context().line, 100);

    // A material index out of range.
    model::Scene bad = scene_with_materials(1);
    add_static(bad, add_object(bad, box_mesh({-1, -1, 0}, {1, 1, 2}, 3), "odd"));
    e = error_of([&] { build(bad); });
    EXPECT_EQ(e.category(), ErrorCategory::input);
    EXPECT_THAT(e.message(), HasSubstr("object \"odd\": triangle 0 has material index 3, out of "
                                       "range (1 materials)"));

    // A singular static transform.
    model::Scene flat = scene_with_materials(1);
    model::StaticTransform squash;
    squash.matrix = std::array<double, 16>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
    add_static(flat, add_object(flat, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box"), squash);
    e = error_of([&] { build(flat); });
    EXPECT_EQ(e.category(), ErrorCategory::input);
    EXPECT_THAT(e.message(), HasSubstr("singular"));
}

TEST(GeometryScene, InstanceTrajectoriesFollowTheInstances) {
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-1, -1, 0}, {1, 1, 2}, 0), "box");
    add_static(scene, box);
    add_dynamic(scene, box, straight_motion({0, 0, 0}, 90.0, 2.0), "car");
    auto trajectories = motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{});
    ASSERT_EQ(trajectories.size(), 2u);
    EXPECT_FALSE(trajectories[0]);
    ASSERT_TRUE(trajectories[1]);
    expect_vec_near(trajectories[1]->pose_at(3.0).position_m, {6.0, 0.0, 0.0}, 1e-9);

    // A motion with neither kind is refused at the instance.
    scene.instances[1].motion = std::make_shared<const model::PlatformMotion>();
    const Error e = error_of(
        [&] { motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{}); });
    EXPECT_EQ(e.category(), ErrorCategory::input);
    EXPECT_THAT(e.message(), HasSubstr("instance \"car\": no motion was read"));
    EXPECT_EQ(e.context().file, "test.yaml");
    EXPECT_EQ(e.context().line, 101);
}

}  // namespace geometry_scene_test
}  // namespace glint::scene
