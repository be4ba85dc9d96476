// SPDX-License-Identifier: Apache-2.0
// Shadow rays through clear sheets (panes: materials whose transmittance passes straight
// through, Bsdf::straight()). A next-event estimate towards the sun, a point source or a
// lidar transmitter that meets a pane is not blocked: the light arrives attenuated by the
// pane's τ(λ) per band. Only scenes with a clear sheet pay for it (MaterialTable::
// any_straight()); docs/materials.md.
#pragma once

#include <span>

#include "glint/radiometry/materials.h"
#include "glint/scene/geometry_scene.h"

namespace glint::radiometry {

/// The most clear sheets one shadow ray passes before it counts as blocked.
inline constexpr int kMaxClearSheets = 64;

/// Follows the shadow ray origin_m + s · direction, 0 < s < distance_m, at `time_s`: false
/// when a surface other than a clear sheet (or more than kMaxClearSheets sheets) lies on it;
/// otherwise true, with `attenuation` (one value per grid band) multiplied by the τ(λ) of each
/// clear sheet passed.
bool pass_clear_sheets(const scene::GeometryScene& scene, const MaterialTable& materials,
                       Vec3 origin_m, const Vec3& direction, double time_s, double distance_m,
                       std::span<double> attenuation);

}  // namespace glint::radiometry
