// SPDX-License-Identifier: Apache-2.0
// Readers of a DIRSIG classic scene into model::Scene: the `.scene` XML (origin, geometry
// list includes, one material database), the `.glist` geometry lists (OBJ and primitive
// base geometry, nested lists, static and dynamic instances, tags) and the documented
// subset of the `.mat` text database (id, name, reflectance and emissivity curves from
// two-column files, constant temperature). docs/scene.md ("DIRSIG classic scenes") gives
// the exact layouts accepted. Like every reader they report each problem (file:line,
// element path) to `diagnostics` and carry on; the caller fails when it has errors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/mesh/mesh.h"
#include "glint/model/scene.h"

namespace glint::dirsig {

/// Reads a DIRSIG `<classicscene>` `.scene` file: its origin, its material database and every
/// enabled geometry list, with their geometry loaded, tessellated and validated. `$SCENE_DIR`
/// is the folder of `file` unless `options` sets it; paths named inside a `.mat` or `.glist`
/// are relative to that file.
model::Scene read_dirsig_scene(const std::filesystem::path& file, const ReadOptions& options,
                               Diagnostics& diagnostics);

/// Reads a DIRSIG `.mat` material database (the subset in docs/scene.md). Curve files are
/// relative to the `.mat` file's folder.
std::vector<model::Material> read_dirsig_materials(const std::filesystem::path& file,
                                                   const ReadOptions& options,
                                                   Diagnostics& diagnostics);

/// Reads one material curve file alone (as glint-platform2jsim --check does): a two-column
/// curve (wavelength µm, value) or a classic `.ems`, read as a `.mat` would read it for
/// `quantity` ("reflectance", "emissivity": values in [0, 1]; "intensity": values >= 0).
/// docs/formats.md ("Material curve files") gives the layouts. Each problem goes to
/// `diagnostics` at the file's line; an empty table means nothing usable was read.
model::SpectralTable read_curve_file(const std::filesystem::path& file, const std::string& quantity,
                                     const ReadOptions& options, Diagnostics& diagnostics);

/// Reads the Wavefront OBJ `file` through `options` and parses it (mesh::parse_obj_mesh:
/// `usemtl` names looked up with `material_index`, faces before any `usemtl` take
/// `default_material`). `display_name` names the file in messages.
model::Mesh load_obj_mesh(const std::filesystem::path& file, const std::string& display_name,
                          const ReadOptions& options, const mesh::MaterialLookup& material_index,
                          std::optional<std::uint32_t> default_material, std::size_t material_count,
                          Diagnostics& diagnostics);

/// Reads a `.glist` geometry list, appending its objects and instances to `scene`, whose
/// materials (matid and OBJ `usemtl` bind to them) must already be read. Nested `glist`
/// base geometry is flattened: its instances are composed with the including instance.
void read_glist(const std::filesystem::path& file, const ReadOptions& options, model::Scene& scene,
                Diagnostics& diagnostics);

}  // namespace glint::dirsig
