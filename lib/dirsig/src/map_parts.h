// SPDX-License-Identifier: Apache-2.0
// Internal interface of the `.scene` property-map reader: the `<maplist>` elements
// (map_reader.cpp) and the decoding of their images into rasters (map_images.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/io/xml.h"
#include "glint/model/scene.h"

namespace glint::dirsig::detail {

/// The most texels a map image may hold (2³¹: a 46k × 46k class map, 2 GiB at one byte).
inline constexpr std::uint64_t kMaxMapTexels = std::uint64_t{1} << 31;

/// "<materialmap> \"name\"", for messages.
std::string map_label_text(const model::PropertyMap& map);

/// Reads `<mapdirectory>` and `<maplist>` of a `<classicscene>` into scene.maps, the images
/// decoded. The scene's materials must be read already (maps name them by id).
void read_property_maps(const io::XmlNode& root, const std::filesystem::path& base_dir,
                        const ReadOptions& options, model::Scene& scene, Diagnostics& diagnostics);

/// Decodes a material map's image: each texel's digital count (the first channel, an 8- or
/// 16-bit integer) through map.dc_materials into a slot of map.slot_materials (which it
/// fills). Problems (unreadable image, floating-point values, a count the table lacks) are
/// errors at `map.where` naming the map; nullptr then.
std::shared_ptr<const model::MapRaster> read_class_raster(model::PropertyMap& map,
                                                          Diagnostics& diagnostics);

/// Decodes a mixture map's image: one band per entry of map.band_materials, each texel's
/// weights normalised to sum 1 (all zero: none). Problems are errors at `map.where`; nullptr
/// then.
std::shared_ptr<const model::MapRaster> read_weight_raster(const model::PropertyMap& map,
                                                           Diagnostics& diagnostics);

/// A texture band's image: the first channel's values, line 0 first.
struct MapBrightness {
    std::size_t width = 0;
    std::size_t height = 0;
    std::vector<float> values;
    bool integer = true;  ///< the file holds integer codes (not floating-point values)
    double max_code = 1.0;  ///< an integer image's largest code (255, 65535, a PNM's maxval)
};

/// Reads a texture band's or a temperature map's image (any channels: the first; any type);
/// problems are errors at `map.where`, nullopt then.
std::optional<MapBrightness> read_brightness(const model::PropertyMap& map,
                                             const model::FileRef& image, Diagnostics& diagnostics);

/// Reads a `<texturemap>`'s `<bandlist>` (windows and images, resolved against `map_dir`);
/// false after an error.
bool read_texture_bands(const io::XmlNode& map_node, const std::filesystem::path& map_dir,
                        const ReadOptions& options, model::PropertyMap& map,
                        Diagnostics& diagnostics);

/// A texture map's raster (each texel's z-score per band) and its texture classes: for each
/// material it covers, the material and a variant per further curve of its texture_curves
/// (appended to scene.materials, once per material however many maps cover it), with each
/// class's z-score per band. False after an error.
bool make_texture(model::PropertyMap& map, model::Scene& scene, Diagnostics& diagnostics);

/// A `<bumpmap>`'s `<scale>` (read into `scale_m`): false after an error.
bool read_bump_scale(const io::XmlNode& map_node, double& scale_m, Diagnostics& diagnostics);

/// A bump map's raster: each texel's height, scale_m × its value (an integer image's counts
/// over its largest code). False after an error.
bool make_bump(model::PropertyMap& map, double scale_m, Diagnostics& diagnostics);

/// The `<image><filename>` of `parent` (a map, or a texture map's band), resolved against
/// `map_dir` into `image`; an error when it is missing or does not exist (false).
bool read_image_element(const io::XmlNode& parent, const std::filesystem::path& map_dir,
                        const ReadOptions& options, const model::PropertyMap& map,
                        model::FileRef& image, Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
