// SPDX-License-Identifier: Apache-2.0
// ViewRefraction: refracted view rays (glint/radiometry/view_refraction.h).
#include "glint/radiometry/view_refraction.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glint/core/error.h"

namespace glint::radiometry {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

/// The flat atmosphere's laws, which the tables are stored relative to (smooth ratios near 1,
/// where the quantities themselves grow steeply towards the horizon): the displacement ∝
/// tan z / cos² z, the zenith change ∝ tan z (from n sin z = const over flat layers).
double displacement_law(double zenith_deg) {
    const double z = zenith_deg / kDegreesPerRadian;
    return std::tan(z) / (std::cos(z) * std::cos(z));
}
double zenith_law(double zenith_deg) { return std::tan(zenith_deg / kDegreesPerRadian); }

}  // namespace

ViewRefraction::ViewRefraction(const glint::atmosphere::RefractionTracer& tracer,
                               double ground_altitude_m, double sensor_altitude_m)
    : m_wavelength_um(tracer.profile().wavelength_um()) {
    if (!std::isfinite(ground_altitude_m) || !std::isfinite(sensor_altitude_m) ||
        ground_altitude_m < 0.0 || !(sensor_altitude_m > ground_altitude_m)) {
        throw input_error("refracted view rays need a sensor above the ground (ground " +
                          std::to_string(ground_altitude_m) + " m, sensor " +
                          std::to_string(sensor_altitude_m) + " m above sea level)");
    }
    // The straight ray's nadir angle at the sensor for its zenith θ at the ground, by the sine
    // rule in the triangle of the Earth's centre, the sensor and the ground point.
    const double ratio = (tracer.earth_radius_m() + ground_altitude_m) /
                         (tracer.earth_radius_m() + sensor_altitude_m);
    const auto nodes = static_cast<std::size_t>(std::lround(kMaxZenithDeg / kZenithStepDeg)) + 1;
    for (std::size_t k = 0; k < nodes; ++k) {
        const double zenith_deg = static_cast<double>(k) * kZenithStepDeg;
        const double nadir_deg =
            std::asin(std::min(ratio * std::sin(zenith_deg / kDegreesPerRadian), 1.0)) *
            kDegreesPerRadian;
        const glint::atmosphere::GroundIntersection g =
            tracer.ground_intersection(sensor_altitude_m, nadir_deg, ground_altitude_m);
        if (k == 0) continue;  // the ratios' limit at 0 is taken from the next node
        m_displacement_m.push_back(g.displacement_m / displacement_law(zenith_deg));
        m_zenith_change_deg.push_back((g.view_zenith_deg - g.straight_view_zenith_deg) /
                                      zenith_law(zenith_deg));
        if (k == 1) {
            m_displacement_m.insert(m_displacement_m.begin(), m_displacement_m.front());
            m_zenith_change_deg.insert(m_zenith_change_deg.begin(), m_zenith_change_deg.front());
        }
    }
}

double ViewRefraction::at(const std::vector<double>& table, double zenith_deg) const noexcept {
    if (!(zenith_deg >= 0.0) || !(zenith_deg <= kMaxZenithDeg)) return 0.0;
    const double x = zenith_deg / kZenithStepDeg;
    const auto lo = std::min(static_cast<std::size_t>(x), table.size() - 2);
    const double f = x - static_cast<double>(lo);
    return (1.0 - f) * table[lo] + f * table[lo + 1];
}

double ViewRefraction::displacement_m(double straight_zenith_deg) const noexcept {
    return at(m_displacement_m, straight_zenith_deg) * displacement_law(straight_zenith_deg);
}

double ViewRefraction::zenith_change_deg(double straight_zenith_deg) const noexcept {
    return at(m_zenith_change_deg, straight_zenith_deg) * zenith_law(straight_zenith_deg);
}

SampleRay ViewRefraction::bend(const SampleRay& ray) const noexcept {
    const Vec3& o = ray.origin_m;
    const Vec3& d = ray.direction;
    if (!(d.z < 0.0) || !(o.z > 0.0)) return ray;
    const double zenith_deg = std::acos(std::clamp(-d.z, -1.0, 1.0)) * kDegreesPerRadian;
    if (!(zenith_deg < kMaxZenithDeg)) return ray;
    const double t = -o.z / d.z;  // along the ray to the ground plane
    const Vec3 ground{o.x + t * d.x, o.y + t * d.y, 0.0};
    const double horizontal = std::hypot(d.x, d.y);
    if (!(horizontal > 0.0)) return ray;  // nadir: nothing moves
    // The unit horizontal direction of travel, away from the sensor.
    const Vec3 away{d.x / horizontal, d.y / horizontal, 0.0};
    const double shift_m = displacement_m(zenith_deg);
    const double bent_rad = (zenith_deg + zenith_change_deg(zenith_deg)) / kDegreesPerRadian;
    const Vec3 bent{std::sin(bent_rad) * away.x, std::sin(bent_rad) * away.y, -std::cos(bent_rad)};
    const Vec3 crossing = ground - away * shift_m;
    SampleRay out = ray;
    out.direction = bent;
    out.origin_m = crossing - bent * t;
    return out;
}

}  // namespace glint::radiometry
