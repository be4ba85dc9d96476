// SPDX-License-Identifier: Apache-2.0
// The procedural terrain and buildings of glint-bench (procedural_scene.h).
#include "procedural_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/rng.h"

namespace glint::bench {
namespace {

/// Key of the random stream that places the buildings (fixed: the scene ignores --seed).
constexpr std::uint64_t kSceneSeed = 20240611;

model::Mesh terrain_mesh(unsigned quads, double size_m) {
    model::Mesh mesh;
    const unsigned side = quads + 1;
    const double step_m = size_m / quads;
    const double start_m = -0.5 * size_m;
    mesh.vertices_m.reserve(static_cast<std::size_t>(side) * side);
    for (unsigned j = 0; j < side; ++j) {
        for (unsigned i = 0; i < side; ++i) {
            const double x = start_m + i * step_m;
            const double y = start_m + j * step_m;
            mesh.vertices_m.push_back({static_cast<float>(x), static_cast<float>(y),
                                       static_cast<float>(terrain_height_m(x, y))});
        }
    }
    mesh.triangles.reserve(2 * static_cast<std::size_t>(quads) * quads);
    for (unsigned j = 0; j < quads; ++j) {
        for (unsigned i = 0; i < quads; ++i) {
            const std::uint32_t v00 = j * side + i;
            const std::uint32_t v10 = v00 + 1;
            const std::uint32_t v01 = v00 + side;
            const std::uint32_t v11 = v01 + 1;
            // Counter-clockwise seen from above: the front face points up.
            mesh.triangles.push_back({v00, v10, v11});
            mesh.triangles.push_back({v00, v11, v01});
        }
    }
    mesh.triangle_materials.assign(mesh.triangles.size(), 0);
    return mesh;
}

/// The unit box [-0.5, 0.5]² × [0, 1], outward faces counter-clockwise.
model::Mesh box_mesh(std::uint32_t material) {
    model::Mesh mesh;
    for (int v = 0; v < 8; ++v) {  // index = x + 2y + 4z
        mesh.vertices_m.push_back(
            {(v & 1) ? 0.5f : -0.5f, (v & 2) ? 0.5f : -0.5f, (v & 4) ? 1.0f : 0.0f});
    }
    mesh.triangles = {{0, 2, 3}, {0, 3, 1},   // bottom (−z)
                      {4, 5, 7}, {4, 7, 6},   // top (+z)
                      {0, 1, 5}, {0, 5, 4},   // south (−y)
                      {2, 6, 7}, {2, 7, 3},   // north (+y)
                      {0, 4, 6}, {0, 6, 2},   // west (−x)
                      {1, 3, 7}, {1, 7, 5}};  // east (+x)
    mesh.triangle_materials.assign(mesh.triangles.size(), material);
    return mesh;
}

}  // namespace

double terrain_height_m(double x_m, double y_m) noexcept {
    constexpr double k = 2.0 * std::numbers::pi;
    return 40.0 * std::sin(k * x_m / 1500.0) * std::cos(k * y_m / 1100.0) +
           15.0 * std::sin(k * (x_m + y_m) / 430.0) + 5.0 * std::cos(k * (x_m - 2.0 * y_m) / 170.0);
}

ProceduralScene build_procedural_scene(const SceneParameters& p) {
    ProceduralScene out;
    model::Scene& scene = out.scene;
    scene.file = "(procedural)";
    scene.materials.push_back(model::flat_material("soil", 0.25));
    scene.materials.push_back(model::flat_material("roof", 0.35, model::kDefaultTemperature_k,
                                                   std::nullopt, {0.15, 0.25}));

    model::GeometryObject terrain;
    terrain.name = "terrain";
    terrain.mesh = terrain_mesh(p.terrain_quads, p.terrain_size_m);
    out.terrain_triangles = terrain.mesh.triangles.size();
    scene.objects.push_back(std::move(terrain));
    model::Instance ground;
    ground.object_index = 0;
    ground.name = "terrain";
    scene.instances.push_back(std::move(ground));

    if (p.buildings == 0) return out;
    model::GeometryObject box;
    box.name = "building";
    box.mesh = box_mesh(1);
    out.building_triangles = box.mesh.triangles.size();
    scene.objects.push_back(std::move(box));

    // A jittered grid of cells over the inner 90 % of the terrain, one building per cell.
    const auto per_side = static_cast<unsigned>(std::ceil(std::sqrt(double(p.buildings))));
    const double cell_m = 0.9 * p.terrain_size_m / per_side;
    const double start_m = -0.45 * p.terrain_size_m;
    scene.instances.reserve(scene.instances.size() + p.buildings);
    for (unsigned b = 0; b < p.buildings; ++b) {
        RandomStream rng(kSceneSeed, {b});
        const double width_m = std::min(0.7 * cell_m, 12.0 + 23.0 * rng.uniform());
        const double depth_m = std::min(0.7 * cell_m, 12.0 + 23.0 * rng.uniform());
        const double height_m = 6.0 + 39.0 * rng.uniform();
        const double heading_rad = 2.0 * std::numbers::pi * rng.uniform();
        const double margin_m = 0.5 * cell_m - 0.5 * std::hypot(width_m, depth_m);
        const double jitter_x = std::max(0.0, margin_m) * (2.0 * rng.uniform() - 1.0);
        const double jitter_y = std::max(0.0, margin_m) * (2.0 * rng.uniform() - 1.0);
        const double x = start_m + ((b % per_side) + 0.5) * cell_m + jitter_x;
        const double y = start_m + ((b / per_side) + 0.5) * cell_m + jitter_y;

        model::Instance instance;
        instance.object_index = 1;
        instance.name = "building" + std::to_string(b);
        instance.transform.translation_m = {x, y, terrain_height_m(x, y) - 2.0};
        instance.transform.rotation_rad = {0.0, 0.0, heading_rad};
        instance.transform.scale = {width_m, depth_m, height_m + 2.0};
        scene.instances.push_back(std::move(instance));
    }
    return out;
}

}  // namespace glint::bench
