// SPDX-License-Identifier: Apache-2.0
// Moonlight (glint/atmosphere/lunar.h).
#include "glint/atmosphere/lunar.h"

#include <cmath>

#include "glint/core/error.h"

namespace glint::atmosphere {

double lunar_irradiance_ratio(double phase_angle_deg, double distance_km) {
    if (!std::isfinite(phase_angle_deg) || !std::isfinite(distance_km) || distance_km <= 0.0) {
        throw input_error("lunar irradiance needs a finite phase angle and a distance > 0");
    }
    const double a = std::abs(phase_angle_deg);
    const double phase_law = std::pow(10.0, -0.4 * (0.026 * a + 4e-9 * a * a * a * a));
    const double solid = (kMoonRadiusKm / distance_km) * (kMoonRadiusKm / distance_km);
    return kMoonGeometricAlbedo * solid * phase_law;
}

double lunar_angular_radius_rad(double distance_km) {
    if (!std::isfinite(distance_km) || distance_km <= kMoonRadiusKm) {
        throw input_error("the moon's distance must exceed its radius");
    }
    return std::asin(kMoonRadiusKm / distance_km);
}

}  // namespace glint::atmosphere
