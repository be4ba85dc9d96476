// SPDX-License-Identifier: Apache-2.0
// Atmospheric refraction and its dispersion through a spherically layered atmosphere: the
// refractive index of moist air, its profile over a standard atmosphere's levels, and rays
// traced through the spherical shells by Bouguer's invariant n r sin z = const: the bending of
// a ray, the Earth-centred angle it travels, astronomical refraction and its inverse, and where
// a sensor's view ray meets the ground with and without refraction.
//
// References:
//  - P. E. Ciddor, "Refractive index of air: new equations for the visible and near infrared",
//    Applied Optics 35, 1996, 1566–1573 (the refractivity of moist air, with its
//    compressibility).
//  - J. A. Stone, J. H. Zimmerman, "Index of refraction of air", NIST Engineering Metrology
//    Toolbox, https://emtoolbox.nist.gov/Wavelength/Documentation.asp (check values of
//    Ciddor's equation).
//  - L. H. Auer, E. M. Standish, "Astronomical refraction: computational method for all zenith
//    angles", The Astronomical Journal 119, 2000, 2472–2474 (the refraction integral).
//  - R. M. Green, "Spherical Astronomy", Cambridge University Press, 1985, chapter 4 (Bouguer's
//    invariant; Laplace's series R = α(1 − β) tan z − α(β − α/2) tan³ z).
//  - G. G. Bennett, "The calculation of astronomical refraction in marine navigation", Journal
//    of Navigation 35, 1982, 255–259 (the check at the horizon and above).
//
// Units: altitudes, radii and lengths m; angles degrees unless the name says _rad; wavelengths
// µm in vacuum; pressures hPa; temperatures K. Checked in
// tests/unit/atmosphere/refraction_test.cpp.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "glint/model/standard_atmospheres.h"

namespace glint::atmosphere {

/// The Earth radius the tracer uses unless told otherwise (the mean radius), m.
inline constexpr double kMeanEarthRadiusM = 6'371'000.0;

/// n − 1 of moist air at vacuum wavelength `wavelength_um`, total pressure `pressure_hpa`,
/// temperature `temperature_k`, water-vapour partial pressure `water_vapour_pressure_hpa` and
/// CO2 mole fraction `co2_ppm` (µmol/mol), by Ciddor's (1996) equations: the dispersion of
/// standard dry air and of water vapour, each scaled by its density from the BIPM
/// compressibility. The water's mole fraction is e/p (the partial pressure as given, no
/// enhancement factor). Ciddor's range: 0.3–1.7 µm, −40–100 °C, 80–120 kPa; his accuracy there
/// is a few 1e-8. Outside it the same formulas are used: towards the infrared the dispersion
/// flattens to its long-wave limit (2.73e-4 at 15 °C, 1013.25 hPa; the real infrared index of
/// moist air has water-band structure this leaves out); at the low pressures and temperatures
/// of the upper atmosphere the compressibility tends to 1 and the refractivity to the density
/// law. Throws glint::Error (input) for a wavelength below 0.2 µm (the dispersion has a pole at
/// 0.132 µm) or not finite, a pressure < 0, a temperature ≤ 0, a vapour pressure outside
/// [0, pressure] or a CO2 fraction outside [0, 1e6].
double air_refractivity(double wavelength_um, double pressure_hpa, double temperature_k,
                        double water_vapour_pressure_hpa, double co2_ppm = 450.0);

/// The refractivity n − 1 of the air at one wavelength against altitude: given at levels, with
/// ln(n − 1) linear in altitude between two levels (refractivity falls near exponentially;
/// linear where either level is 0), the lowest segment's law extended below the first level,
/// and 0 above the last (the table's top, 100 km for the standard atmospheres).
class RefractiveProfile {
public:
    /// The profile of a standard atmosphere's table at `wavelength_um`: air_refractivity at each
    /// level, its water-vapour pressure e = ρ_w R_v T (R_v = 461.5 J/(kg K)), capped at the
    /// level's pressure. Throws glint::Error (input) for the isothermal atmosphere (no levels:
    /// refraction needs a profile) and as air_refractivity.
    RefractiveProfile(const model::StandardAtmosphereProfile& profile, double wavelength_um,
                      double co2_ppm = 450.0);

