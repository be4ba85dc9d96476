// SPDX-License-Identifier: Apache-2.0
// The six standard model atmospheres of LOWTRAN/MODTRAN practice (tropical, mid-latitude
// summer and winter, sub-arctic summer and winter, 1976 U.S. Standard) as tables of altitude,
// pressure, temperature and water-vapour and ozone densities, from G. P. Anderson,
// S. A. Clough, F. X. Kneizys, J. H. Chetwynd, E. P. Shettle, "AFGL Atmospheric Constituent
// Profiles (0-120 km)", AFGL-TR-86-0110, Air Force Geophysics Laboratory, 1986 (a U.S.
// Government work), at its levels from 0 to 100 km; and an isothermal atmosphere for
// analytic work. Plain data: the parametric atmosphere (glint/atmosphere/atmosphere.h) reads
// its air temperature from them, the YAML reader its default columns. docs/thermal.md.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace glint::model {

/// A standard atmosphere (YAML `profile`).
enum class StandardAtmosphere {
    tropical,
    midlatitude_summer,
    midlatitude_winter,
    subarctic_summer,
    subarctic_winter,
    us_standard_1976,
    isothermal,  ///< every level at the air temperature (`air_temperature_k`)
};

/// One level of a standard atmosphere.
struct AtmosphereLevel {
    double altitude_km = 0.0;
    double pressure_hpa = 0.0;
    double temperature_k = 0.0;
    double water_g_per_m3 = 0.0;  ///< water-vapour density
    double ozone_g_per_m3 = 0.0;  ///< ozone density
};

/// A standard atmosphere's table and the columns its densities give.
struct StandardAtmosphereProfile {
    const char* name = "";  ///< its YAML spelling
    /// Ascending altitudes 0-100 km (empty for isothermal).
    std::span<const AtmosphereLevel> levels;
    /// Precipitable water and ozone above sea level, each density exponential between levels.
    double water_column_cm = 0.0;
    double ozone_column_atm_cm = 0.0;
    /// The water's and the ozone's column above each level, g/m² (like `levels`).
    std::vector<double> water_above_g_per_m2;
    std::vector<double> ozone_above_g_per_m2;
};

/// The share of the profile's water column that lies above `altitude_m`, [0, 1]: 1 at or
/// below its first level, 0 at or above its last, the density exponential between levels
/// (as the columns are integrated). −1 for a profile without levels (isothermal).
double water_share_above(const StandardAtmosphereProfile& profile, double altitude_m) noexcept;
/// The same for its ozone.
double ozone_share_above(const StandardAtmosphereProfile& profile, double altitude_m) noexcept;

/// The share of the air's column that lies above `altitude_m`: the pressure there over the
/// pressure at the first level, exponential between levels (ln p linear in altitude) and
/// beyond the table along its first or last segment's. −1 for a profile without levels
/// (isothermal).
double pressure_share_above(const StandardAtmosphereProfile& profile, double altitude_m) noexcept;

/// The table of `which` (the columns computed once from it).
const StandardAtmosphereProfile& standard_atmosphere(StandardAtmosphere which) noexcept;

/// The atmosphere a YAML spelling names ("tropical", "midlatitude_summer", …, "isothermal").
std::optional<StandardAtmosphere> standard_atmosphere_named(std::string_view name) noexcept;

/// Every YAML spelling, comma-separated (for error messages).
const char* standard_atmosphere_names() noexcept;

/// Linear interpolation of the temperature of `levels` at `altitude_m`, the end values held
/// beyond the table.
double profile_temperature_k(std::span<const AtmosphereLevel> levels, double altitude_m) noexcept;

}  // namespace glint::model
