// SPDX-License-Identifier: Apache-2.0
// The property maps of a `.scene` (map_parts.h; docs/maps.md): `<mapdirectory>` and the
// `<maplist>`'s `<materialmap>` and `<mixturemap>` elements, each with its `<matidlist>`,
// `<projector>` (`<uvprojector/>` or `<drapeprojector>`) and image. A disabled map is skipped
// whole; the map kinds glint does not apply are errors naming the map.
#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/text.h"
#include "map_parts.h"

namespace glint::dirsig::detail {
namespace {

/// The kinds of DIRSIG map glint knows by name but does not apply.
constexpr std::string_view kRefusedMaps[] = {"temperaturemap", "normalmap", "reflectancemap",
                                             "radiancemap",    "curvemap",  "rgbmap",
                                             "decalmap",       "densitymap"};

/// A `<matid>`'s material, by id; an error at it when the scene has none.
std::optional<std::uint32_t> material_of(const io::XmlNode& node, const model::Scene& scene,
                                         Diagnostics& diagnostics) {
    const std::string id = node.text();
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].id == id) return static_cast<std::uint32_t>(i);
    }
    diagnostics.error(node.where(), "unknown material id " + quote(id) +
                                        (id.empty() ? "" : " (not in the scene's material file)"));
    return std::nullopt;
}

std::optional<model::MapExtend> extend_attribute(const io::XmlNode& node, std::string_view name,
                                                 Diagnostics& diagnostics) {
    const auto value =
        node.attribute_enum(name, {"none", "clamp", "repeat", "mirror"}, diagnostics);
    if (!value) return std::nullopt;
    if (*value == "clamp") return model::MapExtend::clamp;
    if (*value == "repeat") return model::MapExtend::repeat;
    if (*value == "mirror") return model::MapExtend::mirror;
    return model::MapExtend::none;
}

/// A pair of numbers written as `<x>` and `<y>` children (`<z>`, when given, must be a number
/// and is not used: a drape is vertical) or, for a size, one number for both.
std::optional<std::array<double, 2>> read_pair(const io::XmlNode& node, bool single_allowed,
                                               io::NumberRule rule, Diagnostics& diagnostics) {
    if (single_allowed && node.children().empty()) {
        const auto value = node.own_double(diagnostics, rule);
        if (!value) return std::nullopt;
        return std::array<double, 2>{*value, *value};
    }
    node.warn_unknown_children({"x", "y", "z"}, diagnostics);
    const auto x = node.required_double("x", diagnostics, rule);
    const auto y = node.required_double("y", diagnostics, rule);
    (void)node.optional_double("z", diagnostics);
    if (!x || !y) return std::nullopt;
    return std::array<double, 2>{*x, *y};
}

bool read_projector_elements(const io::XmlNode& node, model::MapProjector& projector,
                             Diagnostics& diagnostics) {
    projector.where = node.where();
    node.warn_unknown_children({"uvprojector", "drapeprojector"}, diagnostics);
    if (const auto origin = node.attribute_enum("origin", {"cartesian", "image"}, diagnostics)) {
        projector.origin =
            *origin == "image" ? model::MapOrigin::image : model::MapOrigin::cartesian;
    }
    projector.flip_x = node.attribute_bool("flipx", diagnostics).value_or(false);
    projector.flip_y = node.attribute_bool("flipy", diagnostics).value_or(false);
    projector.extend_x =
        extend_attribute(node, "extendx", diagnostics).value_or(model::MapExtend::none);
    projector.extend_y =
        extend_attribute(node, "extendy", diagnostics).value_or(model::MapExtend::none);
    const auto uv = node.child("uvprojector");
    const auto drape = node.child("drapeprojector");
    if (uv && drape) {
        diagnostics.error(node.where(), "<projector> has both <uvprojector> and <drapeprojector>");
        return false;
    }
    if (uv) {
        uv->warn_unknown_children({}, diagnostics);
        projector.uv = true;
        return true;
    }
    if (!drape) {
        diagnostics.error(node.where(), "<projector> needs <uvprojector/> or <drapeprojector>");
        return false;
    }
    drape->warn_unknown_children({"insertpoint", "gsd"}, diagnostics);
    bool ok = true;
    if (const auto point = drape->child("insertpoint")) {
        const auto xy = read_pair(*point, false, io::NumberRule::any(), diagnostics);
        if (xy) projector.insert_point_m = *xy;
        ok = xy.has_value();
    }
    const auto gsd = drape->child("gsd");
    if (!gsd) {
        diagnostics.error(drape->where(), "missing required element <gsd>");
        return false;
    }
    const auto size = read_pair(*gsd, true, io::NumberRule::positive(), diagnostics);
    if (size) projector.gsd_m = *size;
    return ok && size.has_value();
}

