// SPDX-License-Identifier: Apache-2.0
// Tests of property maps at a hit (glint/scene/surface_maps.h): each extend mode and flip on
// a crafted axis, the two origins of a drape and of uv coordinates, and maps applied by a
// built GeometryScene — a material map over a plate reproducing its image texel for texel, a
// uv map on a textured quad, maps chained in order, and a mixture map's texel handed out.
#include "glint/scene/surface_maps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "geometry_scene_builders.h"

namespace glint::scene::test {
namespace surface_maps_test {

using model::MapExtend;
using Texel = std::optional<std::array<std::size_t, 2>>;

model::MapProjector projector(MapExtend x, MapExtend y, bool flip_x = false, bool flip_y = false) {
    model::MapProjector p;
    p.origin = model::MapOrigin::image;  // t counts lines from the top: the texel is (s, t)
    p.extend_x = x;
    p.extend_y = y;
    p.flip_x = flip_x;
    p.flip_y = flip_y;
    return p;
}

std::optional<std::size_t> column(MapExtend mode, double s) {
    const Texel at = map_texel(projector(mode, MapExtend::none), 4, 2, s, 0.5);
    if (!at) return std::nullopt;
    return (*at)[0];
}

TEST(MapTexel, ExtendModesAlongAnAxisOfFour) {
    // Inside, every mode gives the texel under the point.
    for (const MapExtend mode :
         {MapExtend::none, MapExtend::clamp, MapExtend::repeat, MapExtend::mirror}) {
        EXPECT_EQ(column(mode, 0.0), 0u);
        EXPECT_EQ(column(mode, 2.5), 2u);
        EXPECT_EQ(column(mode, 3.999), 3u);
    }
    EXPECT_EQ(column(MapExtend::none, -0.001), std::nullopt);
    EXPECT_EQ(column(MapExtend::none, 4.0), std::nullopt);
    EXPECT_EQ(column(MapExtend::clamp, -7.0), 0u);
    EXPECT_EQ(column(MapExtend::clamp, 9.0), 3u);
    // repeat: ... 2 3 | 0 1 2 3 | 0 1 ...
    EXPECT_EQ(column(MapExtend::repeat, 4.2), 0u);
    EXPECT_EQ(column(MapExtend::repeat, 7.5), 3u);
    EXPECT_EQ(column(MapExtend::repeat, -0.5), 3u);
    EXPECT_EQ(column(MapExtend::repeat, -4.5), 3u);
    // mirror: ... 1 0 | 0 1 2 3 | 3 2 1 0 | 0 1 ... (the edge texel repeated)
    EXPECT_EQ(column(MapExtend::mirror, 4.2), 3u);
    EXPECT_EQ(column(MapExtend::mirror, 6.5), 1u);
    EXPECT_EQ(column(MapExtend::mirror, 7.9), 0u);
    EXPECT_EQ(column(MapExtend::mirror, 8.1), 0u);
    EXPECT_EQ(column(MapExtend::mirror, -0.5), 0u);
    EXPECT_EQ(column(MapExtend::mirror, -1.5), 1u);
    EXPECT_EQ(column(MapExtend::none, std::nan("")), std::nullopt);
    // Far beyond the image (texture coordinates of 10³⁰): still a texel of the image.
    EXPECT_LT(*column(MapExtend::repeat, -1e30), 4u);
    EXPECT_LT(*column(MapExtend::mirror, 1e30), 4u);
    EXPECT_EQ(column(MapExtend::repeat, INFINITY), std::nullopt);
}

TEST(MapTexel, FlipsAndOrigins) {
    const model::MapProjector plain = projector(MapExtend::none, MapExtend::none);
    EXPECT_EQ(map_texel(plain, 4, 2, 0.5, 0.5), (Texel{{0, 0}}));
    EXPECT_EQ(map_texel(projector(MapExtend::none, MapExtend::none, true, false), 4, 2, 0.5, 0.5),
              (Texel{{3, 0}}));
    EXPECT_EQ(map_texel(projector(MapExtend::none, MapExtend::none, false, true), 4, 2, 0.5, 0.5),
              (Texel{{0, 1}}));
    // A cartesian origin counts t up from the bottom line.
    model::MapProjector cartesian = plain;
    cartesian.origin = model::MapOrigin::cartesian;
    EXPECT_EQ(map_texel(cartesian, 4, 2, 0.5, 0.5), (Texel{{0, 1}}));
    EXPECT_EQ(map_texel(cartesian, 4, 2, 0.5, 1.5), (Texel{{0, 0}}));
}

TEST(MapTexel, DrapePositionsOfBothOrigins) {
    model::MapProjector p;
    p.insert_point_m = {-10.0, 20.0};
    p.gsd_m = {2.0, 0.5};
    p.origin = model::MapOrigin::cartesian;
    EXPECT_EQ(drape_position(p, 8, 8, -6.0, 21.0), (std::array<double, 2>{2.0, 2.0}));
    p.origin = model::MapOrigin::image;  // the insert point is the upper-left corner
    EXPECT_EQ(drape_position(p, 8, 8, -6.0, 19.0), (std::array<double, 2>{2.0, 2.0}));
    EXPECT_EQ(uv_position(p, 8, 4, 0.25, 0.5), (std::array<double, 2>{2.0, 2.0}));
}

/// A 4 × 3 class raster with slots 0..2 in the given order (line 0 first).
std::shared_ptr<model::MapRaster> class_raster(std::size_t width,
                                               const std::vector<std::uint8_t>& slots) {
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = width;
    raster->height = slots.size() / width;
    // Codes are the slots themselves.
    auto codes = std::shared_ptr<std::uint8_t>(new std::uint8_t[slots.size()],
                                               std::default_delete<std::uint8_t[]>());
    std::copy(slots.begin(), slots.end(), codes.get());
    raster->codes = codes;
    raster->slot_of_code.resize(256);
    for (std::size_t c = 0; c < 256; ++c) raster->slot_of_code[c] = static_cast<std::uint16_t>(c);
    return raster;
}

/// A material map over materials {0} selecting slot k → material 1 + k.
model::PropertyMap material_map(std::shared_ptr<model::MapRaster> raster,
                                model::MapProjector projector, std::uint32_t applies_to = 0,
                                std::vector<std::uint32_t> slots = {1, 2, 3}) {
    model::PropertyMap map;
    map.kind = model::MapKind::material;
    map.name = "classes";
    map.applies_to = {applies_to};
    map.slot_materials = std::move(slots);
    map.projector = projector;
    map.raster = std::move(raster);
    return map;
}

TEST(SurfaceMaps, MaterialMapOverAPlateTexelForTexel) {
    model::Scene scene = scene_with_materials(4);
    add_static(scene, add_object(scene, ground_plane_mesh(100.0, 0), "plate"));
    const std::vector<std::uint8_t> slots{0, 1, 2, 0, 2, 2, 1, 1, 1, 0, 0, 2};
    model::MapProjector p;  // cartesian drape, 2 m texels, lower-left corner at (-4, -3)
    p.insert_point_m = {-4.0, -3.0};
    p.gsd_m = {2.0, 2.0};
    scene.maps.push_back(material_map(class_raster(4, slots), p));
    const GeometryScene built = build(scene);
    for (std::size_t line = 0; line < 3; ++line) {
        for (std::size_t col = 0; col < 4; ++col) {
            // The texel's centre: line 0 is the northernmost.
            const double x = -4.0 + 2.0 * static_cast<double>(col) + 1.0;
            const double y = -3.0 + 2.0 * static_cast<double>(2 - line) + 1.0;
            const auto hit = built.intersect({x, y, 10.0}, kDown, 0.0);
            ASSERT_TRUE(hit);
            EXPECT_EQ(hit->material, 1u + slots[line * 4 + col]) << col << ", " << line;
            EXPECT_EQ(hit->mixture_map, kNoMixture);
        }
    }
    // Off the image (extend none): the plate's own material.
    EXPECT_EQ(built.intersect({-4.5, 0.0, 10.0}, kDown, 0.0)->material, 0u);
    EXPECT_EQ(built.intersect({0.0, 3.5, 10.0}, kDown, 0.0)->material, 0u);
}

TEST(SurfaceMaps, UvMapOnATexturedQuadAndChainedMaps) {
    model::Scene scene = scene_with_materials(6);
    model::Mesh quad = quad_mesh({0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {0, 2, 0}, 0);
    // u runs along x, v along y: corners (0,0) (1,0) (1,1) (0,1).
    quad.triangle_uvs = {{0, 0, 1, 0, 1, 1}, {0, 0, 1, 1, 0, 1}};
    add_static(scene, add_object(scene, quad, "quad"));
    model::MapProjector uv;
    uv.uv = true;
    uv.origin = model::MapOrigin::cartesian;  // v = 0: the bottom line
    scene.maps.push_back(material_map(class_raster(2, {0, 1, 2, 0}), uv));
    // A later map splits material 3 (slot 2's) by halves: chained after the first.
    model::MapProjector drape;
    drape.gsd_m = {2.0, 10.0};
    scene.maps.push_back(material_map(class_raster(2, {0, 1}), drape, 3, {4, 5}));
    const GeometryScene built = build(scene);
    // Bottom line (v < 0.5): slots 2, 0 → materials 3 → (by the drape: x < 2 → 4) and 1.
    EXPECT_EQ(built.intersect({1.0, 0.5, 5.0}, kDown, 0.0)->material, 4u);
    EXPECT_EQ(built.intersect({3.0, 0.5, 5.0}, kDown, 0.0)->material, 1u);
    // Top line: slots 0, 1 → 1, 2.
    EXPECT_EQ(built.intersect({1.0, 1.5, 5.0}, kDown, 0.0)->material, 1u);
    EXPECT_EQ(built.intersect({3.0, 1.5, 5.0}, kDown, 0.0)->material, 2u);
}

TEST(SurfaceMaps, MixtureTexelAndAnEmptyOne) {
    model::Scene scene = scene_with_materials(3);
    add_static(scene, add_object(scene, ground_plane_mesh(100.0, 0), "plate"));
    model::PropertyMap map;
    map.kind = model::MapKind::mixture;
    map.name = "mix";
    map.applies_to = {0};
    map.band_materials = map.slot_materials = {1, 2};
    map.projector.gsd_m = {1.0, 1.0};
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = 2;
    raster->height = 1;
    raster->bands = 2;
    raster->weights = {0.25f, 0.75f, 0.0f, 0.0f};
    map.raster = raster;
    scene.maps.push_back(map);
    const GeometryScene built = build(scene);
    const auto mixed = built.intersect({0.5, 0.5, 5.0}, kDown, 0.0);
    ASSERT_NE(mixed->mixture_map, kNoMixture);
    const MaterialMix mix = built.maps().mix(mixed->mixture_map, mixed->mixture_texel);
    ASSERT_EQ(mix.weights.size(), 2u);
    EXPECT_EQ(mix.materials[0], 1u);
    EXPECT_EQ(mix.weights[1], 0.75f);
    // An all-zero texel: no mixture, the plate's material.
    const auto empty = built.intersect({1.5, 0.5, 5.0}, kDown, 0.0);
    EXPECT_EQ(empty->mixture_map, kNoMixture);
    EXPECT_EQ(empty->material, 0u);
}

TEST(SurfaceMaps, TextureMapPicksTheNearestClassOverItsBands) {
    model::Scene scene = scene_with_materials(4);
    add_static(scene, add_object(scene, ground_plane_mesh(100.0, 0), "plate"));
    model::PropertyMap map;
    map.kind = model::MapKind::texture;
    map.name = "texture";
    map.applies_to = {0};
    map.bands.resize(2);
    map.projector.gsd_m = {1.0, 1.0};
    // Classes 0 (the material), 2 and 3 at z (−1, 0), (0, 1), (1, 0); four texels.
    map.texture_classes = {model::TextureClasses{{0, 2, 3}, {-1, 0, 0, 1, 1, 0}}};
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = 4;
    raster->height = 1;
    raster->bands = 2;
    // Nearest: class 3; class 0; class 2 (z₂ decides); the tie at (−0.5, 0.5) between
    // classes 0 and 2 goes to the first.
    raster->weights = {0.9f, 0.2f, -2.0f, 0.0f, 0.1f, 0.8f, -0.5f, 0.5f};
    map.raster = raster;
    scene.maps.push_back(map);
    const GeometryScene built = build(scene);
    const std::uint32_t expected[] = {3, 0, 2, 0};
    for (int x = 0; x < 4; ++x) {
        EXPECT_EQ(built.intersect({x + 0.5, 0.5, 5.0}, kDown, 0.0)->material, expected[x]) << x;
    }
}

TEST(SurfaceMaps, TemperatureMapBilinearBetweenTexelCentres) {
    model::Scene scene = scene_with_materials(2);
    add_static(scene, add_object(scene, ground_plane_mesh(100.0, 0), "plate"));
    auto map = std::make_shared<model::PropertyMap>();
    map->kind = model::MapKind::temperature;
    map->projector.gsd_m = {1.0, 1.0};  // cartesian drape from (0, 0): line 0 is y 1..2
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = 2;
    raster->height = 2;
    raster->bands = 1;
    raster->weights = {300.0f, 310.0f, 280.0f, 290.0f};  // top line, then bottom line
    map->raster = raster;
    scene.materials[0].temperature_map = map;
    const GeometryScene built = build(scene);
    // Texel centres: the texels' values.
    EXPECT_NEAR(built.intersect({0.5, 0.5, 5.0}, kDown, 0.0)->temperature_k, 280.0, 1e-9);
    EXPECT_NEAR(built.intersect({1.5, 1.5, 5.0}, kDown, 0.0)->temperature_k, 310.0, 1e-9);
    // Between the four centres: their mean; a quarter of the way: bilinear.
    EXPECT_NEAR(built.intersect({1.0, 1.0, 5.0}, kDown, 0.0)->temperature_k, 295.0, 1e-9);
    EXPECT_NEAR(built.intersect({0.75, 0.5, 5.0}, kDown, 0.0)->temperature_k, 282.5, 1e-9);
    // Within half a texel of the edge (extend none): the nearest texel; off it: none (0).
    EXPECT_NEAR(built.intersect({0.2, 1.8, 5.0}, kDown, 0.0)->temperature_k, 300.0, 1e-9);
    EXPECT_EQ(built.intersect({2.5, 1.0, 5.0}, kDown, 0.0)->temperature_k, 0.0);
    // The material stays: a temperature map changes only the temperature.
    EXPECT_EQ(built.intersect({1.0, 1.0, 5.0}, kDown, 0.0)->material, 0u);
}

TEST(SurfaceMaps, BumpMapTiltsTheShadingNormalByItsSlope) {
    model::Scene scene = scene_with_materials(2);
    add_static(scene, add_object(scene, ground_plane_mesh(100.0, 0), "plate"));
    // Heights 0.2 x + 0.1 y on 3 x 3 texels of 2 m from (-3, -3) (cartesian): a plane.
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = 3;
    raster->height = 3;
    raster->bands = 1;
    for (int line = 0; line < 3; ++line) {
        for (int col = 0; col < 3; ++col) {
            const double x = -2.0 + 2.0 * col;
            const double y = 2.0 - 2.0 * line;  // line 0 is the top (north) line
            raster->weights.push_back(static_cast<float>(0.2 * x + 0.1 * y));
        }
    }
    model::PropertyMap map;
    map.kind = model::MapKind::bump;
    map.name = "bumps";
    map.applies_to = {0};
    map.projector.insert_point_m = {-3.0, -3.0};
    map.projector.gsd_m = {2.0, 2.0};
    map.raster = raster;
    scene.maps.push_back(map);
    const GeometryScene built = build(scene);
    const auto hit = built.intersect({0.3, -0.4, 5.0}, kDown, 0.0);
    ASSERT_TRUE(hit->bumped);
    const double norm = std::sqrt(0.2 * 0.2 + 0.1 * 0.1 + 1.0);
    expect_vec_near(hit->shading_normal, {-0.2 / norm, -0.1 / norm, 1.0 / norm}, 1e-6);
    expect_vec_near(hit->normal, {0.0, 0.0, 1.0}, kNormalTol);  // the geometry's is kept
    // Where a central difference leaves the image: no bump.
    EXPECT_FALSE(built.intersect({2.8, 0.0, 5.0}, kDown, 0.0)->bumped);
}

TEST(SurfaceMaps, RefusesARasterThatDoesNotMatch) {
    model::Scene scene = scene_with_materials(4);
    model::PropertyMap map = material_map(class_raster(4, {0, 1}), {});
    std::const_pointer_cast<model::MapRaster>(map.raster)->slot_of_code.resize(10);
    scene.maps.push_back(map);
    const Error e = error_of([&] { SurfaceMaps maps(scene); });
    EXPECT_EQ(e.category(), ErrorCategory::input);
    EXPECT_NE(e.message().find("raster does not match"), std::string::npos) << e.message();
}

}  // namespace surface_maps_test
}  // namespace glint::scene::test
