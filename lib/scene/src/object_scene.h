// SPDX-License-Identifier: Apache-2.0
// One geometry object as an Embree scene of its own (a triangle mesh, built once at high
// quality and shared by every instance of the object), with its bounds and extent.
#pragma once

#include <cstddef>

#include "geometry_scene_impl.h"
#include "instance_motion.h"

namespace glint::scene::detail {

/// Checks an object's mesh against what Embree and the hit queries rely on: at least one
/// triangle, vertex indices in range, finite vertices, one material per triangle, each below
/// `material_count`. Throws glint::Error (input, at the object).
void check_mesh(const model::GeometryObject& object, std::size_t material_count);

/// The object's Embree scene (committed) and hit data. The mesh must have passed check_mesh.
/// Throws glint::Error (runtime) for Embree errors, the memory cap included.
ObjectData build_object_scene(EmbreeDevice& device, const model::GeometryObject& object);

/// Bounds of the mesh's vertices, object coordinates.
Bounds mesh_bounds(const model::Mesh& mesh) noexcept;
/// The extent of the mesh for motion sampling.
ObjectExtent mesh_extent(const model::Mesh& mesh) noexcept;

}  // namespace glint::scene::detail
