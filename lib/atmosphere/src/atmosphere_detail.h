// SPDX-License-Identifier: Apache-2.0
// What the atmosphere models' sources share (private to lib/atmosphere): the constants, the
// geometry and size checks, and the slant absorber amounts.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/core/error.h"

namespace glint::atmosphere::detail {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegToRad = kPi / 180.0;
/// Top of the parametric atmosphere: above it the optical depth is < 1e-5 of the total.
inline constexpr double kTopOfAtmosphereM = 100'000.0;

inline void check_geometry(const AtmosphereGeometry& g) {
    const std::array<double, 6> values{g.sun_zenith_deg,    g.sun_azimuth_deg, g.surface_altitude_m,
                                       g.sensor_altitude_m, g.view_zenith_deg, g.view_azimuth_deg};
    for (double v : values) {
        if (!std::isfinite(v)) throw input_error("atmosphere query with a non-finite geometry");
    }
}

inline void check_size(const SpectralGrid& grid, std::span<const double> values) {
    if (values.size() != grid.size()) {
        throw input_error("solar irradiance has " + std::to_string(values.size()) +
                          " values for a grid of " + std::to_string(grid.size()));
    }
}

inline bool sun_up(const AtmosphereGeometry& g) { return g.sun_zenith_deg < 90.0; }

inline std::vector<double> filled(const SpectralGrid& grid, double value) {
    return std::vector<double>(grid.size(), value);
}

/// Slant amounts: the vertical amounts between two altitudes (`above_low` − `above_high`)
/// times the air mass `m`.
inline GasAmounts slant(const GasAmounts& above_low, const GasAmounts& above_high, double m) {
    return GasAmounts{std::max(above_low.water_cm - above_high.water_cm, 0.0) * m,
                      std::max(above_low.ozone_atm_cm - above_high.ozone_atm_cm, 0.0) * m,
                      std::max(above_low.mixed_air_masses - above_high.mixed_air_masses, 0.0) * m};
}

}  // namespace glint::atmosphere::detail
