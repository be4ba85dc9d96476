// SPDX-License-Identifier: Apache-2.0
// A scene's property maps evaluated at a hit (docs/maps.md): the projector finds the texel
// under the hit (nearest texel: the maps hold classes and per-texel mixes), and the maps
// that apply to the hit's material change it — a material map to the texel's material, a
// texture map to the texture class nearest the texel's brightness, a mixture map to the
// texel's mix of materials, which the radiometry samples; a temperature map gives the hit a
// temperature, a bump map a slope that tilts its shading normal.
//
// Maps apply in the scene's order: a material map's result can be mapped again by a later
// map (DIRSIG chains a land-cover map and the maps of its classes); a mixture ends the chain.
//
// Thread safety: const after construction; the rasters are shared, read-only.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "glint/model/maps.h"
#include "glint/model/scene.h"

namespace glint::scene {

/// The texel (column, line; line 0 the image's top) a projection puts at the continuous
/// image position (s, t), measured in texels from the image's origin corner: s along its
/// columns, t along its lines away from the origin (up for a cartesian origin, down for an
/// image origin). Extend modes, then flips, as docs/maps.md. Nullopt: off the image where
/// the mode is `none`, or not finite.
std::optional<std::array<std::size_t, 2>> map_texel(const model::MapProjector& projector,
                                                    std::size_t width, std::size_t height, double s,
                                                    double t) noexcept;

/// (s, t) of a drape projector at scene point (x_m, y_m).
std::array<double, 2> drape_position(const model::MapProjector& projector, std::size_t width,
                                     std::size_t height, double x_m, double y_m) noexcept;

/// (s, t) of a uv projector at texture coordinates (u, v).
std::array<double, 2> uv_position(const model::MapProjector& projector, std::size_t width,
                                  std::size_t height, double u, double v) noexcept;

/// A hit's texel of a mixture map (RayHit::mixture_map, mixture_texel).
inline constexpr std::uint32_t kNoMixture = 0xffffffffu;

/// A texel's mix: the materials (indices into the scene's materials) and their weights
/// (summing to 1), in the map's band order, zero weights included.
struct MaterialMix {
    std::span<const std::uint32_t> materials;
    std::span<const float> weights;
};

/// Where a hit lies, for the maps: its scene position and, on a triangle with texture
/// coordinates, those interpolated at the hit.
struct MapPoint {
    double x_m = 0.0;
    double y_m = 0.0;
    std::optional<std::array<double, 2>> uv;
};

class SurfaceMaps {
public:
    SurfaceMaps() = default;
    /// The scene's maps (they share its rasters). Throws glint::Error (input, at the map)
    /// for a map whose raster is missing or whose material indices are out of range.
    explicit SurfaceMaps(const model::Scene& scene);

    bool empty() const noexcept { return m_maps.empty(); }
    /// Some map projects through texture coordinates.
    bool uses_uv() const noexcept { return m_uses_uv; }
    /// Some map applies to material `m` (or to a material a map turns it into).
    bool maps_material(std::uint32_t m) const noexcept {
        return m < m_mapped.size() && m_mapped[m] != 0;
    }

    /// What the maps make of a hit.
    struct Applied {
        std::uint32_t material = 0;
        std::uint32_t mixture_map = kNoMixture;  ///< a mixture's map, else kNoMixture
        std::uint64_t mixture_texel = 0;
        double temperature_k = 0.0;  ///< a temperature map's value, else 0 (the material's)
        /// Bump maps: the height field's slope (∂h/∂x, ∂h/∂y, m/m) at the point.
        bool bumped = false;
        double slope_x = 0.0;
        double slope_y = 0.0;
    };

    /// Applies the maps to a hit on material `material` at `point`.
    Applied apply(const MapPoint& point, std::uint32_t material) const noexcept;

    /// The mix of a hit that apply() gave a mixture.
    MaterialMix mix(std::uint32_t mixture_map, std::uint64_t mixture_texel) const noexcept;

private:
    static constexpr std::uint32_t kNone = 0xffffffffu;
    /// The texel under `point` of map `k`, as width · line + column.
    std::optional<std::uint64_t> texel(std::size_t k, const MapPoint& point) const noexcept;
    /// A one-band map's value at `point`, bilinear between texel centres (the nearest texel
    /// where a neighbour is off the image); nullopt off the image.
    static std::optional<double> bilinear(const model::PropertyMap& map,
                                          const MapPoint& point) noexcept;
    /// A bump map's slope at `point` (central differences of the bilinear heights over one
    /// texel), added to `out`; nothing off the image.
    static void add_slope(const model::PropertyMap& map, const MapPoint& point,
                          Applied& out) noexcept;

    std::vector<model::PropertyMap> m_maps;
    /// Per material, per map (material-major): 0 when the map does not apply, else 1 + the
    /// material's place in the map's applies_to (a texture map's classes are found by it).
    std::vector<std::uint32_t> m_applies;
    /// Per material: the first map that applies, kNone if none.
    std::vector<std::uint32_t> m_first_map;
    /// Per material: its temperature map, if any (shared with the scene's material).
    std::vector<std::shared_ptr<const model::PropertyMap>> m_temperature;
    /// Per material: some map applies to it or to what the maps make of it.
    std::vector<std::uint8_t> m_mapped;
    bool m_uses_uv = false;
};

}  // namespace glint::scene
