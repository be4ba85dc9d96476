// SPDX-License-Identifier: Apache-2.0
// PointLights (glint/radiometry/point_lights.h).
#include "glint/radiometry/point_lights.h"

#include <cmath>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::radiometry {

void PointLights::add(const std::string& name, const motion::Vec3& position_m,
                      std::span<const double> intensity_w_per_sr_um) {
    if (intensity_w_per_sr_um.size() != m_bands) {
        throw input_error("point source " + quote(name) + " has " +
                          std::to_string(intensity_w_per_sr_um.size()) + " intensity values for " +
                          std::to_string(m_bands) + " bands");
    }
    if (!std::isfinite(position_m.x) || !std::isfinite(position_m.y) ||
        !std::isfinite(position_m.z)) {
        throw input_error("point source " + quote(name) + " has a non-finite position");
    }
    for (const double v : intensity_w_per_sr_um) {
        if (!(v >= 0.0) || !std::isfinite(v)) {
            throw input_error("point source " + quote(name) + " has intensity " +
                              format_shortest(v) + " W/(sr um); it must be finite and >= 0");
        }
    }
    m_positions.push_back(position_m);
    m_intensity.insert(m_intensity.end(), intensity_w_per_sr_um.begin(),
                       intensity_w_per_sr_um.end());
}

}  // namespace glint::radiometry
