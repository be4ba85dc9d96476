// SPDX-License-Identifier: Apache-2.0
// Property maps at a hit (glint/scene/surface_maps.h).
#include "glint/scene/surface_maps.h"

#include <cmath>
#include <cstring>
#include <string>

#include "glint/core/error.h"

namespace glint::scene {
namespace {

/// `i` modulo `period`, as an index in [0, last]: rounding (|i| far beyond the period loses
/// its fraction) can leave the remainder just outside, which the clamp takes back.
std::size_t wrapped(double i, double period, std::size_t last) noexcept {
    const double m = i - period * std::floor(i / period);
    if (!(m > 0.0)) return 0;
    return std::min(static_cast<std::size_t>(std::min(m, static_cast<double>(last))), last);
}

/// Texel index `i` of an axis `n` texels long under extend mode `mode`.
std::optional<std::size_t> extend(double i, std::size_t n, model::MapExtend mode) noexcept {
    const double size = static_cast<double>(n);
    if (!std::isfinite(i)) return std::nullopt;
    if (i >= 0.0 && i < size) return static_cast<std::size_t>(i);
    switch (mode) {
        case model::MapExtend::none:
            return std::nullopt;
        case model::MapExtend::clamp:
            return i < 0.0 ? 0 : n - 1;
        case model::MapExtend::repeat:
            return wrapped(i, size, n - 1);
        case model::MapExtend::mirror: {
            const std::size_t m = wrapped(i, 2.0 * size, 2 * n - 1);
            return m < n ? m : 2 * n - 1 - m;
        }
    }
    return std::nullopt;
}

/// The texture class whose z-scores lie nearest the texel's `z` (least squares over the
/// bands; the first on a tie).
std::uint32_t nearest_class(const model::TextureClasses& classes, const float* z,
                            std::size_t bands) noexcept {
    std::size_t best = 0;
    double best_distance = INFINITY;
    for (std::size_t k = 0; k < classes.materials.size(); ++k) {
        double distance = 0.0;
        for (std::size_t b = 0; b < bands; ++b) {
            const double d = double{z[b]} - double{classes.z[k * bands + b]};
            distance += d * d;
        }
        if (distance < best_distance) {
            best_distance = distance;
            best = k;
        }
    }
    return classes.materials[best];
}

}  // namespace

std::optional<std::array<std::size_t, 2>> map_texel(const model::MapProjector& projector,
                                                    std::size_t width, std::size_t height, double s,
                                                    double t) noexcept {
    if (width == 0 || height == 0) return std::nullopt;
    const auto column = extend(std::floor(s), width, projector.extend_x);
    const auto away = extend(std::floor(t), height, projector.extend_y);
    if (!column || !away) return std::nullopt;
    std::size_t x = *column;
    // Lines count down from the top; a cartesian origin's t counts up from the bottom.
    std::size_t y = projector.origin == model::MapOrigin::cartesian ? height - 1 - *away : *away;
    if (projector.flip_x) x = width - 1 - x;
    if (projector.flip_y) y = height - 1 - y;
    return std::array<std::size_t, 2>{x, y};
}

std::array<double, 2> drape_position(const model::MapProjector& projector, std::size_t, std::size_t,
                                     double x_m, double y_m) noexcept {
    const double s = (x_m - projector.insert_point_m[0]) / projector.gsd_m[0];
    const double north = (y_m - projector.insert_point_m[1]) / projector.gsd_m[1];
    // An image origin lies at the upper-left corner: its lines run south.
    return {s, projector.origin == model::MapOrigin::cartesian ? north : -north};
}

std::array<double, 2> uv_position(const model::MapProjector&, std::size_t width, std::size_t height,
                                  double u, double v) noexcept {
    // v runs away from the origin corner's line in either convention (OBJ's v = 0 is the
    // bottom line with a cartesian origin, the top line with an image origin).
    return {u * static_cast<double>(width), v * static_cast<double>(height)};
}

namespace {

/// (s, t) of `point` on `map`'s image by its projector; nullopt for a uv map at a point
/// without texture coordinates.
std::optional<std::array<double, 2>> map_position(const model::PropertyMap& map,
                                                  const MapPoint& point) noexcept {
    const model::MapRaster& raster = *map.raster;
    if (!map.projector.uv) {
        return drape_position(map.projector, raster.width, raster.height, point.x_m, point.y_m);
    }
    if (!point.uv) return std::nullopt;
    return uv_position(map.projector, raster.width, raster.height, (*point.uv)[0], (*point.uv)[1]);
}

}  // namespace

SurfaceMaps::SurfaceMaps(const model::Scene& scene) : m_maps(scene.maps) {
    const std::size_t materials = scene.materials.size();
    m_applies.assign(materials * m_maps.size(), 0);
    m_first_map.assign(materials, kNone);
    for (std::size_t k = 0; k < m_maps.size(); ++k) {
        const model::PropertyMap& map = m_maps[k];
        const std::string what =
            std::string(model::map_element_name(map.kind)) + " \"" + map.name + "\"";
        if (!map.raster) throw input_error(what + " has no image read", map.where);
        const model::MapRaster& raster = *map.raster;
        const std::uint64_t texels = std::uint64_t{raster.width} * raster.height;
        const std::size_t bands = map.kind == model::MapKind::texture ? map.bands.size()
                                  : map.kind == model::MapKind::bump  ? 1
                                                                      : map.slot_materials.size();
        const bool matches =
            map.kind == model::MapKind::material
                ? raster.codes != nullptr && (raster.code_bytes == 1 || raster.code_bytes == 2) &&
                      raster.code_stride >= raster.code_bytes &&
                      raster.slot_of_code.size() == (std::size_t{1} << (8 * raster.code_bytes))
                : raster.weights.size() == texels * raster.bands && raster.bands == bands;
        if (!matches) throw input_error(what + ": its raster does not match its image", map.where);
        std::vector<std::uint32_t> selected = map.slot_materials;
        if (map.kind == model::MapKind::texture) {
            if (map.texture_classes.size() != map.applies_to.size()) {
                throw input_error(what + ": texture classes do not match its materials", map.where);
            }
            for (const model::TextureClasses& c : map.texture_classes) {
                if (c.materials.empty() || c.z.size() != c.materials.size() * bands) {
                    throw input_error(what + ": texture classes do not match its bands", map.where);
                }
                selected.insert(selected.end(), c.materials.begin(), c.materials.end());
            }
        }
        for (const std::uint32_t m : selected) {
            if (m >= materials) throw input_error(what + ": material out of range", map.where);
        }
        for (std::size_t i = 0; i < map.applies_to.size(); ++i) {
            const std::uint32_t m = map.applies_to[i];
            if (m >= materials) throw input_error(what + ": material out of range", map.where);
            m_applies[m * m_maps.size() + k] = static_cast<std::uint32_t>(i + 1);
            if (m_first_map[m] == kNone) m_first_map[m] = static_cast<std::uint32_t>(k);
        }
        if (map.projector.uv) m_uses_uv = true;
    }
    m_temperature.resize(materials);
    m_mapped.assign(materials, 0);
    for (std::size_t m = 0; m < materials; ++m) {
        const auto& map = scene.materials[m].temperature_map;
        if (map) {
            const model::MapRaster* raster = map->raster.get();
            if (raster == nullptr || raster->bands != 1 ||
                raster->weights.size() != raster->width * raster->height) {
                throw input_error("the temperature map of material \"" + scene.materials[m].id +
                                      "\": its raster does not match its image",
                                  map->where);
            }
            m_temperature[m] = map;
            if (map->projector.uv) m_uses_uv = true;
        }
        m_mapped[m] = m_first_map[m] != kNone || map ? 1 : 0;
    }
    // A mixture's material is drawn by the radiometry, after the maps: none may have a
    // temperature map of its own.
    for (const model::PropertyMap& map : m_maps) {
        if (map.kind != model::MapKind::mixture) continue;
        for (const std::uint32_t m : map.slot_materials) {
            if (m_temperature[m]) {
                throw input_error("mixturemap \"" + map.name + "\": material \"" +
                                      scene.materials[m].id +
                                      "\" has a temperature map, which a mixture's materials "
                                      "cannot have",
                                  map.where);
            }
        }
    }
}

std::optional<std::uint64_t> SurfaceMaps::texel(std::size_t k,
                                                const MapPoint& point) const noexcept {
    const model::PropertyMap& map = m_maps[k];
    const model::MapRaster& raster = *map.raster;
    const auto position = map_position(map, point);
    if (!position) return std::nullopt;
    const std::array<double, 2>& st = *position;
    const auto at = map_texel(map.projector, raster.width, raster.height, st[0], st[1]);
    if (!at) return std::nullopt;
    return std::uint64_t{(*at)[1]} * raster.width + (*at)[0];
}

std::optional<double> SurfaceMaps::bilinear(const model::PropertyMap& map,
                                            const MapPoint& point) noexcept {
    const model::MapRaster& raster = *map.raster;
    const auto position = map_position(map, point);
    if (!position) return std::nullopt;
    const std::array<double, 2>& st = *position;
    const auto value = [&](double s, double t) -> std::optional<double> {
        const auto at = map_texel(map.projector, raster.width, raster.height, s, t);
        if (!at) return std::nullopt;
        return raster.weights[(*at)[1] * raster.width + (*at)[0]];
    };
    // Texel centres lie at half-integers: interpolate between the four around (s, t).
    const double s0 = std::floor(st[0] - 0.5);
    const double t0 = std::floor(st[1] - 0.5);
    const double fs = st[0] - 0.5 - s0;
    const double ft = st[1] - 0.5 - t0;
    const auto a = value(s0 + 0.5, t0 + 0.5);
    const auto b = value(s0 + 1.5, t0 + 0.5);
    const auto c = value(s0 + 0.5, t0 + 1.5);
    const auto d = value(s0 + 1.5, t0 + 1.5);
    if (a && b && c && d) {
        return (1.0 - ft) * ((1.0 - fs) * *a + fs * *b) + ft * ((1.0 - fs) * *c + fs * *d);
    }
    return value(st[0], st[1]);
}

void SurfaceMaps::add_slope(const model::PropertyMap& map, const MapPoint& point,
                            Applied& out) noexcept {
    const double gx = map.projector.gsd_m[0];
    const double gy = map.projector.gsd_m[1];
    const auto at = [&](double dx, double dy) {
        return bilinear(map, MapPoint{point.x_m + dx, point.y_m + dy, std::nullopt});
    };
    const auto east = at(0.5 * gx, 0.0);
    const auto west = at(-0.5 * gx, 0.0);
    const auto north = at(0.0, 0.5 * gy);
    const auto south = at(0.0, -0.5 * gy);
    if (!east || !west || !north || !south) return;
    out.bumped = true;
    out.slope_x += (*east - *west) / gx;
    out.slope_y += (*north - *south) / gy;
}

SurfaceMaps::Applied SurfaceMaps::apply(const MapPoint& point,
                                        std::uint32_t material) const noexcept {
    Applied out;
    out.material = material;
    if (!maps_material(material)) return out;
    const std::size_t count = m_maps.size();
    const std::size_t first = m_first_map[material] == kNone ? count : m_first_map[material];
    for (std::size_t k = first; k < count; ++k) {
        const std::uint32_t material_now = out.material;
        if (m_applies[material_now * count + k] == 0) continue;
        const auto at = texel(k, point);
        if (!at) continue;
        const model::PropertyMap& map = m_maps[k];
        const model::MapRaster& raster = *map.raster;
        if (map.kind == model::MapKind::bump) {
            add_slope(map, point, out);
            continue;
        }
        if (map.kind == model::MapKind::mixture) {
            const float* w = raster.weights.data() + *at * raster.bands;
            bool any = false;
            for (std::size_t b = 0; b < raster.bands && !any; ++b) any = w[b] > 0.0f;
            if (!any) continue;  // no material here: the facet keeps its own
            out.mixture_map = static_cast<std::uint32_t>(k);
            out.mixture_texel = *at;
            break;
        }
        if (map.kind == model::MapKind::texture) {
            const model::TextureClasses& classes =
                map.texture_classes[m_applies[material_now * count + k] - 1];
            out.material =
                nearest_class(classes, raster.weights.data() + *at * raster.bands, raster.bands);
            continue;
        }
        const std::uint32_t slot = raster.slot(*at);
        if (slot < map.slot_materials.size()) out.material = map.slot_materials[slot];
    }
    if (out.mixture_map == kNoMixture && m_temperature[out.material]) {
        out.temperature_k = bilinear(*m_temperature[out.material], point).value_or(0.0);
    }
    return out;
}

MaterialMix SurfaceMaps::mix(std::uint32_t mixture_map,
                             std::uint64_t mixture_texel) const noexcept {
    const model::PropertyMap& map = m_maps[mixture_map];
    const model::MapRaster& raster = *map.raster;
    return {
        map.slot_materials,
        std::span<const float>(raster.weights.data() + mixture_texel * raster.bands, raster.bands)};
}

}  // namespace glint::scene
