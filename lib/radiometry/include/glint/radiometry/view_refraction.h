// SPDX-License-Identifier: Apache-2.0
// The view rays of a sensor above the scene, bent by the air's refraction at one wavelength
// (docs/physics.md, "Refraction in the renderer"). The atmosphere's spherical shells bend a
// view ray towards the ground: it meets the ground nearer the point below the sensor than its
// straight line does, arriving steeper. The scene's own height range is small against the air
// the ray crosses, so the renderer keeps the ray straight inside the scene and corrects it
// where its straight line crosses the scene's ground plane (z = 0, the scene origin's
// altitude): the crossing moves towards the sensor by the refraction's displacement and the
// direction turns to the refracted ray's arrival zenith, both from RefractionTracer's
// ground_intersection at the ray's zenith angle there, tabulated once per sensor altitude and
// wavelength. A ray that does not descend to the ground plane is left straight.
#pragma once

#include <vector>

#include "glint/atmosphere/refraction.h"
#include "glint/radiometry/path_tracer.h"
#include "glint/radiometry/problem.h"

namespace glint::radiometry {

/// The displacement and arrival zenith of refracted view rays for one sensor altitude and
/// wavelength. Immutable; bend() may run from any thread.
class ViewRefraction {
public:
    /// Nodes of the table: the straight ray's zenith angle at the ground, 0° … kMaxZenithDeg.
    static constexpr double kZenithStepDeg = 0.25;
    static constexpr double kMaxZenithDeg = 89.0;

    /// The table for a sensor at `sensor_altitude_m` and the scene's ground at
    /// `ground_altitude_m` (both above sea level, the sensor higher), through `tracer`'s
    /// profile at its wavelength. Throws glint::Error (input) for altitudes out of order or not
    /// finite, and what the tracer throws.
    ViewRefraction(const glint::atmosphere::RefractionTracer& tracer, double ground_altitude_m,
                   double sensor_altitude_m);

    /// The wavelength the table is for, µm.
    double wavelength_um() const noexcept { return m_wavelength_um; }
    /// How far refraction moves the ground point of a ray whose straight line meets the ground
    /// at zenith `straight_zenith_deg`, towards the point below the sensor, m (its ratio to the
    /// flat atmosphere's tan z / cos² z linear between the nodes; 0 beyond kMaxZenithDeg).
    double displacement_m(double straight_zenith_deg) const noexcept;
    /// The refracted ray's zenith at the ground minus the straight one's there, degrees (< 0:
    /// it arrives steeper; its ratio to tan z linear between the nodes).
    double zenith_change_deg(double straight_zenith_deg) const noexcept;

    /// `ray` (leaving the sensor; scene ENU, the ground plane z = 0) as the air bends it: where
    /// its straight line crosses z = 0 at a zenith below kMaxZenithDeg, the crossing moved
    /// towards the sensor by displacement_m and the direction turned by zenith_change_deg in
    /// its vertical plane, the origin as far back along the new direction as the sensor was
    /// along the old; unchanged otherwise (it rises, runs level, starts below the plane or
    /// meets it beyond kMaxZenithDeg).
    SampleRay bend(const SampleRay& ray) const noexcept;

private:
    double m_wavelength_um = 0.0;
    std::vector<double> m_displacement_m;     ///< per node
    std::vector<double> m_zenith_change_deg;  ///< per node
    /// Interpolates `table` at `zenith_deg` (0 beyond the last node).
    double at(const std::vector<double>& table, double zenith_deg) const noexcept;
};

/// A ray source whose rays are another's bent by a ViewRefraction (both must outlive it).
class RefractedRaySource final : public RaySource {
public:
    RefractedRaySource(const RaySource& straight, const ViewRefraction& refraction)
        : m_straight(straight), m_refraction(refraction) {}
    SampleRay generate(std::uint64_t problem, std::uint64_t sample,
                       RandomStream& rng) const override {
        return m_refraction.bend(m_straight.generate(problem, sample, rng));
    }

private:
    const RaySource& m_straight;
    const ViewRefraction& m_refraction;
};

}  // namespace glint::radiometry
