// SPDX-License-Identifier: Apache-2.0
// Point sources (a vehicle's lights, a beacon): isotropic emitters of spectral intensity
// I(λ) [W/(sr µm)] at fixed scene positions, sampled on the tracer's spectral grid. The path
// tracer lights every surface vertex by next-event estimation towards each of them: one
// shadow ray per source, irradiance E(λ) = I(λ) cos θ / r² on the surface (θ from its
// normal, r the distance; no atmosphere between surfaces, as for every path inside the
// scene). A source is a point: no ray hits it (the camera sees it through the sensor
// library's seen_point_sources, docs/physics.md "Point sources seen by the camera").
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "glint/motion/geometry.h"

namespace glint::radiometry {

/// The point sources of a scene on one spectral grid. Held flat ([source][band]).
class PointLights {
public:
    /// An empty list for `bands` bands.
    explicit PointLights(std::size_t bands) : m_bands(bands) {}

    /// Adds a source at `position_m` (scene ENU) of intensity `intensity_w_per_sr_um` (one
    /// value per band). Throws glint::Error (input, naming `name`) for a wrong band count,
    /// a negative or non-finite intensity or a non-finite position.
    void add(const std::string& name, const motion::Vec3& position_m,
             std::span<const double> intensity_w_per_sr_um);

    std::size_t size() const noexcept { return m_positions.size(); }
    std::size_t bands() const noexcept { return m_bands; }
    bool empty() const noexcept { return m_positions.empty(); }
    const motion::Vec3& position_m(std::size_t i) const noexcept { return m_positions[i]; }
    std::span<const double> intensity_w_per_sr_um(std::size_t i) const noexcept {
        return {m_intensity.data() + i * m_bands, m_bands};
    }

private:
    std::size_t m_bands = 0;
    std::vector<motion::Vec3> m_positions;
    std::vector<double> m_intensity;
};

}  // namespace glint::radiometry
