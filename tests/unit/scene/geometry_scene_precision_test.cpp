// SPDX-License-Identifier: Apache-2.0
// Precision of the geometry scene at every scale: a ground plate seen from 1 km to
// 36,000 km with a small box far above it (which makes Embree's frame start kilometres up,
// so the float camera rays run tens of kilometres before the hit) casts no false shadow;
// a plate in UTM-sized coordinates behaves as one at the origin; and rays leaving a surface
// (reflected at grazing angles, transmitted through thin slabs, off instanced objects far
// from the origin, off a moving object) never hit the surface they leave. Every query kind
// is used: intersect, occluded and their packet forms.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "geometry_scene_builders.h"
#include "glint/motion/euler.h"
#include "glint/scene/geometry_scene.h"

namespace glint::scene {
namespace geometry_scene_precision_test {

using namespace glint::scene::test;

/// The sun of the false-shadow scene: 26° above the horizon is low enough that a shadow ray
/// starting a little under the plate crosses it within a few millimetres.
const Vec3 kSun = normalized(Vec3{-0.3, -0.2, 0.9});

/// A hit position is where the double ray crosses the triangle's plane: double rounding of
/// coordinates up to 4e7 m is ~1e-8 m; 1e-6 m leaves room for the float vertices' plane.
constexpr double kPosition_m = 1e-6;

/// The plate (2 km, at z = 0) and, unless `box_altitude_m` is 0, a 2 m box at
/// (9 km, 9 km, box_altitude_m), far outside any view of the plate.
GeometryScene plate_and_far_box(double box_altitude_m) {
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, ground_plane_mesh(2000.0, 0), "plate"));
    if (box_altitude_m > 0.0) {
        add_static(scene, add_object(scene,
                                     box_mesh({9000, 9000, box_altitude_m},
                                              {9002, 9002, box_altitude_m + 2.0}, 0),
                                     "box"));
    }
    return build(scene);
}

/// The ground points of a 200 × 200 view of the plate (1.8 km across, off-grid numbers).
std::vector<Vec3> ground_grid() {
    std::vector<Vec3> points;
    for (int i = 0; i < 200; ++i) {
        for (int j = 0; j < 200; ++j) {
            points.push_back({-900.0 + 9.0 * i + 0.123, -900.0 + 9.0 * j + 0.456, 0.0});
        }
    }
    return points;
}

struct ShadowCount {
    int missed = 0;  ///< camera rays that did not hit the plate where they aimed
    int false_shadows = 0;
    double worst_position_m = 0.0;
};

/// Looks at every grid point from `camera` (single queries), then asks whether the sun is
/// seen from the hit (single and packet queries must agree).
ShadowCount look_from(const GeometryScene& geometry, const Vec3& camera) {
    ShadowCount count;
    const std::vector<Vec3> targets = ground_grid();
    std::vector<PacketRay> shadow_rays;
    std::vector<PacketRay> camera_rays;
    for (const Vec3& target : targets) {
        const Vec3 d = normalized(target - camera);
        camera_rays.push_back({camera, d, 0.0});
        const auto hit = geometry.intersect(camera, d, 0.0);
        if (!hit || hit->instance != 0) {
            ++count.missed;
            continue;
        }
        count.worst_position_m = std::max(count.worst_position_m, norm(hit->position_m - target));
        const Vec3 origin = geometry.spawn_origin(*hit, kSun);
        const bool blocked = geometry.occluded(origin, kSun, 0.0);
        if (blocked || geometry.intersect(origin, kSun, 0.0)) ++count.false_shadows;
        shadow_rays.push_back({origin, kSun, 0.0});
    }
    // The packet forms see the same.
    for (std::size_t at = 0; at < camera_rays.size(); at += kPacketSize) {
        const std::size_t n = std::min(kPacketSize, camera_rays.size() - at);
        std::array<std::optional<RayHit>, kPacketSize> hits;
        geometry.intersect_packet(std::span(camera_rays).subspan(at, n), std::span(hits).first(n));
        for (std::size_t k = 0; k < n; ++k) {
            if (!hits[k] || hits[k]->instance != 0) ++count.missed;
        }
    }
    for (std::size_t at = 0; at < shadow_rays.size(); at += kPacketSize) {
        const std::size_t n = std::min(kPacketSize, shadow_rays.size() - at);
        std::array<bool, kPacketSize> blocked{};
        geometry.occluded_packet(std::span(shadow_rays).subspan(at, n),
                                 std::span(blocked).first(n));
        for (std::size_t k = 0; k < n; ++k) count.false_shadows += blocked[k] ? 1 : 0;
    }
    return count;
}