    /// The same from levels of one's own (at least 2, altitudes increasing, pressures ≥ 0,
    /// temperatures > 0, water ≥ 0). Throws glint::Error (input) naming the bad level.
    RefractiveProfile(std::span<const model::AtmosphereLevel> levels, double wavelength_um,
                      double co2_ppm = 450.0);

    /// A profile of given refractivities n − 1 (≥ 0) at altitudes (m, increasing, at least 2).
    /// Throws glint::Error (input) for sizes that differ or values out of range.
    static RefractiveProfile from_refractivity(std::span<const double> altitudes_m,
                                               std::span<const double> refractivity);

    /// n − 1 at `altitude_m`.
    double refractivity(double altitude_m) const noexcept;
    /// (n − 1)(altitude_m + rise_m) − (n − 1)(altitude_m), to full relative precision for a
    /// small rise within one segment (where subtracting the two would cancel).
    double refractivity_change(double altitude_m, double rise_m) const noexcept;
    /// d(n − 1)/dh at `altitude_m`, 1/m (0 above the top; at a level, the segment above).
    double refractivity_gradient_per_m(double altitude_m) const noexcept;

    /// The wavelength it was made for, µm (0 for from_refractivity).
    double wavelength_um() const noexcept { return m_wavelength_um; }
    /// The last level's altitude, above which the refractivity is 0.
    double top_altitude_m() const noexcept { return m_altitudes_m.back(); }
    /// The levels' altitudes and refractivities.
    std::span<const double> level_altitudes_m() const noexcept { return m_altitudes_m; }
    std::span<const double> level_refractivity() const noexcept { return m_refractivity; }

private:
    RefractiveProfile() = default;
    void set_levels(std::vector<double> altitudes_m, std::vector<double> refractivity);
    std::size_t segment_of(double altitude_m) const noexcept;

    std::vector<double> m_altitudes_m;
    std::vector<double> m_refractivity;
    /// Per segment (level k to k + 1): d ln(n − 1)/dh, or d(n − 1)/dh where m_linear[k].
    std::vector<double> m_slope_per_m;
    std::vector<char> m_linear;
    double m_wavelength_um = 0.0;
};

/// One ray traced from an observer to an altitude.
struct RefractedPath {
    /// Earth-centred angle between the observer and the ray's end point, rad.
    double central_angle_rad = 0.0;
    /// How far the ray's direction turned along the path (towards the Earth; > 0 in air whose
    /// refractivity falls with height), rad: the end's zenith angle is the start's minus the
    /// central angle plus this.
    double bending_rad = 0.0;
    /// The zenith angle at the observer of the straight line to the end point, degrees.
    double geometric_zenith_deg = 0.0;
    /// The zenith angle of the ray's direction of travel at its end, degrees (< 90 arriving
    /// upwards; the reverse ray starts there at 180° minus this).
    double end_zenith_deg = 0.0;
    /// The length along the curved ray, m.
    double path_length_m = 0.0;
    /// The straight-line distance from the observer to the end point, m.
    double chord_length_m = 0.0;
    /// Where the ray passed its lowest point on the way (it started below the horizontal and
    /// its end lies above that point), m; empty otherwise.
    std::optional<double> tangent_altitude_m;
};

/// Where a sensor's view ray meets the ground, with and without refraction. The geometry: the
/// sensor at altitude h_s above the sub-sensor point, the ray leaving it at nadir angle η (from
/// the direction to the Earth's centre); arcs are measured along the ground's sphere (radius
/// Earth radius + ground altitude) from the sub-sensor point to the ray's ground point, in the
/// plane of the ray and the Earth's centre.
struct GroundIntersection {
    double arc_m = 0.0;           ///< the refracted ray's ground point
    double straight_arc_m = 0.0;  ///< the straight ray's ground point
    /// straight_arc_m − arc_m (> 0: refraction brings the ground point towards the sub-sensor
    /// point; the pixel sees ground nearer the nadir than straight rays place it).
    double displacement_m = 0.0;
    /// The zenith angle at the ground point of the direction back along the ray (the apparent
    /// direction of the sensor), and the straight ray's, degrees.
    double view_zenith_deg = 0.0;
    double straight_view_zenith_deg = 0.0;
    double path_length_m = 0.0;     ///< along the refracted ray, sensor to ground
    double straight_range_m = 0.0;  ///< along the straight ray, sensor to its ground point
};

/// Rays through a spherically layered atmosphere: shells of refractive index n(r), r the
/// distance from the Earth's centre (Earth radius + altitude), the ground the sphere of
/// altitude 0. Along a ray n r sin z is constant (Bouguer); the tracer integrates the central
/// angle dφ = c dr / (r √(n²r² − c²)), the bending dδ = −c (dn/dr) dr / (n √(n²r² − c²)) and
/// the length n r dr / √(n²r² − c²) over each monotone piece of the path, with r = r_low + u²
/// (which removes the 1/√ singularity at a tangent point), by adaptive Gauss–Kronrod (7/15
/// points) between the levels, to about 1e-13 rad; above the profile's top the ray is straight
/// and the pieces are closed-form. Pure computation, safe to share between threads.
class RefractionTracer {
public:
    /// Throws glint::Error (input) for a radius not > 0 and finite, and for a profile whose
    /// n r does not increase with r everywhere from the ground to its top (refractivity falling
    /// faster than 1/r, super-refraction: rays would be trapped, which this tracer does not
    /// follow).
    explicit RefractionTracer(RefractiveProfile profile, double earth_radius_m = kMeanEarthRadiusM);