/// The `<projector>`; false after an error in it.
bool read_projector(const io::XmlNode& node, model::MapProjector& projector,
                    Diagnostics& diagnostics) {
    const std::size_t errors = diagnostics.error_count();
    return read_projector_elements(node, projector, diagnostics) &&
           diagnostics.error_count() == errors;
}

/// A list of `<matid>` children of the map's `element`, in order (repeats dropped when
/// `unique`); nullopt after an error (a missing or empty list, an unknown id).
std::optional<std::vector<std::uint32_t>> read_material_list(const io::XmlNode& map_node,
                                                             const char* element, bool unique,
                                                             const model::Scene& scene,
                                                             Diagnostics& diagnostics) {
    const auto list = map_node.child(element);
    if (!list) {
        diagnostics.error(map_node.where(),
                          std::string("missing required element <") + element + ">");
        return std::nullopt;
    }
    list->warn_unknown_children({"matid"}, diagnostics);
    std::vector<std::uint32_t> out;
    bool ok = true;
    for (const io::XmlNode& id : list->children("matid")) {
        const auto m = material_of(id, scene, diagnostics);
        if (!m) {
            ok = false;
        } else if (!unique || std::find(out.begin(), out.end(), *m) == out.end()) {
            out.push_back(*m);
        }
    }
    if (ok && out.empty()) {
        diagnostics.error(list->where(), std::string("<") + element + "> lists no material");
    }
    if (!ok || out.empty()) return std::nullopt;
    return out;
}

bool read_dc_table(const io::XmlNode& map_node, const model::Scene& scene, model::PropertyMap& map,
                   Diagnostics& diagnostics) {
    const auto table = map_node.child("dcmatlut");
    if (!table) {
        diagnostics.error(map_node.where(), "missing required element <dcmatlut>");
        return false;
    }
    table->warn_unknown_children({"entry"}, diagnostics);
    bool ok = true;
    for (const io::XmlNode& entry : table->children("entry")) {
        entry.warn_unknown_children({"dc", "matid"}, diagnostics);
        const auto dc = entry.required_int("dc", diagnostics, 0, 65535);
        const auto id = entry.child("matid");
        if (!id) diagnostics.error(entry.where(), "missing required element <matid>");
        const auto m = id ? material_of(*id, scene, diagnostics) : std::nullopt;
        if (!dc || !m) {
            ok = false;
            continue;
        }
        const auto dc_value = static_cast<std::uint32_t>(*dc);
        for (const auto& [earlier, material] : map.dc_materials) {
            if (earlier == dc_value && material != *m) {
                diagnostics.error(entry.where(), "digital count " + std::to_string(dc_value) +
                                                     " is listed twice, for different materials");
                ok = false;
            }
        }
        map.dc_materials.emplace_back(dc_value, *m);
    }
    if (ok && map.dc_materials.empty()) {
        diagnostics.error(table->where(), "<dcmatlut> has no <entry>");
        return false;
    }
    return ok;
}

/// A clear pane's straight transmission is traced past by shadow rays before any map is
/// looked at, so a map cannot make or unmake one: an error at the map.
bool no_clear_panes(const model::PropertyMap& map, const model::Scene& scene,
                    Diagnostics& diagnostics) {
    std::vector<std::uint32_t> all = map.applies_to;
    all.insert(all.end(), map.slot_materials.begin(), map.slot_materials.end());
    for (const auto& entry : map.dc_materials) all.push_back(entry.second);
    for (const std::uint32_t m : all) {
        if (scene.materials[m].straight_transmission) {
            diagnostics.error(map.where, map_label_text(map) + ": material " +
                                             quote(scene.materials[m].id) +
                                             " is a clear pane (straight transmission), which "
                                             "a map cannot apply to or select");
            return false;
        }
    }
    return true;
}

}  // namespace

std::string map_label_text(const model::PropertyMap& map) {
    if (map.kind == model::MapKind::temperature) {
        return "the temperature map of material " + quote(map.name);
    }
    return std::string("<") + model::map_element_name(map.kind) + "> " + quote(map.name);
}

