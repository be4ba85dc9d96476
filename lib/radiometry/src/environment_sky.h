// SPDX-License-Identifier: Apache-2.0
// The environment's sky tables (environment_sky.cpp), private to glint_radiometry.
#pragma once

#include <memory>
#include <numbers>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/radiometry/environment.h"

namespace glint::radiometry::detail {

inline constexpr double kSkyRadToDeg = 180.0 / std::numbers::pi;

/// The nodes around `cos_zenith` among zenith nodes 0°, kSkyZenithStepDeg … 90° of air masses
/// `air_mass`: linear in the air mass between them (an optically thin band's emission grows
/// as the air mass does, which in the zenith angle is steeply convex towards the horizon);
/// the horizon node at or below it.
AltitudeLevel locate_sky_zenith(const std::vector<double>& air_mass, double cos_zenith);

/// The scattered sky's directional shape at `geometry`'s surface ([zenith node][azimuth
/// node][band], ∫ shape cos dΩ = π per band; a band whose sky is black is 1 everywhere), or
/// null where the model has none or the sky is black; one zenith per task on `threads`
/// threads (0: all), the same numbers whatever the count.
std::shared_ptr<const std::vector<double>> sky_shape(
    const SpectralGrid& grid, const glint::atmosphere::AtmosphereModel& atmosphere,
    const glint::atmosphere::AtmosphereGeometry& geometry, const std::vector<double>& toa,
    const std::vector<double>& air_mass, unsigned threads);

}  // namespace glint::radiometry::detail
