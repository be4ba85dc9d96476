// SPDX-License-Identifier: Apache-2.0
// Property maps (DIRSIG's `<maplist>`, docs/maps.md): images whose texels choose, per hit,
// among a scene's materials. A map applies to the facets whose material is in its
// `applies_to` list; a projector places its image on them (draped vertically in the scene's
// x–y plane, or through the facets' texture coordinates), and the texel under a hit decides:
//   - a material map: one material per texel, through a digital-count look-up table;
//   - a mixture map: a weight per material per texel (the image's bands), the surface being
//     that mix (the radiance the weighted mean, the abundance truth the weights);
//   - a texture map: the texel's relative brightness in one or more spectral windows picks,
//     per material, the texture class (a curve of its multi-curve `.ems`) whose brightness
//     there matches best (DIRSIG's statistical texture);
//   - a temperature map (a material's `TEMP_SOLVER_NAME = Map` in its `.mat`): the surface's
//     temperature, interpolated between texel centres, in place of the material's;
//   - a bump map: a height field whose slope tilts the shading normal (the geometry, and so
//     every shadow, stays the facets').
// Plain data: the readers fill it (images decoded into compact rasters), the scene component
// evaluates it per hit.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/model/common.h"

namespace glint::model {

/// What a projection does beyond the image's edge, along one image axis.
enum class MapExtend {
    none,    ///< nothing: the facet keeps its own material there
    clamp,   ///< the edge texel continues
    repeat,  ///< the image tiles
    mirror,  ///< the image tiles, every other copy mirrored (seamless)
};

/// Where the image's first texel lies. `cartesian`: the lower-left corner (columns run +x,
/// rows run +y, the image upright in the scene's east–north plane; v = 0 is the bottom
/// line). `image`: the upper-left corner (rows run −y; v = 0 is the top line).
enum class MapOrigin { cartesian, image };

/// How a map's image is laid on the surface.
struct MapProjector {
    /// True: through the facets' texture coordinates (OBJ `vt`), u ∈ [0, 1] across the
    /// image's width and v ∈ [0, 1] across its height. False: draped vertically.
    bool uv = false;
    MapOrigin origin = MapOrigin::cartesian;
    bool flip_x = false;  ///< mirror the columns (after the origin)
    bool flip_y = false;  ///< mirror the lines (after the origin)
    MapExtend extend_x = MapExtend::none;
    MapExtend extend_y = MapExtend::none;
    /// Drape: the scene point (east, north, m) where the image's origin corner lies.
    std::array<double, 2> insert_point_m{};
    /// Drape: a texel's size on the ground (east, north), m.
    std::array<double, 2> gsd_m{1.0, 1.0};
    ErrorContext where;
};

/// A map image as its texels select: a class raster (each texel's digital count, looked up
/// in `slot_of_code`) or a weight raster (`bands` floats per texel). Line 0 is the file's top
/// line.
struct MapRaster {
    std::size_t width = 0;
    std::size_t height = 0;
    /// Class rasters: each texel's code, `code_bytes` bytes (big-endian when 2) every
    /// `code_stride` bytes, line after line — a binary PGM/PPM's own bytes, memory-mapped (only
    /// the pages rays touch are read), or codes decoded from another format.
    std::shared_ptr<const std::uint8_t> codes;
    std::size_t code_bytes = 1;
    std::size_t code_stride = 1;
    /// Class rasters: the slot (into the map's `slot_materials`) of each code the image holds.
    std::vector<std::uint16_t> slot_of_code;
    /// Weight rasters: width × height × bands weights, each texel's summing to 1 (or all 0:
    /// no material, the facet keeps its own); texture maps: each texel's z-score per band;
    /// temperature maps: each texel's temperature, K; bump maps: each texel's height, m.
    std::vector<float> weights;
    std::size_t bands = 0;

    /// A class raster's code at `texel` (width · line + column).
    std::uint32_t code(std::uint64_t texel) const noexcept {
        const std::uint8_t* p = codes.get() + texel * code_stride;
        return code_bytes == 1 ? p[0] : (std::uint32_t{p[0]} << 8) | p[1];
    }
    /// A class raster's slot at `texel`.
    std::uint32_t slot(std::uint64_t texel) const noexcept { return slot_of_code[code(texel)]; }
};

enum class MapKind { material, mixture, texture, temperature, bump };

/// One `<band>` of a texture map: a spectral window and the image of the scene's relative
/// brightness in it.
struct TextureBand {
    double min_um = 0.0;
    double max_um = 0.0;
    FileRef image;
};

/// A texture map's classes for one material it covers: the material and its texture-class
/// variants (class 0 is the material itself), and each class's z-score per band (the class's
/// mean reflectance in the band's window, standardised over the classes), classes × bands.
struct TextureClasses {
    std::vector<std::uint32_t> materials;
    std::vector<float> z;
};

/// One `<materialmap>`, `<mixturemap>` or `<texturemap>`.
struct PropertyMap {
    MapKind kind = MapKind::material;
    std::string name;
    /// The facets it applies to: indices into Scene::materials.
    std::vector<std::uint32_t> applies_to;
    MapProjector projector;
    FileRef image;
    /// Material maps: the look-up table as written, DC → material index.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> dc_materials;
    /// Mixture maps: the material of each image band, in band order.
    std::vector<std::uint32_t> band_materials;
    /// What a raster slot selects: material maps, the distinct materials of the table
    /// (a texel's slot indexes it); mixture maps, band_materials.
    std::vector<std::uint32_t> slot_materials;
    /// Texture maps: the bands (their images' texels' z-scores fill the raster's weights, one
    /// per band), and the classes of each material of `applies_to`, in its order.
    std::vector<TextureBand> bands;
    std::vector<TextureClasses> texture_classes;
    /// Shared: every capture's scene holds the same decoded image.
    std::shared_ptr<const MapRaster> raster;
    ErrorContext where;
};

/// The name `kind` is written with in a scene file ("materialmap", "mixturemap").
const char* map_element_name(MapKind kind);

struct Material;

/// One line describing a map for glint-platform2jsim --check: its kind and name, image size,
/// projector, and the materials it covers and selects (by id; `materials` is the scene's),
/// e.g. `materialmap "Classes": 4 x 6 texels, drape 0.2 x 0.2 m from (-0.8, 0.6), origin
/// image, extend none/none, over 1, selects 11, 12, 13`.
std::string describe_map(const PropertyMap& map, const std::vector<Material>& materials);

}  // namespace glint::model
