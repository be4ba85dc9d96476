// SPDX-License-Identifier: Apache-2.0
// The benchmark's procedural scene: a square terrain heightfield (a smooth, deterministic sum
// of sines, two triangles per grid cell) and one unit box instanced as buildings standing on
// it, each with its own footprint, height and heading. Two spectrally flat materials: a
// Lambertian soil for the terrain and a roof material with a small GGX specular lobe. The
// scene depends only on its parameters (never on --seed), so every run traces the same
// geometry.
#pragma once

#include <cstddef>
#include <cstdint>

#include "glint/model/scene.h"

namespace glint::bench {

/// Size of the procedural scene.
struct SceneParameters {
    unsigned terrain_quads = 710;    ///< grid cells per side (2 triangles each)
    double terrain_size_m = 4000.0;  ///< side of the terrain square, centred on the origin
    unsigned buildings = 4096;       ///< instances of the box, on a jittered square grid
};

/// What build_procedural_scene made, with its triangle counts.
struct ProceduralScene {
    model::Scene scene;
    std::uint64_t terrain_triangles = 0;
    std::uint64_t building_triangles = 0;  ///< of the one box object
    /// Distinct triangles held in memory (terrain + one box).
    std::uint64_t unique_triangles() const noexcept {
        return terrain_triangles + building_triangles;
    }
};

/// Terrain height at (x, y), metres (the function the heightfield samples).
double terrain_height_m(double x_m, double y_m) noexcept;

/// Builds the scene: object 0 the terrain (one identity instance), object 1 the unit box
/// [-0.5, 0.5]² × [0, 1] with `buildings` static instances (scaled, turned about z, set on
/// the terrain and sunk 2 m so slopes leave no gap). Material 0 is the soil, 1 the roof.
ProceduralScene build_procedural_scene(const SceneParameters& parameters);

}  // namespace glint::bench
