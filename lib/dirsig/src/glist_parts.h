// SPDX-License-Identifier: Apache-2.0
// Internal interface of the glist readers: the state one scene load shares between its
// glists (geometry database directories, nested glists and local material files read once,
// warnings given once), path search through the database directories (scene_search.cpp),
// the material scopes of `localmaterials` and `assign` (glist_materials.cpp), nested glist
// placement (glist_nested.cpp), point sources (glist_sources.cpp) and the per-file element
// reader (glist_reader.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/io/xml.h"
#include "glint/model/scene.h"

namespace glint::dirsig::detail {

using Matrix4 = std::array<double, 16>;

/// A nested glist as read once per scene load and material scope: its objects are in the
/// scene already and `instances` (absolute object indices) are placed again for every
/// instance that includes it, so a glist named by ten objects is parsed once.
struct NestedGlist {
    std::vector<model::Instance> instances;
    std::vector<model::PointSource> sources;  ///< positions in the glist's frame
};

/// A material of a `localmaterials` file: its id and name as written (the copy appended to
/// Scene::materials may carry a qualified id) and its index in Scene::materials.
struct LocalMaterial {
    std::string id;
    std::string name;
    std::uint32_t index = 0;
};

/// `<assign id="ID">objmtl</assign>`: OBJ `usemtl objmtl` binds to material ID.
struct Assignment {
    std::string obj_name;
    std::uint32_t material = 0;
};

/// The materials one object adds for its base geometry (and, through a nested glist, for
/// every object below it): its `localmaterials` and its `assign` entries.
struct MaterialScope {
    std::vector<LocalMaterial> locals;
    std::vector<Assignment> assignments;
    std::string key;  ///< identifies the scope in the nested-glist cache
};

/// What one scene load shares between all its glists.
struct SceneLoad {
    /// Folders of `<gdbdirectory>` and `<odbdirectory>`, resolved, in file order.
    std::vector<std::filesystem::path> gdb_dirs;
    std::vector<std::filesystem::path> odb_dirs;
    /// Scene::materials[0, global_materials) are the scene's own (the `.mat`, or the YAML
    /// materials); later ones come from `localmaterials` and bind only inside their scope.
    std::size_t global_materials = 0;
    /// `localmaterials` files read so far: their materials, by absolute path.
    std::map<std::filesystem::path, std::vector<LocalMaterial>> local_files;
    /// Nested glists read so far, by absolute path and material scope key.
    std::map<std::pair<std::filesystem::path, std::string>, NestedGlist> nested;
    /// Objects baked for a dynamic instance of a glist: (object, placement) → object index.
    std::map<std::pair<std::size_t, Matrix4>, std::size_t> baked;
    /// Glists being read, outermost first (an include cycle is an error).
    std::vector<std::filesystem::path> chain;
    /// Warnings already given once in this load, by kind.
    std::set<std::string> warned;
};

/// What a relative path names: geometry (OBJ, GDB) is searched in the gdb directories
/// first, glists (and ODBs) in the odb directories first; `plain` files (materials,
/// motion) only beside the file that names them.
enum class FileKind { geometry, glist, plain };

/// Finds the file `text` (named at `where` in a file whose folder is `base_dir`) as
/// docs/scene.md ("Paths") describes: absolute and `$VAR` paths as written; `local` (the
/// `search_paths="local"` attribute) or a plain file beside the naming file; otherwise the
/// database directories, then the naming file's folder. A miss is an error at `where` naming
/// `what` and every place tried; a guess is a warning, once per load. Empty `resolved`: not
/// found.
model::FileRef find_file(const std::string& text, const std::filesystem::path& base_dir, bool local,
                         FileKind kind, std::string_view what, const ErrorContext& where,
                         const ReadOptions& options, SceneLoad& load, Diagnostics& diagnostics);

/// Reads the `<gdbdirectory>` and `<odbdirectory>` elements of a `.scene` (relative to
/// `base_dir`, the scene's folder) into `load`; a folder that does not exist is a warning.
void read_database_dirs(const io::XmlNode& root, const std::filesystem::path& base_dir,
                        const ReadOptions& options, SceneLoad& load, Diagnostics& diagnostics);

/// The value of a `search_paths` attribute: true for "local"; absent is false; another
/// value is a warning (read as absent).
bool search_paths_local(const io::XmlNode& node, Diagnostics& diagnostics);

/// Reads one glist file into `scene` with `scopes` (outermost first) in force.
void read_glist_file(const std::filesystem::path& path, const ReadOptions& options,
                     model::Scene& scene, Diagnostics& diagnostics, SceneLoad& load,
                     const std::vector<MaterialScope>& scopes);

/// The scope an `object` element adds: its `localmaterials` files (read once per load and
/// appended to scene.materials) and its `assign` elements (found in the object and in
/// `obj`). nullopt when it has neither.
std::optional<MaterialScope> read_material_scope(const io::XmlNode& object,
                                                 std::optional<io::XmlNode> obj,
                                                 const std::filesystem::path& base_dir, bool local,
                                                 const ReadOptions& options, model::Scene& scene,
                                                 SceneLoad& load,
                                                 const std::vector<MaterialScope>& outer,
                                                 Diagnostics& diagnostics);

/// The material `id` names within `scopes` (innermost first, then the scene's own).
std::optional<std::uint32_t> material_by_id(const std::string& id, const model::Scene& scene,
                                            const SceneLoad& load,
                                            const std::vector<MaterialScope>& scopes);

/// The material an OBJ `usemtl name` binds to: an `assign` of that name (innermost scope
/// first), else a material whose id, then whose name, is `name` (scopes, then the scene).
std::optional<std::uint32_t> material_for_usemtl(const std::string& name, const model::Scene& scene,
                                                 const SceneLoad& load,
                                                 const std::vector<MaterialScope>& scopes);

/// The 4×4 of a static transform (scene.h: p' = t + R · (s ∘ p)).
Matrix4 to_matrix(const model::StaticTransform& t);
Matrix4 multiply(const Matrix4& a, const Matrix4& b);
bool is_identity(const Matrix4& m);

/// Places the instances of the nested glist `ref` once per instance of `outer`: static
/// outer instances compose their matrix with the inner one; a dynamic outer instance moves
/// every part, each part's inner placement baked into a copy of its mesh.
void place_nested(const model::FileRef& ref, const std::vector<model::Instance>& outer,
                  const ReadOptions& options, model::Scene& scene, SceneLoad& load,
                  const std::vector<MaterialScope>& scopes, Diagnostics& diagnostics);

/// Reads an object's `<basesource>` (one `<pointsource matid="…">`, its material a point
/// source within `within`): one model::PointSource per instance of `instances`, appended to
/// scene.point_sources.
void read_base_source(const io::XmlNode& base, const std::string& object_name,
                      const std::vector<model::Instance>& instances,
                      const std::vector<MaterialScope>& within, model::Scene& scene,
                      const SceneLoad& load, Diagnostics& diagnostics);

/// Places a nested glist's point sources `inner` once per instance of `outer`, as
/// place_nested places its instances.
void place_nested_sources(const std::vector<model::PointSource>& inner,
                          const std::vector<model::Instance>& outer, model::Scene& scene,
                          Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