bool read_image_element(const io::XmlNode& parent, const std::filesystem::path& map_dir,
                        const ReadOptions& options, const model::PropertyMap& map,
                        model::FileRef& image, Diagnostics& diagnostics) {
    const auto element = parent.child("image");
    if (!element) {
        diagnostics.error(parent.where(), "missing required element <image>");
        return false;
    }
    element->warn_unknown_children({"filename"}, diagnostics);
    const auto name = element->child("filename");
    if (!name) {
        diagnostics.error(element->where(), "missing required element <filename>");
        return false;
    }
    image = options.paths.resolve(name->text(), map_dir, name->where(), diagnostics);
    if (image.resolved.empty()) return false;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(image.resolved, ec)) {
        diagnostics.error(name->where(), map_label_text(map) + " image " + quote(image.text) +
                                             " not found (" + image.resolved.string() + ")");
        return false;
    }
    return true;
}

namespace {

/// A map's `<matidlist>` and `<projector>`; false after an error.
bool read_placement(const io::XmlNode& node, const model::Scene& scene, model::PropertyMap& map,
                    bool& warned_drape, Diagnostics& diagnostics) {
    const auto applies_to = read_material_list(node, "matidlist", true, scene, diagnostics);
    if (applies_to) map.applies_to = *applies_to;
    bool ok = applies_to.has_value();
    const auto projector = node.child("projector");
    if (!projector) {
        diagnostics.error(node.where(), "missing required element <projector>");
        return false;
    }
    ok = read_projector(*projector, map.projector, diagnostics) && ok;
    if (!map.projector.uv && !warned_drape) {
        diagnostics.warning(projector->where(),
                            "<drapeprojector> (<insertpoint>, <gsd>) is glint's reading of "
                            "DIRSIG's DRAPE_PROJECTOR keys; check the map's placement "
                            "(docs/maps.md)");
        warned_drape = true;
    }
    return ok;
}

/// What a map of each kind holds besides its placement; false after an error.
bool read_contents(const io::XmlNode& node, const std::filesystem::path& map_dir,
                   const ReadOptions& options, const model::Scene& scene, model::PropertyMap& map,
                   bool& warned_mixture, double& bump_scale_m, Diagnostics& diagnostics) {
    switch (map.kind) {
        case model::MapKind::material:
            return read_dc_table(node, scene, map, diagnostics) &&
                   read_image_element(node, map_dir, options, map, map.image, diagnostics);
        case model::MapKind::texture:
            return read_texture_bands(node, map_dir, options, map, diagnostics);
        case model::MapKind::bump:
            return read_bump_scale(node, bump_scale_m, diagnostics) &&
                   read_image_element(node, map_dir, options, map, map.image, diagnostics);
        case model::MapKind::temperature:
            return false;  // a .mat's, not a <maplist>'s
        case model::MapKind::mixture:
            break;
    }
    if (!warned_mixture) {
        diagnostics.warning(node.where(),
                            "<mixturemap> with <bandmaterials> (a material per image band) is "
                            "glint's reading of DIRSIG's mixture maps (docs/maps.md)");
        warned_mixture = true;
    }
    // `<bandmaterials>`: a mixture map's material per image band, in band order.
    const auto bands = read_material_list(node, "bandmaterials", false, scene, diagnostics);
    if (bands) map.band_materials = map.slot_materials = *bands;
    return read_image_element(node, map_dir, options, map, map.image, diagnostics) &&
           bands.has_value();
}

/// The map's image decoded (a texture map's bands, with its classes); false after an error.
bool decode(model::PropertyMap& map, double bump_scale_m, model::Scene& scene,
            Diagnostics& diagnostics) {
    switch (map.kind) {
        case model::MapKind::bump:
            return make_bump(map, bump_scale_m, diagnostics);
        case model::MapKind::temperature:
            return false;
        case model::MapKind::material:
            map.raster = read_class_raster(map, diagnostics);
            break;
        case model::MapKind::mixture:
            map.raster = read_weight_raster(map, diagnostics);
            break;
        case model::MapKind::texture:
            return make_texture(map, scene, diagnostics);
    }
    return map.raster != nullptr;
}

/// A mixture's material is drawn per path after the maps have been applied, so no map (nor
/// a .mat temperature map) can apply to it: an error at the mixture map for each one that
/// would.
void refuse_mapped_mixtures(const model::Scene& scene, Diagnostics& diagnostics) {
    for (const model::PropertyMap& mixture : scene.maps) {
        if (mixture.kind != model::MapKind::mixture) continue;
        for (const std::uint32_t m : mixture.slot_materials) {
            const model::Material& material = scene.materials[m];
            std::string by;
            for (const model::PropertyMap& other : scene.maps) {
                const auto& covered = other.applies_to;
                if (std::find(covered.begin(), covered.end(), m) != covered.end()) {
                    by = map_label_text(other);
                    break;
                }
            }
            if (by.empty() && material.temperature_map) by = "its temperature map";
            if (by.empty()) continue;
            diagnostics.error(mixture.where,
                              map_label_text(mixture) + ": material " + quote(material.id) +
                                  " is covered by " + by +
                                  ", which cannot apply to a mixture's material (drawn per "
                                  "path after the maps)");
        }
    }
}

}  // namespace

