// SPDX-License-Identifier: Apache-2.0
// Reader of glint's own YAML scene (docs/scene.md; keys listed in glint/model/scene.h). Like
// every reader it reports each problem (file:line, key path) to `diagnostics` and carries on;
// the caller fails when diagnostics has errors. Meshes are built by glint/mesh/mesh.h.
#pragma once

#include <filesystem>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/model/scene.h"

namespace glint::yaml {

/// Reads a glint YAML scene, loading and tessellating its geometry and reading the motion
/// of its dynamic instances. `$SCENE_DIR` is the folder of `file` unless `options` sets it.
/// The DIRSIG `.glist` files of its `glists` key are read with read_glist into the same
/// scene, after its `objects`; their `matid` and `usemtl` bind to its materials by id.
model::Scene read_yaml_scene(const std::filesystem::path& file, const dirsig::ReadOptions& options,
                             Diagnostics& diagnostics);

}  // namespace glint::yaml
