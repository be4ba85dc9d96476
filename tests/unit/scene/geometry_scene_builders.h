// SPDX-License-Identifier: Apache-2.0
// Small model::Scene builders for the GeometryScene tests: materials, primitive and custom
// meshes, static instances and FlexMotion dynamic instances (straight line, spin), a build()
// that makes the trajectories the way a tool does, and the tests' shared tolerances and
// expectation helpers.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <mutex>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/core/error.h"
#include "glint/core/log.h"
#include "glint/mesh/mesh.h"
#include "glint/scene/geometry_scene.h"

namespace glint::scene::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;

inline constexpr Vec3 kDown{0.0, 0.0, -1.0};
inline constexpr Vec3 kUp{0.0, 0.0, 1.0};

/// Float vertices and transforms give normals good to a few float ulps (≈ 1e-7); 1e-6 is a
/// safe bound for unit vectors built from them.
inline constexpr double kNormalTol = 1e-6;
/// Distances in scenes of a few hundred metres: float hit distances over ≤ 300 m carry
/// ≈ 3e-5 m of rounding; 1e-4 m is a safe bound.
inline constexpr double kLocalTol_m = 1e-4;

inline void expect_vec_near(const Vec3& actual, const Vec3& expected, double tol) {
    EXPECT_NEAR(actual.x, expected.x, tol);
    EXPECT_NEAR(actual.y, expected.y, tol);
    EXPECT_NEAR(actual.z, expected.z, tol);
}

/// Warnings collected from a Log.
struct Warnings {
    std::mutex mutex;
    std::vector<std::string> items;
    Log log() {
        return Log(
            [this](LogLevel, const std::string& m) {
                const std::lock_guard<std::mutex> lock(mutex);
                items.push_back(m);
            },
            LogLevel::warning);
    }
};

/// The category and message of the glint::Error `f` throws (fails when it throws none).
template <class F>
inline Error error_of(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "no glint::Error thrown";
    return Error(ErrorCategory::internal, "none");
}

/// An empty scene with `count` materials "m0", "m1", ...
inline model::Scene scene_with_materials(std::size_t count) {
    model::Scene scene;
    scene.file = "test.yaml";
    for (std::size_t i = 0; i < count; ++i) {
        model::Material m;
        m.id = "m" + std::to_string(i);
        m.name = m.id;
        scene.materials.push_back(m);
    }
    return scene;
}

/// The tessellated mesh of a primitive (glint's own tessellation, docs/scene.md).
inline model::Mesh primitive_mesh(const model::Primitive& primitive, std::uint32_t material) {
    Diagnostics diagnostics;
    model::Mesh mesh = mesh::tessellate_primitive(primitive, material, {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    return mesh;
}

/// A square ground plane of side `size_m` at z = 0, normal +z.
inline model::Mesh ground_plane_mesh(double size_m, std::uint32_t material) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::ground_plane;
    p.size_m = size_m;
    return primitive_mesh(p, material);
}

/// An axis-aligned box, outward normals.
inline model::Mesh box_mesh(const Vec3& lower, const Vec3& upper, std::uint32_t material) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::box;
    p.lower_m = motion::to_array(lower);
    p.upper_m = motion::to_array(upper);
    return primitive_mesh(p, material);
}

/// A UV sphere about the origin.
inline model::Mesh sphere_mesh(double radius_m, int segments, int rings, std::uint32_t material) {
    model::Primitive p;
    p.kind = model::PrimitiveKind::sphere;
    p.radius_m = radius_m;
    p.segments = segments;
    p.rings = rings;
    return primitive_mesh(p, material);
}

/// A quad (two triangles, counter-clockwise a, b, c, d seen from the front).
inline model::Mesh quad_mesh(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                             std::uint32_t material) {
    model::Mesh mesh;
    for (const Vec3& v : {a, b, c, d}) {
        mesh.vertices_m.push_back(
            {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)});
    }
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.triangle_materials = {material, material};
    return mesh;
}

/// Adds an object holding `mesh`; returns its index.
inline std::size_t add_object(model::Scene& scene, model::Mesh mesh, const std::string& name) {
    model::GeometryObject object;
    object.name = name;
    object.mesh = std::move(mesh);
    object.where = {scene.file, static_cast<int>(10 + scene.objects.size()), name};
    scene.objects.push_back(std::move(object));
    return scene.objects.size() - 1;
}

/// Adds a static instance of `object`; returns its index.
inline std::size_t add_static(model::Scene& scene, std::size_t object,
                              const model::StaticTransform& transform = {},
                              const std::string& name = "static") {
    model::Instance instance;
    instance.object_index = object;
    instance.name = name;
    instance.transform = transform;
    instance.where = {scene.file, static_cast<int>(100 + scene.instances.size()), name};
    scene.instances.push_back(std::move(instance));
    return scene.instances.size() - 1;
}

/// Adds a dynamic instance of `object` moving as `motion`; returns its index.
inline std::size_t add_dynamic(model::Scene& scene, std::size_t object, model::FlexMotion motion,
                               const std::string& name = "dynamic") {
    model::Instance instance;
    instance.object_index = object;
    instance.name = name;
    model::PlatformMotion platform_motion;
    platform_motion.flexible = std::move(motion);
    instance.motion = std::make_shared<const model::PlatformMotion>(std::move(platform_motion));
    instance.where = {scene.file, static_cast<int>(100 + scene.instances.size()), name};
    scene.instances.push_back(std::move(instance));
    return scene.instances.size() - 1;
}

/// A translation-only static transform.
inline model::StaticTransform translated(const Vec3& t) {
    model::StaticTransform transform;
    transform.translation_m = motion::to_array(t);
    return transform;
}

/// Straight-line motion from `start` (at t = 0) along `heading_deg` (clockwise from north)
/// at `speed_m_s`, with the identity orientation throughout.
inline model::FlexMotion straight_motion(const Vec3& start, double heading_deg, double speed_m_s) {
    model::FlexMotion f;
    f.location.type = model::LocationEngineType::straight;
    f.location.heading_rad = heading_deg * kDeg;
    f.location.speed_m_s = speed_m_s;
    f.location.location.xyz_m = motion::to_array(start);
    f.orientation.type = model::OrientationEngineType::euler;
    f.orientation.table = {model::MotionTableRow{0.0, {0.0, 0.0, 0.0, 0.0}, 0}};
    return f;
}

/// A spin about `axis` at `rate_deg_s` (phase 0 at t = 0) at the fixed place `at`.
inline model::FlexMotion spin_motion(const Vec3& at, const Vec3& axis, double rate_deg_s) {
    model::FlexMotion f;
    f.location.type = model::LocationEngineType::fixed;
    f.location.location.xyz_m = motion::to_array(at);
    f.orientation.type = model::OrientationEngineType::spin;
    f.orientation.spin_axis = motion::to_array(axis);
    f.orientation.spin_rate_rad_s = rate_deg_s * kDeg;
    return f;
}

/// Build options over `window` with the default device and sampling.
inline BuildOptions options_over(double begin_s, double end_s) {
    BuildOptions options;
    options.window = {begin_s, end_s};
    return options;
}

/// The scene built with trajectories from make_instance_trajectories (default frame).
inline GeometryScene build(const model::Scene& scene, const BuildOptions& options = {},
                           Log log = {}) {
    const auto trajectories =
        motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{}, log);
    return GeometryScene::build(scene, trajectories, options, log);
}

}  // namespace glint::scene::test
