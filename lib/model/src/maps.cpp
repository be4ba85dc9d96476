// SPDX-License-Identifier: Apache-2.0
// Property maps (glint/model/maps.h).
#include "glint/model/maps.h"

#include <algorithm>
#include <cmath>

#include "glint/core/text.h"
#include "glint/model/scene.h"

namespace glint::model {

const char* map_element_name(MapKind kind) {
    switch (kind) {
        case MapKind::mixture:
            return "mixturemap";
        case MapKind::texture:
            return "texturemap";
        case MapKind::temperature:
            return "temperature map";
        case MapKind::bump:
            return "bumpmap";
        case MapKind::material:
            break;
    }
    return "materialmap";
}

namespace {

const char* extend_name(MapExtend extend) {
    switch (extend) {
        case MapExtend::clamp:
            return "clamp";
        case MapExtend::repeat:
            return "repeat";
        case MapExtend::mirror:
            return "mirror";
        case MapExtend::none:
            break;
    }
    return "none";
}

std::string ids(const std::vector<std::uint32_t>& indices, const std::vector<Material>& materials) {
    std::string out;
    for (const std::uint32_t m : indices) {
        out += (out.empty() ? "" : ", ") + (m < materials.size() ? materials[m].id : "?");
    }
    return out;
}

}  // namespace

std::string describe_map(const PropertyMap& map, const std::vector<Material>& materials) {
    const MapProjector& p = map.projector;
    std::string out = std::string(map_element_name(map.kind)) + " \"" + map.name + "\": ";
    if (map.raster) {
        out += std::to_string(map.raster->width) + " x " + std::to_string(map.raster->height) +
               " texels" +
               (map.kind != MapKind::material ? " x " + std::to_string(map.raster->bands) +
                                                    (map.raster->bands == 1 ? " band" : " bands")
                                              : std::string()) +
               ", ";
    }
    if (p.uv) {
        out += "uv";
    } else {
        out += "drape " + format_shortest(p.gsd_m[0]) + " x " + format_shortest(p.gsd_m[1]) +
               " m from (" + format_shortest(p.insert_point_m[0]) + ", " +
               format_shortest(p.insert_point_m[1]) + ")";
    }
    out += std::string(", origin ") + (p.origin == MapOrigin::image ? "image" : "cartesian") +
           (p.flip_x ? ", flipx" : "") + (p.flip_y ? ", flipy" : "") + ", extend " +
           extend_name(p.extend_x) + "/" + extend_name(p.extend_y) + ", over " +
           ids(map.applies_to, materials);
    if (map.kind == MapKind::temperature) {
        // Over its own material; its range instead of the materials.
        out.erase(out.rfind(", over "));
        if (map.raster && !map.raster->weights.empty()) {
            const auto [lo, hi] =
                std::minmax_element(map.raster->weights.begin(), map.raster->weights.end());
            out += ", " + format_shortest(std::round(*lo * 100.0) / 100.0) + "-" +
                   format_shortest(std::round(*hi * 100.0) / 100.0) + " K";
        }
    } else if (map.kind == MapKind::bump) {
        if (map.raster && !map.raster->weights.empty()) {
            const auto [lo, hi] =
                std::minmax_element(map.raster->weights.begin(), map.raster->weights.end());
            out += ", heights " + format_shortest(std::round(*lo * 1e4) / 1e4) + "-" +
                   format_shortest(std::round(*hi * 1e4) / 1e4) + " m";
        }
    } else if (map.kind == MapKind::texture) {
        std::size_t classes = 0;
        for (const TextureClasses& c : map.texture_classes) classes += c.materials.size();
        out += ", " + std::to_string(classes) + " texture classes";
    } else {
        out += ", selects " + ids(map.slot_materials, materials);
    }
    return out;
}

}  // namespace glint::model
