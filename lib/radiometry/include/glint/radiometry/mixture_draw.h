// SPDX-License-Identifier: Apache-2.0
// A mixture map's texel at a hit, turned into one material per path: the material is drawn
// with probability its weight, so the radiance's expectation is the weighted mean of the pure
// materials' radiances (linear mixing) and each path stays a path through one surface. The
// hit keeps its mixture (RayHit::mixture_map), so truth records the weights, not the draw.
#pragma once

#include "glint/core/rng.h"
#include "glint/scene/geometry_scene.h"

namespace glint::radiometry {

/// The material drawn from `mix` at `u` ∈ [0, 1): the first whose cumulative weight passes u
/// (the last with a weight > 0 when rounding leaves u beyond the sum).
std::uint32_t draw_from_mix(const scene::MaterialMix& mix, double u) noexcept;

/// On a hit with a mixture, sets hit.material to a material drawn from it (one uniform number
/// from `rng`); any other hit is left as it is and draws nothing.
inline void draw_mixture_material(const scene::GeometryScene& scene, scene::RayHit& hit,
                                  RandomStream& rng) {
    if (hit.mixture_map == scene::kNoMixture) return;
    hit.material =
        draw_from_mix(scene.maps().mix(hit.mixture_map, hit.mixture_texel), rng.uniform());
}

}  // namespace glint::radiometry
