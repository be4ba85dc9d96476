// SPDX-License-Identifier: Apache-2.0
// A `<bumpmap>` (map_parts.h; docs/maps.md): an image of heights whose slope tilts the
// shading normal. `<scale>` is the height, in metres, of an integer image's largest count
// (white) or of a floating-point image's 1.0; heights are scale × value. DIRSIG names a
// scale without publishing its element: glint's reading, said once per scene file.
#include <string>

#include "glint/core/text.h"
#include "map_parts.h"

namespace glint::dirsig::detail {

bool read_bump_scale(const io::XmlNode& map_node, double& scale_m, Diagnostics& diagnostics) {
    const auto scale = map_node.required_double("scale", diagnostics, io::NumberRule::any());
    if (!scale) return false;
    if (!(*scale != 0.0) || !std::isfinite(*scale)) {
        diagnostics.error(map_node.child("scale")->where(), "<scale> " + format_shortest(*scale) +
                                                                " is not a finite non-zero "
                                                                "height in metres");
        return false;
    }
    scale_m = *scale;
    return true;
}

bool make_bump(model::PropertyMap& map, double scale_m, Diagnostics& diagnostics) {
    if (map.projector.uv) {
        diagnostics.error(map.projector.where,
                          map_label_text(map) +
                              ": a bump map through texture coordinates is not supported (its "
                              "slopes need the facets' texel size); give it a <drapeprojector>");
        return false;
    }
    std::optional<MapBrightness> image = read_brightness(map, map.image, diagnostics);
    if (!image) return false;
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = image->width;
    raster->height = image->height;
    raster->bands = 1;
    raster->weights.resize(image->values.size());
    const double per_value = image->integer ? scale_m / image->max_code : scale_m;
    for (std::size_t t = 0; t < image->values.size(); ++t) {
        raster->weights[t] = static_cast<float>(per_value * image->values[t]);
    }
    map.raster = raster;
    return true;
}

}  // namespace glint::dirsig::detail
