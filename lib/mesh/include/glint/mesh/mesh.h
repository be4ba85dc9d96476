// SPDX-License-Identifier: Apache-2.0
// Building the triangle meshes of a scene from what its files describe: Wavefront OBJ text
// (glint's own one-pass reader, which values coordinates as tinyobjloader 2.0 did; `usemtl`
// names bound to materials), the YAML scene's primitives (ground plane, box, UV sphere, disk,
// cylinder; docs/scene.md gives the exact tessellation), and the validation every mesh passes
// before the Embree scene sees it. No file is opened here: the readers hand the text in.
// Problems go to `diagnostics` (file:line) and the functions carry on; the caller fails when
// diagnostics has errors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "glint/core/diagnostics.h"
#include "glint/model/scene.h"

namespace glint::mesh {

/// Looks a `usemtl` name up: the material index, or nullopt for an unknown name.
using MaterialLookup = std::function<std::optional<std::uint32_t>(const std::string&)>;

/// Parses Wavefront OBJ `text` (named `display_name` in diagnostics) into a mesh: vertices
/// (`v`), faces (`f`, polygons fan-triangulated, negative indices relative), `usemtl` names
/// looked up with `material_index` (nullopt: an error naming the material). Faces before any
/// `usemtl` take `default_material` (none: an error). Normals, texture coordinates, groups and
/// `mtllib` are ignored. Vertices that are not finite numbers, indices out of range and
/// unknown materials are errors at the OBJ's own line. The mesh is validated (validate_mesh)
/// before it is returned; an empty mesh on error.
model::Mesh parse_obj_mesh(std::string_view text, const std::string& display_name,
                           const MaterialLookup& material_index,
                           std::optional<std::uint32_t> default_material,
                           std::size_t material_count, Diagnostics& diagnostics);

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

}  // namespace glint::mesh
