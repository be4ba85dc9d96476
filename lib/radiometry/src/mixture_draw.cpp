// SPDX-License-Identifier: Apache-2.0
// Drawing a material from a mixture map's texel (glint/radiometry/mixture_draw.h).
#include "glint/radiometry/mixture_draw.h"

namespace glint::radiometry {

std::uint32_t draw_from_mix(const scene::MaterialMix& mix, double u) noexcept {
    double sum = 0.0;
    std::size_t last = 0;
    for (std::size_t k = 0; k < mix.weights.size(); ++k) {
        if (!(mix.weights[k] > 0.0f)) continue;
        sum += mix.weights[k];
        last = k;
        if (u < sum) return mix.materials[k];
    }
    return mix.materials[last];
}

}  // namespace glint::radiometry
