// SPDX-License-Identifier: Apache-2.0
// The inside of a GeometryScene, shared by the build (geometry_scene.cpp) and the ray
// queries (ray_queries.cpp). Members are declared so that they are destroyed in a safe
// order: the top-level scene first, then the object scenes, then the device.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "embree_device.h"
#include "placement.h"

namespace glint::scene {
namespace detail {

/// One object's Embree scene and what a hit on it needs.
struct ObjectData {
    ScenePtr scene;                        ///< null for an object no instance uses
    std::vector<std::uint32_t> materials;  ///< per triangle; empty when all are single_material
    std::uint32_t single_material = 0;     ///< every triangle's, when `materials` is empty
    std::uint64_t triangle_count = 0;
};

/// One instance in the top-level scene (its Embree geometry ID is its index).
struct InstanceData {
    std::size_t object = 0;
    /// True when Embree interpolates the transform over time steps (≥ 2).
    bool moving = false;
    /// Static instances (and instants): the normal matrix (inverse transpose of the linear
    /// part of the object → scene map).
    Mat3 normal_matrix = Mat3::identity();
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
