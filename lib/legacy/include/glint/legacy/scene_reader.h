// SPDX-License-Identifier: Apache-2.0
// Reader of the glint YAML scene (docs/scene.md; keys listed in glint/model/scene.h) and its
// geometry stages: Wavefront OBJ loading (tinyobjloader, `usemtl` names bound to materials),
// primitive tessellation and the mesh validation every mesh passes before Embree sees it.
// Like every legacy reader they report each problem (file:line, key path) to `diagnostics`
// and carry on; the caller fails when diagnostics has errors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/legacy/read_options.h"
#include "glint/model/scene.h"

namespace glint::legacy {

/// Reads a glint YAML scene, loading and tessellating its geometry and reading the motion
/// of its dynamic instances. `$SCENE_DIR` is the folder of `file` unless `options` sets it.
/// The DIRSIG `.glist` files of its `glists` key are read with read_glist into the same
/// scene, after its `objects`; their `matid` and `usemtl` bind to its materials by id.
model::Scene read_yaml_scene(const std::filesystem::path& file, const ReadOptions& options,
                             Diagnostics& diagnostics);

/// Loads a Wavefront OBJ into a mesh: vertices (`v`), faces (`f`, polygons fan-triangulated,
/// negative indices relative), `usemtl` names looked up with `material_index` (nullopt: an
/// error naming the material). Faces before any `usemtl` take `default_material` (none: an
/// error). Normals, texture coordinates, groups and `mtllib` are ignored. Vertices that are
/// not finite numbers, indices out of range and unknown materials are errors at the OBJ's
/// own line. The mesh is validated (validate_mesh) before it is returned.
model::Mesh load_obj_mesh(
    const std::filesystem::path& file, const std::string& display_name,
    const std::function<std::optional<std::uint32_t>(const std::string&)>& material_index,
    std::optional<std::uint32_t> default_material, std::size_t material_count,
    Diagnostics& diagnostics);

/// Tessellates a primitive (docs/scene.md gives the exact definitions), every triangle of
/// material `material`. Parameters out of range are errors at `where` (an empty mesh then).
model::Mesh tessellate_primitive(const model::Primitive& primitive, std::uint32_t material,
                                 const ErrorContext& where, Diagnostics& diagnostics);

/// Validates a mesh in place: non-finite vertices, vertex indices out of range and material
/// indices >= `material_count` are errors; degenerate triangles (repeated index, or area
/// <= 1e-12 × the squared longest edge) are dropped with one warning giving their count;
/// a mesh left without triangles is an error. Returns true when no error was found.
bool validate_mesh(model::Mesh& mesh, std::size_t material_count, const ErrorContext& where,
                   Diagnostics& diagnostics);

}  // namespace glint::legacy
