// SPDX-License-Identifier: Apache-2.0
// The aerosol of the parametric atmosphere as LOWTRAN/MODTRAN practice builds it, as plain
// data: the aerosol types (mixtures of OPAC's components by number density: M. Hess,
// P. Koepke, I. Schult, "Optical Properties of Aerosols and Clouds: The Software Package OPAC",
// Bulletin of the American Meteorological Society 79, 1998, 831–844, Table 4) and the vertical
// profiles of their 550 nm extinction (F. X. Kneizys et al., "Users Guide to LOWTRAN 7",
// AFGL-TR-88-0177, Air Force Geophysics Laboratory, 1988, after E. P. Shettle and R. W. Fenn,
// AFGL-TR-79-0214, 1979: a boundary layer 0–2 km set by the visibility, the free troposphere
// 2–10 km by season and visibility, the stratosphere 10–30 km and the upper atmosphere by
// season). The optics of the components: glint/atmosphere/aerosol_table.h. docs/physics.md
// ("Aerosol types", "Vertical structure").
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace glint::model {

/// One OPAC component of an aerosol type and its number density in the type's standard mix.
struct AerosolComponentNumber {
    const char*
        component;  ///< OPAC's name: inso, waso, soot, ssam, sscm, minm, miam, micm, mitr, suso
    double number_per_cm3;
};

/// An aerosol type: a mixture of components (their number densities fix the proportions;
/// the amount is set by the visibility or the optical depth).
struct AerosolMixture {
    const char* name;  ///< its YAML spelling
    std::span<const AerosolComponentNumber> components;
    /// Whether the components' sizes and indices follow the air's relative humidity (false:
    /// the dry 0 % optics, e.g. the stratosphere's sulphate).
    bool humidity_growth = true;
    const char* description;
};

/// The type a YAML spelling names: OPAC's ten (continental_clean, continental_average,
/// continental_polluted, urban, desert, maritime_clean, maritime_polluted, maritime_tropical,
/// arctic, antarctic), Shettle & Fenn's names for the nearest of them (rural =
/// continental_average, maritime = maritime_clean), tropospheric (OPAC's water-soluble
/// component alone: Shettle & Fenn's tropospheric model is the rural model without its large
/// particles) and stratospheric (OPAC's sulphate droplets, dry).
std::optional<AerosolMixture> aerosol_mixture_named(std::string_view name) noexcept;
/// Every YAML spelling, comma-separated (for error messages).
const char* aerosol_mixture_names() noexcept;

/// Whether `name` is one of OPAC's ten components (inso, waso, soot, ssam, sscm, minm, miam,
/// micm, mitr, suso): the names a user's aerosol profile may use.
bool is_aerosol_component(std::string_view name) noexcept;
/// OPAC's ten component names, comma-separated (for error messages).
const char* aerosol_component_names() noexcept;

/// LOWTRAN 7's season of the aerosol profiles above the boundary layer.
enum class AerosolSeason { spring_summer, fall_winter };

/// The 550 nm extinction of each regime at one altitude, 1/km.
struct RegimeExtinction {
    double boundary_layer = 0.0;  ///< 0–2 km: the boundary-layer type
    double troposphere = 0.0;     ///< above 2 km to 10 km: the tropospheric type
    double stratosphere = 0.0;    ///< above 10 km: stratospheric background and upper atmosphere
};

/// LOWTRAN 7's aerosol levels, km (0, 1, 2, …, 25, 30, 35, 40, 45, 50, 70, 100).
std::span<const double> aerosol_profile_levels_km() noexcept;

/// The 550 nm extinction of each regime at LOWTRAN 7's level `level` (an index of
/// aerosol_profile_levels_km) for a surface visibility `visibility_km` (Koschmieder, the
/// Rayleigh extinction removed; > 0) and `season`: the boundary layer's values linear in 1/V
/// between the tabulated visibilities (50, 23, 10, 5, 2 km; extrapolated linearly in 1/V
/// beyond them, as the ground value then follows Koschmieder's law, never below 0), the
/// troposphere's up to 4 km linear in 1/V between its 23 and 50 km tables (the 23 km one
/// below 23 km), the rest fixed by the season.
RegimeExtinction lowtran_aerosol_extinction(std::size_t level, double visibility_km,
                                            AerosolSeason season) noexcept;

}  // namespace glint::model
