// SPDX-License-Identifier: Apache-2.0
// Moonlight: the moon's irradiance at the top of the atmosphere as a fraction of the sun's,
// from its phase angle and distance. The moon is a grey reflector of geometric albedo 0.12
// (full moon at the mean distance: V = −12.7, 2.45 × 10⁻⁶ of the sun) with the phase law of
// K. Krisciunas and B. E. Schaefer, "A model of the brightness of moonlight", Publications of
// the Astronomical Society of the Pacific 103, 1991, 1033–1039 (after Allen's Astrophysical
// Quantities): 10^(−0.4 (0.026 |α| + 4 × 10⁻⁹ α⁴)), α the phase angle in degrees.
// docs/physics.md ("The moon").
#pragma once

namespace glint::atmosphere {

/// The moon's mean radius, km.
inline constexpr double kMoonRadiusKm = 1737.4;
/// Geometric albedo (grey).
inline constexpr double kMoonGeometricAlbedo = 0.12;
/// Mean Earth–moon distance, km.
inline constexpr double kMoonMeanDistanceKm = 384'400.0;

/// E_moon(λ) / E_sun(λ) at the top of the atmosphere for the phase angle `phase_angle_deg`
/// (0 full, 180 new) and the observer–moon distance `distance_km`; the sun's irradiance is at
/// the moon's distance from the sun (that of the Earth to 0.3 %). Throws glint::Error
/// (input) for a non-finite angle or a distance ≤ 0.
double lunar_irradiance_ratio(double phase_angle_deg, double distance_km);

/// The moon's angular radius seen from `distance_km`, rad.
double lunar_angular_radius_rad(double distance_km);

}  // namespace glint::atmosphere