void read_property_maps(const io::XmlNode& root, const std::filesystem::path& base_dir,
                        const ReadOptions& options, model::Scene& scene, Diagnostics& diagnostics) {
    std::filesystem::path map_dir = base_dir;
    if (const auto dir = root.child("mapdirectory")) {
        const model::FileRef ref =
            options.paths.resolve(dir->text(), base_dir, dir->where(), diagnostics);
        std::error_code ec;
        if (!ref.resolved.empty() && !std::filesystem::is_directory(ref.resolved, ec)) {
            diagnostics.error(dir->where(), "map directory " + quote(dir->text()) +
                                                " is not a folder (" + ref.resolved.string() + ")");
        } else if (!ref.resolved.empty()) {
            map_dir = ref.resolved;
        }
    }
    const auto list = root.child("maplist");
    if (!list) return;
    bool warned_drape = false;
    bool warned_mixture = false;
    bool warned_bump = false;
    for (const io::XmlNode& node : list->children()) {
        const std::string& kind = node.name();
        const bool known = kind == "materialmap" || kind == "mixturemap" || kind == "texturemap" ||
                           kind == "bumpmap";
        const bool refused = std::find(std::begin(kRefusedMaps), std::end(kRefusedMaps), kind) !=
                             std::end(kRefusedMaps);
        if (!known && !refused) {
            diagnostics.warning(node.where(), "unknown element <" + kind + "> ignored");
            continue;
        }
        if (node.attribute_bool("enabled", diagnostics) == false) continue;
        model::PropertyMap map;
        map.kind = kind == "mixturemap"   ? model::MapKind::mixture
                   : kind == "texturemap" ? model::MapKind::texture
                   : kind == "bumpmap"    ? model::MapKind::bump
                                          : model::MapKind::material;
        map.name = node.attribute("name").value_or("");
        map.where = node.where();
        if (refused) {
            diagnostics.error(node.where(),
                              "<" + kind + "> " + quote(map.name) +
                                  " is not supported: glint applies material, mixture, "
                                  "texture and bump maps" +
                                  (kind == "temperaturemap"
                                       ? ", and temperature maps given in the material's .mat "
                                         "entry (TEMP_SOLVER_NAME = Map)"
                                       : "") +
                                  " (docs/maps.md); disable it (enabled=\"false\") to render "
                                  "without it");
            continue;
        }
        switch (map.kind) {
            case model::MapKind::material:
                node.warn_unknown_children({"matidlist", "projector", "dcmatlut", "image"},
                                           diagnostics);
                break;
            case model::MapKind::mixture:
                node.warn_unknown_children({"matidlist", "projector", "bandmaterials", "image"},
                                           diagnostics);
                break;
            case model::MapKind::texture:
                node.warn_unknown_children({"matidlist", "projector", "bandlist"}, diagnostics);
                break;
            case model::MapKind::bump:
                node.warn_unknown_children({"matidlist", "projector", "scale", "image"},
                                           diagnostics);
                if (!warned_bump) {
                    diagnostics.warning(node.where(),
                                        "<bumpmap> with <scale> (the height, m, of the image's "
                                        "white) is glint's reading of DIRSIG's bump maps "
                                        "(docs/maps.md)");
                    warned_bump = true;
                }
                break;
            case model::MapKind::temperature:
                break;
        }
        if (map.kind == model::MapKind::material &&
            node.attribute_bool("mixing", diagnostics).value_or(false)) {
            diagnostics.error(node.where_attribute("mixing"),
                              map_label_text(map) +
                                  ": mixing=\"true\" is not supported (DIRSIG does not publish "
                                  "what it blends); use a <mixturemap> for mixed texels");
            continue;
        }
        bool ok = read_placement(node, scene, map, warned_drape, diagnostics);
        double bump_scale_m = 0.0;
        ok = read_contents(node, map_dir, options, scene, map, warned_mixture, bump_scale_m,
                           diagnostics) &&
             ok;
        if (!ok || !no_clear_panes(map, scene, diagnostics)) continue;
        if (decode(map, bump_scale_m, scene, diagnostics)) scene.maps.push_back(std::move(map));
    }
    refuse_mapped_mixtures(scene, diagnostics);
}

}  // namespace glint::dirsig::detail