    const RefractiveProfile& profile() const noexcept { return m_profile; }
    double earth_radius_m() const noexcept { return m_earth_radius_m; }

    /// The ray leaving an observer at `observer_altitude_m` (≥ 0) in the direction of apparent
    /// zenith angle `apparent_zenith_deg` ([0, 180]; above 90 it first descends), followed to
    /// where it reaches `end_altitude_m` (≥ 0): the first crossing when that lies below the
    /// observer, otherwise after the tangent point for a descending ray. Throws glint::Error
    /// (input) for values out of range and when the ray does not reach that altitude: an
    /// ascending ray (≤ 90°) towards a lower altitude, a descending ray whose tangent point lies
    /// above the lower altitude, a ray that meets the ground (altitude 0) before its tangent
    /// point on its way to a higher altitude.
    RefractedPath trace(double observer_altitude_m, double apparent_zenith_deg,
                        double end_altitude_m) const;

    /// Astronomical refraction: true minus apparent zenith angle of a source outside the
    /// atmosphere seen from `observer_altitude_m` at `apparent_zenith_deg`, degrees: the
    /// bending of the ray out through the profile's top (including the step of n there; the
    /// vacuum above bends nothing). Throws as trace (a ray that meets the ground).
    double astronomical_refraction_deg(double observer_altitude_m,
                                       double apparent_zenith_deg) const;

    /// The inverse: the apparent zenith angle of a source outside the atmosphere at true zenith
    /// angle `true_zenith_deg` ([0, 180]), solved to 1e-10°; empty when the source lies below
    /// the apparent horizon (no ray from the observer that misses the ground reaches it).
    /// Throws glint::Error (input) for values out of range.
    std::optional<double> apparent_zenith_for_true_deg(double observer_altitude_m,
                                                       double true_zenith_deg) const;

    /// Where the view ray of a sensor at `sensor_altitude_m`, leaving at nadir angle
    /// `nadir_angle_deg` ([0, 90)), meets the ground at `ground_altitude_m` (≥ 0, below the
    /// sensor). Throws glint::Error (input) for values out of range and for a straight ray that
    /// passes above the ground (the message gives the horizon's nadir angle).
    GroundIntersection ground_intersection(double sensor_altitude_m, double nadir_angle_deg,
                                           double ground_altitude_m = 0.0) const;

private:
    RefractiveProfile m_profile;
    double m_earth_radius_m;
};

}  // namespace glint::atmosphere
