// SPDX-License-Identifier: Apache-2.0
// Reader of the glint YAML scene (docs/scene.md): origin, materials (inline or two-column
// file spectra), geometry objects (OBJ or primitive) and their static or dynamic instances,
// and DIRSIG `.glist` geometry lists included with `glists:` (read with read_glist).
// yaml-cpp parses the text; every problem is reported with the YAML file line and the key
// path (e.g. "materials[1].reflectance.values[2]") and the reader carries on.
#include "glint/dirsig/scene_reader.h"

#include "scene_parts.h"
#include "yaml_text.h"

namespace glint::yaml {
namespace {

using namespace yaml_scene;

void read_origin(Reader& r, const YAML::Node& node, model::Scene& scene) {
    if (!r.expect_map(node, "origin")) return;
    r.warn_unknown(node, "origin", {"latitude", "longitude", "altitude"});
    model::SceneOrigin origin;
    origin.where = r.where(node, "origin");
    const auto lat = r.number_key(node, "origin", "latitude", true);
    const auto lon = r.number_key(node, "origin", "longitude", true);
    const auto alt = r.number_key(node, "origin", "altitude", false);
    if (lat && (*lat < -90.0 || *lat > 90.0)) {
        r.error(node["latitude"], "origin.latitude",
                "latitude " + format_shortest(*lat) + " deg is outside [-90, 90]");
    }
    if (lon && (*lon < -180.0 || *lon > 180.0)) {
        r.error(node["longitude"], "origin.longitude",
                "longitude " + format_shortest(*lon) + " deg is outside [-180, 180]");
    }
    origin.latitude_deg = lat.value_or(0.0);
    origin.longitude_deg = lon.value_or(0.0);
    origin.altitude_m = alt.value_or(0.0);
    scene.origin = origin;
}

/// Appends the objects and instances of every `glists[i]` to `scene`, whose materials the
/// glists' `matid` and `usemtl` bind to (by id text).
void read_glists(Reader& r, const YAML::Node& node, model::Scene& scene) {
    if (!node.IsSequence()) {
        r.error(node, "glists", "expected a list of .glist paths");
        return;
    }
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string path = "glists[" + std::to_string(i) + "]";
        const YAML::Node item = node[i];
        if (!item.IsScalar() || item.Scalar().empty()) {
            r.error(item, path, "expected the path of a .glist file");
            continue;
        }
        const model::FileRef ref =
            r.options.paths.resolve(item.Scalar(), r.base_dir, r.where(item, path), r.diagnostics);
        if (ref.resolved.empty()) continue;
        std::error_code ec;
        if (!std::filesystem::is_regular_file(ref.resolved, ec)) {
            r.error(item, path, "glist " + ref.text + " not found (" + ref.resolved.string() + ")");
            continue;
        }
        read_glist(ref.resolved, r.options, scene, r.diagnostics);
    }
}

void read_document(Reader& r, const YAML::Node& root, model::Scene& scene) {
    if (!root.IsMap()) {
        r.error(root, "", "expected a mapping with keys origin, materials, objects and glists");
        return;
    }
    r.warn_unknown(root, "", {"origin", "materials", "objects", "glists"});
    if (const YAML::Node origin = root["origin"]) read_origin(r, origin, scene);

    if (const YAML::Node materials = root["materials"]) {
        if (!materials.IsSequence()) {
            r.error(materials, "materials", "expected a list of materials");
        } else {
            std::set<std::string> ids;
            std::set<std::string> names;
            for (std::size_t i = 0; i < materials.size(); ++i) {
                const std::string path = "materials[" + std::to_string(i) + "]";
                model::Material m = read_material(r, materials[i], path);
                if (!m.id.empty() && !ids.insert(m.id).second) {
                    r.error(materials[i]["id"], path + ".id",
                            "duplicate material id \"" + m.id + "\"");
                }
                if (!m.name.empty() && !names.insert(m.name).second) {
                    r.error(materials[i], path, "duplicate material name \"" + m.name + "\"");
                }
                scene.materials.push_back(std::move(m));
            }
        }
    }

    const YAML::Node objects = root["objects"];
    const YAML::Node glists = root["glists"];
    if (!objects) {
        if (!glists) r.error(root, "", "missing required key \"objects\" (or \"glists\")");
    } else if (!objects.IsSequence()) {
        r.error(objects, "objects", "expected a list of objects");
    } else {
        for (std::size_t i = 0; i < objects.size(); ++i) {
            read_object(r, objects[i], "objects[" + std::to_string(i) + "]", scene);
        }
    }
    if (glists) read_glists(r, glists, scene);
}

}  // namespace

model::Scene read_yaml_scene(const std::filesystem::path& file, const ReadOptions& options,
                             Diagnostics& diagnostics) {
    model::Scene scene;
    scene.file = file.string();
    ReadOptions local = options;
    const std::filesystem::path base_dir = std::filesystem::absolute(file).parent_path();
    if (!local.paths.scene_dir) local.paths.scene_dir = base_dir;
    Reader reader{scene.file, base_dir, local, diagnostics};
    try {
        const std::string text = local.read_text(file, scene.file);
        const std::optional<YAML::Node> root = detail::parse_yaml(text, scene.file, diagnostics);
        if (!root) return scene;
        read_document(reader, *root, scene);
    } catch (const Error& error) {
        diagnostics.add(error);
    } catch (const YAML::Exception& error) {
        diagnostics.error({scene.file, error.mark.line >= 0 ? error.mark.line + 1 : 0, {}},
                          "cannot read YAML: " + error.msg);
    }
    return scene;
}

}  // namespace glint::yaml