TEST(GeometryScenePrecision, FarGeometryCastsNoFalseShadowsFromAnyAltitude) {
    // The reproduction: before hit points were rebuilt from the triangle, the view from
    // 550 km with the box 50 km up found 85 of these 40,000 points in false shadow.
    for (const double box_altitude_m : {50'000.0, 100'000.0}) {
        const GeometryScene geometry = plate_and_far_box(box_altitude_m);
        for (const double sensor_altitude_m : {1'000.0, 550'000.0, 705'000.0, 36'000'000.0}) {
            const Vec3 camera{3000.0, 1234.5, sensor_altitude_m};
            const ShadowCount count = look_from(geometry, camera);
            const std::string where = "box at " + std::to_string(box_altitude_m) +
                                      " m, sensor at " + std::to_string(sensor_altitude_m) + " m";
            EXPECT_EQ(count.missed, 0) << where;
            EXPECT_EQ(count.false_shadows, 0) << where;
            EXPECT_LT(count.worst_position_m, kPosition_m) << where;
        }
    }
}

TEST(GeometryScenePrecision, TheFarBoxStillCastsItsShadow) {
    // The fix must not make shadow rays blind: from under the box, looking at it, it blocks.
    const GeometryScene geometry = plate_and_far_box(50'000.0);
    const Vec3 below{9001.0, 9001.0, 0.0};
    const auto hit = geometry.intersect({9001.0, 9001.0, 10.0}, {0.0, 0.0, -1.0}, 0.0);
    ASSERT_FALSE(hit);  // the plate ends at 1 km; nothing under the box
    EXPECT_TRUE(geometry.occluded(below, {0.0, 0.0, 1.0}, 0.0));
    EXPECT_FALSE(geometry.occluded(below, {0.0, 0.0, 1.0}, 0.0, 0.0, 49'999.0));
}

/// A ground-plane primitive of side `size_m` centred at `center`.
model::Mesh plate_at(const Vec3& center, double size_m) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::ground_plane;
    p.size_m = size_m;
    p.center_m = motion::to_array(center);
    return primitive_mesh(p, 0);
}

TEST(GeometryScenePrecision, UtmSizedCoordinatesWorkAsAtTheOrigin) {
    // The same plate with an 8 m tall box on it, once at the origin and once with its vertices at
    // UTM-like coordinates (a DIRSIG scene in easting/northing), and once placed there by an
    // instance translation instead. The views must agree to the position tolerance, the
    // box must shade the same ground, and no surface may shade itself.
    const Vec3 utm{500'000.0, 4'000'000.0, 0.0};
    struct Case {
        std::string name;
        Vec3 shift;
        bool by_instance;
    };
    const std::vector<Case> cases = {
        {"origin", {}, false}, {"vertices", utm, false}, {"instance", utm, true}};
    std::vector<std::vector<int>> shadows(cases.size());
    std::vector<double> largest_offset_m(cases.size(), 0.0);
    for (std::size_t c = 0; c < cases.size(); ++c) {
        model::Scene scene = scene_with_materials(1);
        const Vec3 vertex_shift = cases[c].by_instance ? Vec3{} : cases[c].shift;
        const model::StaticTransform placed =
            cases[c].by_instance ? translated(cases[c].shift) : model::StaticTransform{};
        add_static(scene, add_object(scene, plate_at(vertex_shift, 2000.0), "plate"), placed);
        add_static(
            scene,
            add_object(scene,
                       box_mesh(vertex_shift + Vec3{10, 20, 0}, vertex_shift + Vec3{12, 22, 8}, 0),
                       "box"),
            placed);
        const GeometryScene geometry = build(scene);
        const Vec3 camera = cases[c].shift + Vec3{50.0, -30.0, 700'000.0};
        for (int i = 0; i < 60; ++i) {
            for (int j = 0; j < 60; ++j) {
                const Vec3 target = cases[c].shift + Vec3{-19.9 + 0.7 * i, -9.7 + 0.7 * j, 0.0};
                const auto hit = geometry.intersect(camera, normalized(target - camera), 0.0);
                ASSERT_TRUE(hit) << cases[c].name;
                // The box or the plate: either way on the line of sight.
                const Vec3 along = hit->position_m - camera;
                EXPECT_LT(norm(cross(normalized(along), normalized(target - camera))) * norm(along),
                          kPosition_m)
                    << cases[c].name;
                largest_offset_m[c] = std::max(largest_offset_m[c], hit->spawn_offset_m);
                const Vec3 origin = geometry.spawn_origin(*hit, kSun);
                const bool shaded = geometry.occluded(origin, kSun, 0.0);
                // A box top never shades itself; a point on the plate is shaded only by the
                // box (found by intersect too).
                if (hit->instance == 1) {
                    EXPECT_FALSE(shaded) << cases[c].name << " box top " << i << "," << j;
                }
                if (shaded) {
                    const auto blocker = geometry.intersect(origin, kSun, 0.0);
                    ASSERT_TRUE(blocker);
                    EXPECT_EQ(blocker->instance, 1u) << cases[c].name;
                }
                shadows[c].push_back(shaded ? 1 : 0);
            }
        }
    }
    EXPECT_EQ(shadows[1], shadows[0]);
    EXPECT_EQ(shadows[2], shadows[0]);
    int shaded = 0;
    for (const int s : shadows[0]) shaded += s;
    EXPECT_GT(shaded, 15);  // the box's 3 m shadow falls in the view
    // The offsets are those of the scene's own size (its float numbers up to ~1 km carry
    // 6e-5 m per ulp), wherever it lies: the same to 1 % at the origin and at UTM.
    EXPECT_LT(largest_offset_m[0], 5e-3);
    EXPECT_NEAR(largest_offset_m[1], largest_offset_m[0], 0.01 * largest_offset_m[0]);
    EXPECT_NEAR(largest_offset_m[2], largest_offset_m[0], 0.01 * largest_offset_m[0]);
}

TEST(GeometryScenePrecision, AMeshInUtmCoordinatesKeepsItsEdgesToTheMillimetre) {
    // A 2 km plate whose corners are written at (500,000.3 ± 1000, 4,000,000.7 ± 1000): as
    // plain floats they would move by up to 0.125 m (the float step there is 0.25 m); kept
    // from a mesh origin (model::mesh_origin_for) they stay. Rays 2 mm inside its edges hit,
    // 2 mm outside miss.
    const Vec3 center{500'000.3, 4'000'000.7, 0.0};
    model::Scene scene = scene_with_materials(1);
    add_static(scene, add_object(scene, plate_at(center, 2000.0), "plate"));
    ASSERT_NE(scene.objects[0].mesh.origin_m[0], 0.0);
    const GeometryScene geometry = build(scene);
    for (const double inset_m : {0.002, -0.002}) {
        for (const Vec3& edge :
             {Vec3{1000.0 - inset_m, 3.0, 0.0}, Vec3{-1000.0 + inset_m, 3.0, 0.0},
              Vec3{3.0, 1000.0 - inset_m, 0.0}, Vec3{3.0, -1000.0 + inset_m, 0.0}}) {
            const Vec3 target = center + edge;
            const auto hit =
                geometry.intersect(target + Vec3{0.0, 0.0, 500.0}, {0.0, 0.0, -1.0}, 0.0);
            EXPECT_EQ(hit.has_value(), inset_m > 0.0) << edge.x << ", " << edge.y;
            if (hit) {
                EXPECT_LT(norm(hit->position_m - target), kPosition_m);
            }
        }
    }
}

/// Directions leaving a surface of unit normal `n` at elevations from `min_deg` to 89°,
/// azimuths all round (elevation measured from the surface).
std::vector<Vec3> leaving_directions(const Vec3& n, double min_deg, int count) {
    const Vec3 a = std::abs(n.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 t = normalized(cross(n, a));
    const Vec3 b = cross(n, t);
    std::vector<Vec3> out;
    for (int i = 0; i < count; ++i) {
        // Elevations spaced logarithmically, so grazing ones are many.
        const double f = (i + 0.5) / count;
        const double elevation = min_deg * std::pow(89.0 / min_deg, f) * kDeg;
        const double azimuth = 2.399963 * i;  // golden angle
        out.push_back(
            normalized(n * std::sin(elevation) +
                       (t * std::cos(azimuth) + b * std::sin(azimuth)) * std::cos(elevation)));
    }
    return out;
}

/// Counts rays leaving `hit` into the outside (along `directions`) that hit the same
/// triangle of the same instance, with each query kind.
int self_hits(const GeometryScene& geometry, const RayHit& hit,
              const std::vector<Vec3>& directions) {
    int count = 0;
    std::vector<PacketRay> rays;
    for (const Vec3& d : directions) {
        const Vec3 origin = geometry.spawn_origin(hit, d);
        const auto again = geometry.intersect(origin, d, 0.0);
        if (again && again->instance == hit.instance && again->triangle == hit.triangle) ++count;
        rays.push_back({origin, d, 0.0});
    }
    for (std::size_t at = 0; at < rays.size(); at += kPacketSize) {
        const std::size_t n = std::min(kPacketSize, rays.size() - at);
        std::array<std::optional<RayHit>, kPacketSize> hits;
        geometry.intersect_packet(std::span(rays).subspan(at, n), std::span(hits).first(n));
        for (std::size_t k = 0; k < n; ++k) {
            if (hits[k] && hits[k]->instance == hit.instance && hits[k]->triangle == hit.triangle)
                ++count;
        }
    }
    return count;
}

TEST(GeometryScenePrecision, GrazingRaysNeverHitTheSurfaceTheyLeave) {
    // Lone tilted 2 km plates (nothing else to hit) near the origin, 40 km out and at UTM
    // coordinates; rays leave every hit at elevations down to 0.01° on both sides.
    struct Place {
        Vec3 translation;
        std::array<double, 3> rotation_deg;
    };
    const std::vector<Place> places = {{{0, 0, 0}, {10, -20, 30}},
                                       {{40'000, -25'000, 350}, {-35, 5, 80}},
                                       {{512'345.5, 4'123'456.25, 1800}, {3, 60, -10}}};
    for (const Place& place : places) {
        model::Scene scene = scene_with_materials(1);
        const std::size_t plate = add_object(
            scene,
            quad_mesh({-1000, -1000, 0}, {1000, -1000, 0}, {1000, 1000, 0}, {-1000, 1000, 0}, 0),
            "plate");
        model::StaticTransform transform = translated(place.translation);
        transform.rotation_rad = {place.rotation_deg[0] * kDeg, place.rotation_deg[1] * kDeg,
                                  place.rotation_deg[2] * kDeg};
        add_static(scene, plate, transform);
        const GeometryScene geometry = build(scene);
        const motion::Mat3 r = motion::euler_to_matrix(motion::to_vec3(transform.rotation_rad),
                                                       motion::EulerOrder::xyz);
        int hits = 0;
        int self = 0;
        for (int i = 0; i < 40; ++i) {
            const Vec3 n = r * Vec3{0, 0, 1};
            const Vec3 target =
                place.translation + r * Vec3{(i % 7) * 140.0 - 421.3, (i % 5) * 190.0 - 377.7, 0.0};
            const Vec3 d = normalized(Vec3{0.3 * std::cos(i), 0.3 * std::sin(i), -1.0});
            const Vec3 from = dot(d, n) < 0 ? target - d * 3000.0 : target + d * 3000.0;
            const auto hit = geometry.intersect(from, dot(d, n) < 0 ? d : d * -1.0, 0.0);
            if (!hit) continue;
            ++hits;
            self += self_hits(geometry, *hit, leaving_directions(hit->normal, 0.01, 50));
            self += self_hits(geometry, *hit, leaving_directions(hit->normal * -1.0, 0.01, 50));
        }
        EXPECT_EQ(hits, 40);
        EXPECT_EQ(self, 0) << "plate at " << place.translation.x;
    }
}

TEST(GeometryScenePrecision, ThinSlabsAndFarInstancesKeepTheirFaces) {
    // A 1 mm slab (10 m across) and a UV sphere (1 m radius), each instanced near the origin
    // and at UTM-like coordinates with a rotation. A ray entering the slab finds the other
    // face about 1 mm on; one entering the sphere finds the far side; rays leaving either
    // into the outside hit nothing (both are convex and alone).
    for (const Vec3& far : {Vec3{0, 0, 0}, Vec3{600'000.0, 4'100'000.0, 1500.0}}) {
        model::Scene scene = scene_with_materials(1);
        const std::size_t slab = add_object(scene, box_mesh({-5, -5, 0}, {5, 5, 0.001}, 0), "slab");
        const std::size_t ball = add_object(scene, sphere_mesh(1.0, 48, 24, 0), "ball");
        model::StaticTransform slab_at = translated(far);
        slab_at.rotation_rad = {0.2, -0.1, 0.7};
        add_static(scene, slab, slab_at, "slab");
        add_static(scene, ball, translated(far + Vec3{30.0, 0.0, 5.0}), "ball");
        const GeometryScene geometry = build(scene);

        int self = 0;
        int wrong_inside = 0;
        for (int i = 0; i < 60; ++i) {
            // Into the slab from above, at up to 80° from its normal.
            const motion::Mat3 r = motion::euler_to_matrix(motion::to_vec3(slab_at.rotation_rad),
                                                           motion::EulerOrder::xyz);
            const Vec3 n = r * Vec3{0, 0, 1};
            const Vec3 target = far + r * Vec3{(i % 6) * 1.3 - 3.1, (i % 5) * 1.7 - 3.3, 0.001};
            const double tilt = (i * 1.33) * kDeg;
            const Vec3 side = normalized(cross(n, Vec3{0.3, 0.4, 0.5}));
            const Vec3 d = normalized(n * -std::cos(tilt) + side * std::sin(tilt));
            const auto top = geometry.intersect(target - d * 50.0, d, 0.0);
            ASSERT_TRUE(top);
            self += self_hits(geometry, *top, leaving_directions(top->normal, 0.01, 20));
            const auto bottom = geometry.intersect(geometry.spawn_origin(*top, d), d, 0.0);
            // The other face, 1 mm / cos on (float vertices: 0.001 is 0.001 ± 1e-10).
            if (!bottom || dot(bottom->normal, top->normal) > -0.99 ||
                std::abs(bottom->distance_m - (0.001 - top->spawn_offset_m) / std::cos(tilt)) >
                    1e-6) {
                ++wrong_inside;
            } else {
                self += self_hits(geometry, *bottom, leaving_directions(bottom->normal, 0.01, 20));
            }

            // Into the sphere.
            const Vec3 centre = far + Vec3{30.0, 0.0, 5.0};
            const Vec3 aim = normalized(Vec3{std::cos(0.7 * i), std::sin(1.1 * i), 0.4});
            const Vec3 from = centre + aim * 20.0 + Vec3{0.0, 0.1 * (i % 3), 0.0};
            const Vec3 in = normalized(centre - from);
            const auto near_side = geometry.intersect(from, in, 0.0);
            ASSERT_TRUE(near_side);
            self +=
                self_hits(geometry, *near_side, leaving_directions(near_side->normal, 0.01, 20));
            const auto far_side =
                geometry.intersect(geometry.spawn_origin(*near_side, in), in, 0.0);
            if (!far_side || far_side->distance_m < 1.5) ++wrong_inside;
        }
        EXPECT_EQ(self, 0) << far.x;
        EXPECT_EQ(wrong_inside, 0) << far.x;
    }
}

TEST(GeometryScenePrecision, AMovingObjectFarFromTheOriginDoesNotShadeItself) {
    // A box flying 200 m/s at UTM-like coordinates, 3 km up: rays leaving any hit on it
    // into the outside find nothing of it, at every time in the window.
    model::Scene scene = scene_with_materials(1);
    const std::size_t box = add_object(scene, box_mesh({-2, -1, -0.5}, {2, 1, 0.5}, 0), "jet");
    const Vec3 start{520'000.0, 4'050'000.0, 3000.0};
    add_dynamic(scene, box, straight_motion(start, 45.0, 200.0));
    const GeometryScene geometry = build(scene, options_over(0.0, 2.0));
    int hits = 0;
    int self = 0;
    for (int i = 0; i < 40; ++i) {
        const double t = 0.05 * i;
        const Vec3 at = start + Vec3{std::sin(45 * kDeg), std::cos(45 * kDeg), 0.0} * (200.0 * t);
        const Vec3 d = normalized(Vec3{0.2 * std::cos(i), 0.2 * std::sin(i), -1.0});
        const Vec3 from = at + Vec3{0.1 * (i % 5) - 0.2, 0.05 * (i % 3), 0.0} - d * 100.0;
        const auto hit = geometry.intersect(from, d, t);
        if (!hit) continue;
        ++hits;
        for (const Vec3& out : leaving_directions(hit->normal, 0.01, 20)) {
            const auto again = geometry.intersect(geometry.spawn_origin(*hit, out), out, t);
            if (again) ++self;
        }
    }
    EXPECT_GT(hits, 35);
    EXPECT_EQ(self, 0);
}

}  // namespace geometry_scene_precision_test
}  // namespace glint::scene
