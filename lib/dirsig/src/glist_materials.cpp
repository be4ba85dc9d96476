// SPDX-License-Identifier: Apache-2.0
// Material scopes of glist objects: `<localmaterials>` (a `.mat` whose materials bind only
// inside the object's base geometry, nested glists included; DIRSIG's bundled objects) and
// `<assign id="ID">objmtl</assign>` (OBJ `usemtl objmtl` binds to material ID), and the
// lookups of `matid` and `usemtl` through them: innermost scope first, then the scene's own.
#include <algorithm>

#include "glint/core/text.h"
#include "glint/dirsig/scene_reader.h"
#include "glist_parts.h"

namespace glint::dirsig::detail {
namespace {

bool id_taken(const model::Scene& scene, const std::string& id) {
    for (const model::Material& m : scene.materials) {
        if (m.id == id) return true;
    }
    return false;
}

/// Reads a localmaterials file once per load, appending its materials to the scene. A
/// material whose id the scene already uses is stored as "ID@file.mat" (then "…#2", …), so
/// that Scene::materials keeps unique ids; glist lookups still use the id as written.
const std::vector<LocalMaterial>& local_file(const std::filesystem::path& path,
                                             const ReadOptions& options, model::Scene& scene,
                                             SceneLoad& load, Diagnostics& diagnostics) {
    const auto found = load.local_files.find(path);
    if (found != load.local_files.end()) return found->second;
    std::vector<LocalMaterial> locals;
    for (model::Material& m : read_dirsig_materials(path, options, diagnostics)) {
        LocalMaterial local{m.id, m.name, static_cast<std::uint32_t>(scene.materials.size())};
        if (id_taken(scene, m.id)) {
            const std::string base = m.id + "@" + path.filename().string();
            std::string id = base;
            for (int n = 2; id_taken(scene, id); ++n) id = base + "#" + std::to_string(n);
            m.id = id;
        }
        scene.materials.push_back(std::move(m));
        locals.push_back(std::move(local));
    }
    return load.local_files.emplace(path, std::move(locals)).first->second;
}

std::optional<std::uint32_t> in_scopes(const std::vector<MaterialScope>& scopes,
                                       const std::string& text, bool by_name) {
    for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
        for (const LocalMaterial& m : scope->locals) {
            if ((by_name ? m.name : m.id) == text) return m.index;
        }
    }
    return std::nullopt;
}

std::optional<std::uint32_t> in_scene(const model::Scene& scene, const SceneLoad& load,
                                      const std::string& text, bool by_name) {
    const std::size_t n = std::min(load.global_materials, scene.materials.size());
    for (std::size_t i = 0; i < n; ++i) {
        if ((by_name ? scene.materials[i].name : scene.materials[i].id) == text) {
            return static_cast<std::uint32_t>(i);
        }
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::uint32_t> material_by_id(const std::string& id, const model::Scene& scene,
                                            const SceneLoad& load,
                                            const std::vector<MaterialScope>& scopes) {
    if (const auto local = in_scopes(scopes, id, false)) return local;
    return in_scene(scene, load, id, false);
}

std::optional<std::uint32_t> material_for_usemtl(const std::string& name, const model::Scene& scene,
                                                 const SceneLoad& load,
                                                 const std::vector<MaterialScope>& scopes) {
    for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
        for (const Assignment& a : scope->assignments) {
            if (a.obj_name == name) return a.material;
        }
    }
    if (const auto local = in_scopes(scopes, name, false)) return local;
    if (const auto local = in_scopes(scopes, name, true)) return local;
    if (const auto global = in_scene(scene, load, name, false)) return global;
    return in_scene(scene, load, name, true);
}

std::optional<MaterialScope> read_material_scope(const io::XmlNode& object,
                                                 std::optional<io::XmlNode> obj,
                                                 const std::filesystem::path& base_dir, bool local,
                                                 const ReadOptions& options, model::Scene& scene,
                                                 SceneLoad& load,
                                                 const std::vector<MaterialScope>& outer,
                                                 Diagnostics& diagnostics) {
    const std::vector<io::XmlNode> files = object.children("localmaterials");
    std::vector<io::XmlNode> assigns = object.children("assign");
    if (obj) {
        for (io::XmlNode& a : obj->children("assign")) assigns.push_back(std::move(a));
    }
    if (files.empty() && assigns.empty()) return std::nullopt;

    MaterialScope scope;
    for (const io::XmlNode& node : files) {
        if (node.text().empty()) {
            diagnostics.error(node.where(), "empty localmaterials path");
            continue;
        }
        const model::FileRef ref =
            find_file(node.text(), base_dir, local, FileKind::plain, "local material file",
                      node.where(), options, load, diagnostics);
        if (ref.resolved.empty()) continue;
        const std::vector<LocalMaterial>& locals =
            local_file(ref.resolved, options, scene, load, diagnostics);
        scope.locals.insert(scope.locals.end(), locals.begin(), locals.end());
        scope.key += "m:" + ref.resolved.string() + "\n";
    }
    std::vector<MaterialScope> scopes = outer;
    scopes.push_back(scope);
    for (const io::XmlNode& node : assigns) {
        const auto id = node.attribute("id");
        if (!id || id->empty()) {
            diagnostics.error(node.where(), "missing attribute id (the material id assigned)");
            continue;
        }
        if (node.text().empty()) {
            diagnostics.error(node.where(), "empty assign: expected the OBJ material name");
            continue;
        }
        const auto index = material_by_id(*id, scene, load, scopes);
        if (!index) {
            diagnostics.error(node.where_attribute("id"), "unknown material id " + quote(*id));
            continue;
        }
        scope.assignments.push_back({node.text(), *index});
        scope.key += "a:" + node.text() + "=" + std::to_string(*index) + "\n";
    }
    return scope;
}

}  // namespace glint::dirsig::detail
