// SPDX-License-Identifier: Apache-2.0
// Shadow rays through clear sheets (glint/radiometry/clear_sheets.h).
#include "glint/radiometry/clear_sheets.h"

#include <limits>

namespace glint::radiometry {

bool pass_clear_sheets(const scene::GeometryScene& scene, const MaterialTable& materials,
                       Vec3 origin_m, const Vec3& direction, double time_s, double distance_m,
                       std::span<double> attenuation) {
    double left_m = distance_m;
    scene::RayHit hit;
    for (int sheet = 0; sheet <= kMaxClearSheets; ++sheet) {
        if (!scene.intersect_into(origin_m, direction, time_s, hit, 0.0, left_m)) return true;
        if (sheet == kMaxClearSheets || !materials.straight(hit.material)) return false;
        const std::span<const double> tau = materials.transmittance(hit.material);
        for (std::size_t b = 0; b < attenuation.size(); ++b) attenuation[b] *= tau[b];
        const Vec3 next = scene.spawn_origin(hit, direction);
        if (left_m != std::numeric_limits<double>::infinity()) left_m -= norm(next - origin_m);
        origin_m = next;
    }
    return false;
}

}  // namespace glint::radiometry
