// SPDX-License-Identifier: Apache-2.0
// Reader of DIRSIG `<classicscene>` `.scene` files: the geodetic scene origin, the material
// database (`matfilename`, read first so geometry can bind to it), the geometry and object
// database directories and every enabled `geometrylistinclude`; and the OBJ files of YAML
// scenes.
#include "glint/dirsig/scene_reader.h"

#include "glint/core/text.h"
#include "glint/io/xml.h"
#include "glist_parts.h"
#include "map_parts.h"

namespace glint::dirsig {
namespace {

void read_origin(const io::XmlNode& node, model::Scene& scene, Diagnostics& diagnostics) {
    node.warn_unknown_children({"location"}, diagnostics);
    const auto location = node.child("location");
    if (!location) {
        diagnostics.error(node.where(), "missing required element <location>");
        return;
    }
    location->warn_unknown_children({"latitude", "longitude", "altitude"}, diagnostics);
    if (const auto frame = location->attribute("frame"); frame && *frame != "geodetic") {
        diagnostics.error(location->where_attribute("frame"),
                          "location frame \"" + *frame + "\" is not supported, expected geodetic");
        return;
    }
    model::SceneOrigin origin;
    origin.where = location->where();
    origin.latitude_deg =
        location->required_double("latitude", diagnostics, io::NumberRule::range(-90.0, 90.0))
            .value_or(0.0);
    origin.longitude_deg =
        location->required_double("longitude", diagnostics, io::NumberRule::range(-180.0, 180.0))
            .value_or(0.0);
    origin.altitude_m = location->optional_double("altitude", diagnostics).value_or(0.0);
    scene.origin = origin;
}

/// Resolves a path element of the scene file; an error at it when the file does not exist.
std::optional<std::filesystem::path> existing(const io::XmlNode& node, const std::string& text,
                                              const std::filesystem::path& base_dir,
                                              const ReadOptions& options, const std::string& what,
                                              Diagnostics& diagnostics) {
    const model::FileRef ref = options.paths.resolve(text, base_dir, node.where(), diagnostics);
    if (ref.resolved.empty()) return std::nullopt;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(ref.resolved, ec)) {
        diagnostics.error(node.where(),
                          what + " " + text + " not found (" + ref.resolved.string() + ")");
        return std::nullopt;
    }
    return ref.resolved;
}

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace

model::Scene read_dirsig_scene(const std::filesystem::path& file, const ReadOptions& options,
                               Diagnostics& diagnostics) {
    model::Scene scene;
    scene.file = file.string();
    ReadOptions local = options;
    const std::filesystem::path base_dir = std::filesystem::absolute(file).parent_path();
    if (!local.paths.scene_dir) local.paths.scene_dir = base_dir;
    try {
        const io::XmlDocument document =
            io::XmlDocument::parse(local.read_text(file, scene.file), scene.file);
        const io::XmlNode root = document.root("classicscene");
        root.warn_unknown_children(
            {"metadata", "sceneorigin", "properties", "thumbnaillist", "landmarks", "odbdirectory",
             "gdbdirectory", "geometrylist", "matfilename", "emsdirectory", "extdirectory",
             "absdirectory", "srcdirectory", "mapdirectory", "maplist"},
            diagnostics);
        if (const auto origin = root.child("sceneorigin")) read_origin(*origin, scene, diagnostics);
        const auto mats = root.children("matfilename");
        if (mats.size() > 1) {
            diagnostics.error(mats[1].where(), "more than one <matfilename>");
        }
        if (mats.empty()) {
            diagnostics.error(root.where(), "missing required element <matfilename>");
        } else if (const auto path = existing(mats.front(), mats.front().text(), base_dir, local,
                                              "material file", diagnostics)) {
            scene.materials = read_dirsig_materials(*path, local, diagnostics);
        }
        detail::read_property_maps(root, base_dir, local, scene, diagnostics);
        detail::SceneLoad load;
        load.global_materials = scene.materials.size();
        detail::read_database_dirs(root, base_dir, local, load, diagnostics);
        for (const io::XmlNode& list : root.children("geometrylist")) {
            if (list.attribute_bool("enabled", diagnostics) == false) continue;
            list.warn_unknown_children({"geometrylistinclude"}, diagnostics);
            for (const io::XmlNode& include : list.children("geometrylistinclude")) {
                if (include.attribute_bool("enabled", diagnostics) == false) continue;
                const std::string text = include.text();
                if (text.empty()) {
                    diagnostics.error(include.where(), "empty geometry list path");
                    continue;
                }
                const std::string ext = lower_extension(text);
                if (ext == ".odb" || ext == ".gdb") {
                    diagnostics.error(include.where(), ext.substr(1) + " geometry (" + text +
                                                           ") is not supported; convert it to "
                                                           "a .glist of OBJ geometry");
                    continue;
                }
                const model::FileRef ref = detail::find_file(
                    text, base_dir, detail::search_paths_local(include, diagnostics),
                    detail::FileKind::glist, "geometry list", include.where(), local, load,
                    diagnostics);
                if (!ref.resolved.empty()) {
                    detail::read_glist_file(ref.resolved, local, scene, diagnostics, load, {});
                }
            }
        }
        document.warn_unread(diagnostics);
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    return scene;
}

model::Mesh load_obj_mesh(const std::filesystem::path& file, const std::string& display_name,
                          const ReadOptions& options, const mesh::MaterialLookup& material_index,
                          std::optional<std::uint32_t> default_material, std::size_t material_count,
                          Diagnostics& diagnostics) {
    const std::string name = display_name.empty() ? file.string() : display_name;
    const std::optional<std::string> read = options.read_text_reported(file, name, diagnostics);
    if (!read) return {};
    const std::string& text = *read;
    return mesh::parse_obj_mesh(text, name, material_index, default_material, material_count,
                                diagnostics);
}

}  // namespace glint::dirsig
