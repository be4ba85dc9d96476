// SPDX-License-Identifier: Apache-2.0
// Physical constants (SI, CODATA 2018) and the small unit conversions glint needs. Every
// quantity carries its unit in its name; internal radiance is W/(cm² sr µm) (docs/units.md).
#pragma once

#include <numbers>

namespace glint {

// ---- Constants (CODATA 2018; the first four are exact by the 2019 SI definition) ----------

/// Planck constant h in J·s (exact).
inline constexpr double kPlanckJS = 6.62607015e-34;
/// Speed of light in vacuum c in m/s (exact).
inline constexpr double kSpeedOfLightMPerS = 299792458.0;
/// Boltzmann constant k_B in J/K (exact).
inline constexpr double kBoltzmannJPerK = 1.380649e-23;
/// Elementary charge e in C (exact).
inline constexpr double kElementaryChargeC = 1.602176634e-19;
/// Stefan–Boltzmann constant σ = 2π⁵k⁴/(15h³c²) in W/(m² K⁴) (CODATA 2018, 10 digits).
inline constexpr double kStefanBoltzmannWPerM2K4 = 5.670374419e-8;
/// Wien's displacement constant b = hc/(k·4.965114231744…) in µm·K (CODATA 2018).
inline constexpr double kWienDisplacementUmK = 2897.771955;
/// First radiation constant for spectral radiance, 2hc², in W·m²/sr.
inline constexpr double kPlanckC1WM2PerSr =
    2.0 * kPlanckJS * kSpeedOfLightMPerS * kSpeedOfLightMPerS;
/// Second radiation constant c₂ = hc/k_B in µm·K (≈ 14387.77).
inline constexpr double kPlanckC2UmK = kPlanckJS * kSpeedOfLightMPerS / kBoltzmannJPerK * 1e6;

// ---- Length ------------------------------------------------------------------------------

/// Micrometres to nanometres.
constexpr double um_to_nm(double length_um) { return length_um * 1e3; }
/// Nanometres to micrometres.
constexpr double nm_to_um(double length_nm) { return length_nm * 1e-3; }
/// Micrometres to metres.
constexpr double um_to_m(double length_um) { return length_um * 1e-6; }
/// Metres to micrometres.
constexpr double m_to_um(double length_m) { return length_m * 1e6; }
/// Nanometres to metres.
constexpr double nm_to_m(double length_nm) { return length_nm * 1e-9; }
/// Metres to nanometres.
constexpr double m_to_nm(double length_m) { return length_m * 1e9; }

// ---- Area --------------------------------------------------------------------------------

/// Square centimetres to square metres.
constexpr double cm2_to_m2(double area_cm2) { return area_cm2 * 1e-4; }
/// Square metres to square centimetres.
constexpr double m2_to_cm2(double area_m2) { return area_m2 * 1e4; }
/// A quantity per m² (e.g. W/(m² sr µm)) expressed per cm² (e.g. W/(cm² sr µm)).
constexpr double per_m2_to_per_cm2(double value_per_m2) { return value_per_m2 * 1e-4; }
/// A quantity per cm² expressed per m².
constexpr double per_cm2_to_per_m2(double value_per_cm2) { return value_per_cm2 * 1e4; }

// ---- Power -------------------------------------------------------------------------------

/// Watts to milliwatts.
constexpr double w_to_mw(double power_w) { return power_w * 1e3; }
/// Milliwatts to watts.
constexpr double mw_to_w(double power_mw) { return power_mw * 1e-3; }
/// Watts to microwatts.
constexpr double w_to_uw(double power_w) { return power_w * 1e6; }
/// Microwatts to watts.
constexpr double uw_to_w(double power_uw) { return power_uw * 1e-6; }

// ---- Angle -------------------------------------------------------------------------------

/// Degrees to radians.
constexpr double deg_to_rad(double angle_deg) { return angle_deg * (std::numbers::pi / 180.0); }
/// Radians to degrees.
constexpr double rad_to_deg(double angle_rad) { return angle_rad * (180.0 / std::numbers::pi); }

}  // namespace glint
