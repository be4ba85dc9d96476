// SPDX-License-Identifier: Apache-2.0
// The inside of a GeometryScene, shared by the build (geometry_scene.cpp) and the ray
// queries (ray_queries.cpp). Members are declared so that they are destroyed in a safe
// order: the top-level scene first, then the object scenes, then the device.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "embree_device.h"
#include "placement.h"

namespace glint::scene {
namespace detail {

/// A triangle's plane in its object's buffer coordinates (vertices less the object's centre):
/// normal · p = offset. One aligned 32-byte record per triangle, so a hit rebuilds its point
/// from one cache line instead of an index and three vertex loads.
struct alignas(32) TrianglePlane {
    double offset_m = 0.0;          ///< normal · v0, in double from the float vertices
    std::array<float, 3> normal{};  ///< unit (v1 − v0) × (v2 − v0); 0 when degenerate
    float diameter_m = 0.0f;        ///< the largest |vi − vj|∞, rounded up
};
static_assert(sizeof(TrianglePlane) == 32, "one plane per half cache line");

/// One object's Embree scene and what a hit on it needs.
struct ObjectData {
    ScenePtr scene;  ///< null for an object no instance uses
    /// Per triangle, its plane: a hit's position and normal.
    std::vector<TrianglePlane> planes;
    /// The vertex buffer Embree traces: the mesh's vertices minus `center_m`, in float
    /// (3 per vertex, owned by the geometry the scene holds); read only for a ray lying in a
    /// triangle's plane.
    const float* vertices = nullptr;
    const std::uint32_t* triangles = nullptr;  ///< 3 per triangle, owned like `vertices`
    /// The centre of the mesh's bounds, object coordinates: the buffer holds vertices relative
    /// to it, so Embree's object-space numbers are the object's size, not its position.
    Vec3 center_m;
    std::vector<std::uint32_t> materials;  ///< per triangle; empty when all are single_material
    std::uint32_t single_material = 0;     ///< every triangle's, when `materials` is empty
    /// Per triangle, its corners' texture coordinates: only when a map projects through them.
    std::vector<std::array<float, 6>> uvs;
    std::uint64_t triangle_count = 0;
};

/// One instance in the top-level scene (its Embree geometry ID is its index).
struct InstanceData {
    std::size_t object = 0;
    /// True when Embree interpolates the transform over time steps (≥ 2).
    bool moving = false;
    /// Left out of the Embree scene (BuildOptions::static_only): no ray meets it.
    bool absent = false;
    /// Static instances (and instants): the normal matrix (inverse transpose of the linear
    /// part of `to_frame`).
    Mat3 normal_matrix = Mat3::identity();
    /// Static instances (and instants): the map from the object's vertex buffer to Embree's
    /// frame exactly as Embree holds it (its float 3×4 matrix, read back in double).
    Affine to_frame;
    /// Moving instances: the geometry, to ask Embree for its transform at a ray's time.
    RTCGeometry geometry = nullptr;
    /// Where the instance is over the window (moving ones: swept and padded).
    Bounds bounds;
};

}  // namespace detail

struct GeometryScene::Impl {
    std::unique_ptr<detail::EmbreeDevice> device;
    std::vector<detail::ObjectData> objects;
    std::vector<detail::GeometryPtr> instance_geometries;
    detail::ScenePtr top;
    std::vector<detail::InstanceData> instances;

    /// Where Embree's frame has its origin, scene ENU: the centre of the scene's bounds. Rays
    /// and instance translations are shifted by it in double before they become float, so
    /// Embree's numbers are the scene's size, not its distance from the scene origin (a scene
    /// in UTM coordinates keeps millimetres).
    Vec3 anchor_m;
    /// The scene's property maps, applied to every hit.
    SurfaceMaps maps;
    /// THERM's facet temperatures (null: none).
    std::shared_ptr<const FacetTemperatures> facet_temperatures;
    Bounds bounds;       ///< tight (reported)
    Bounds clip_bounds;  ///< enlarged, for clipping rays in double precision
    TimeWindow window;
    std::vector<unsigned> time_steps;
    std::uint64_t instanced_triangles = 0;
    /// Some instance moves over the window (the top level then holds motion-blurred
    /// instances, whose packet traversal rounds differently from the single-ray one).
    bool any_moving = false;

    ~Impl() {
        top.reset();
        instance_geometries.clear();
        objects.clear();
        device.reset();
    }
};

}  // namespace glint::scene
