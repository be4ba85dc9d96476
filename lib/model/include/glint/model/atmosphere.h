// SPDX-License-Identifier: Apache-2.0
// The atmosphere description read from a .jsim BasicAtmosphere's atmosphere_filename: a glint
// YAML atmosphere (model none, parametric or tabulated) or the simpleradiativetransfer subset
// of a DIRSIG .atm file. Plain data; the physics lives in glint/atmosphere/atmosphere.h and the
// formulas in docs/physics.md ("Atmosphere and sun").
//
// YAML keys: glint/yaml/atmosphere_reader.h reads them (unknown keys are warnings); their
// types, units and defaults are the table of docs/scene.md ("Atmosphere"), the defaults also
// the members' initialisers below.
//
// DIRSIG .atm subset: `<atmosphericconditions>` > `<simpleradiativetransfer>` >
// `<apparentskytemperature>` (K, default 0) gives kind simple.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/model/aerosol_models.h"
#include "glint/model/standard_atmospheres.h"

namespace glint::model {

/// Which atmosphere model a description selects.
enum class AtmosphereKind {
    none,        ///< exo-atmospheric sun, black sky, no path effects
    parametric,  ///< Rayleigh + aerosol extinction and single scattering
    tabulated,   ///< a user table (MODTRAN, libRadtran, 6S output) for one geometry
    simple,      ///< DIRSIG .atm simpleradiativetransfer: no path effects, sky at a temperature
};

/// A user's aerosol profile (YAML `aerosol_profile`): the densities of OPAC's components in
/// layers stacked from the ground up, each with its own mixture and the humidity of its air.
struct AerosolProfile {
    /// OPAC's component names (inso, waso, soot, ssam, sscm, minm, miam, micm, mitr, suso),
    /// one density column each, no name twice.
    std::vector<std::string> components;
    /// Whether the densities are masses, g/m³ (else particle numbers, 1/cm³).
    bool mass_densities = false;
    /// With mass densities: the humidity at which the particles were weighed, % (the number
    /// of particles is the mass over one particle's mass grown at this humidity). Unset: each
    /// layer's own humidity (the particles weighed as they are in the layer; libRadtran's
    /// convention for its aerosol_species_file).
    std::optional<double> mass_humidity_percent;
    /// The layers' boundaries, km above sea level, increasing; layer i runs from
    /// altitudes_km[i] to altitudes_km[i + 1] with densities[i] throughout.
    std::vector<double> altitudes_km;
    /// Per layer (altitudes_km.size() − 1 rows), one density per component, ≥ 0.
    std::vector<std::vector<double>> densities;
    /// Where it was written, for errors the aerosol optics table finds.
    ErrorContext where;
};

/// Parameters of the parametric model (units in the names; defaults in the file table).
struct ParametricAtmosphere {
    double aerosol_optical_depth_550 = 0.1;       ///< vertical, at 0.55 µm, from sea level
    double angstrom_exponent = 1.3;               ///< α in τ_a(λ) = τ_550 (λ/0.55)^−α
    double aerosol_scale_height_m = 1200.0;       ///< aerosol extinction ∝ exp(−z/H_a)
    double aerosol_asymmetry = 0.7;               ///< Henyey–Greenstein asymmetry g
    double aerosol_single_scatter_albedo = 0.95;  ///< ω_a
    /// Rayleigh extinction (and the mixed gases' amount) ∝ exp(−z/H_R) when set; unset: the
    /// `profile`'s pressure (the isothermal profile, which has none: H_R = 8000 m).
    std::optional<double> rayleigh_scale_height_m;
    double sea_level_pressure_hpa = 1013.25;  ///< Rayleigh optical depth ∝ pressure
    /// The air's temperature profile (and, through the YAML reader, the defaults of the
    /// columns and of air_temperature_k): glint/model/standard_atmospheres.h.
    StandardAtmosphere profile = StandardAtmosphere::us_standard_1976;
    /// Air temperature at sea level: the profile is shifted by its difference from the
    /// profile's own sea-level temperature, the shift fading linearly to 0 at 11 km
    /// (isothermal: the temperature of every level).
    double air_temperature_k = 288.15;
    double water_vapor_pressure_hpa = 10.0;  ///< for the Brutsaert sky (gas_absorption false)
    /// Molecular absorption from the gas band model (glint/atmosphere/gas_absorption.h).
    bool gas_absorption = true;
    /// Precipitable water of the vertical column above sea level, cm (default: the AFGL
    /// mid-latitude summer atmosphere's).
    double water_vapor_cm = 2.924;
    /// Ozone column, atm-cm (default: mid-latitude summer).
    double ozone_atm_cm = 0.332;
    /// Multiple scattering (successive orders) for the diffuse sky and the path radiance;
    /// false: the single-scatter path radiance and the Bird–Hulstrom diffuse sky.
    bool multiple_scattering = true;
    /// Lambertian albedo of the ground under the plane-parallel atmosphere: the light it
    /// sends back up that the sky scatters down again, and into the path radiance.
    double ground_albedo = 0.2;
    /// The scattered sky's radiance by direction (its aureole around the sun, its horizon),
    /// normalised to the diffuse irradiance; false: that irradiance / π from every direction.
    bool directional_sky = true;
    /// Refraction through the profile's refractive index (Ciddor's, at each spectral state's
    /// wavelength): view rays from above the scene and the sun's and moon's apparent
    /// directions. Without effect for the isothermal profile (it has no levels).
    bool refraction = true;

    /// The boundary layer's aerosol type (glint/model/aerosol_models.h): LOWTRAN 7's layered
    /// profiles with OPAC's optics. Empty: the exponential aerosol of the five aerosol_ keys
    /// above (Ångström spectrum, Henyey–Greenstein phase function).
    std::string aerosol_model;
    /// With aerosol_model: the surface visibility that sets the profiles, km.
    double visibility_km = 23.0;
    /// With aerosol_model or aerosol_profile: the whole column's vertical 550 nm optical depth
    /// above sea level, the profiles scaled to it (unset: the visibility's, or the profile's
    /// own).
    std::optional<double> aerosol_column_depth_550;
    /// With aerosol_model or aerosol_profile: the relative humidity every layer's
    /// water-soluble particles have grown at, % (unset: with aerosol_model the profile's at
    /// sea level, with aerosol_profile the profile's at each layer's middle; 70 % for
    /// isothermal; the stratospheric type is always dry).
    std::optional<double> relative_humidity_percent;
    /// With aerosol_model: the season of the profiles above 2 km (unset: fall_winter for the
    /// winter profiles, else spring_summer).
    std::optional<AerosolSeason> aerosol_season;
    /// With aerosol_model: the types of the free troposphere (2–10 km) and the stratosphere
    /// (above 10 km); "none" leaves the layer clear.
    std::string tropospheric_aerosol = "tropospheric";
    std::string stratospheric_aerosol = "stratospheric";

    /// A user's aerosol profile instead of the exponential or LOWTRAN aerosol (never with
    /// aerosol_model). aerosol_column_depth_550 scales it; relative_humidity_percent, when
    /// set, is every layer's humidity (unset: each layer's from `profile` at its middle).
    std::optional<AerosolProfile> aerosol_profile;
};

/// Koschmieder's constant: visibility V = 3.912 / β_ext(550 nm) at the ground (2 % contrast).
inline constexpr double kKoschmieder = 3.912;
/// Rayleigh extinction of sea-level air at 550 nm, km⁻¹ (removed from 3.912/V).
inline constexpr double kRayleighExtinction550PerKm = 0.01159;

/// A tabulated atmosphere for one sun/sensor geometry; every column has one entry per row.
struct TabulatedAtmosphere {
    std::string table_file;                             ///< the table file, as resolved
    std::vector<double> wavelengths_um;                 ///< strictly increasing
    std::vector<double> sun_transmittance;              ///< TOA → surface, direct beam, [0, 1]
    std::vector<double> sensor_transmittance;           ///< surface → sensor, [0, 1]
    std::vector<double> path_radiance_w_per_cm2_sr_um;  ///< at the sensor, ≥ 0
    std::vector<double> sky_irradiance_w_per_cm2_um;    ///< diffuse, horizontal surface, ≥ 0
    std::vector<double> thermal_sky_radiance_w_per_cm2_sr_um;  ///< empty: from sky_temperature_k
    double sky_temperature_k = 0.0;  ///< used when the thermal column is absent
};

/// DIRSIG's simpleradiativetransfer subset.
struct SimpleAtmosphere {
    double apparent_sky_temperature_k = 0.0;  ///< isotropic sky radiance B(λ, T)
};

/// An atmosphere description; only the member for `kind` is meaningful.
struct Atmosphere {
    AtmosphereKind kind = AtmosphereKind::none;
    ParametricAtmosphere parametric;
    TabulatedAtmosphere tabulated;
    SimpleAtmosphere simple;
    ErrorContext where;  ///< the file (and line of `model`) it was read from
    /// A DIRSIG `.atm`'s weather history (`<uniformweather><classicdata><filename>`), as
    /// written (relative to the .atm); empty: none.
    std::string weather_file;
    ErrorContext weather_where;
    /// What it came from, for the outputs' provenance: the file read (its path), or
    /// "--atmosphere none" / "--atmosphere parametric", or "default" (glint's default
    /// parametric atmosphere, the simulation naming none).
    std::string source = "default";
};

/// "none", "parametric", "tabulated" or "simple".
inline const char* to_string(AtmosphereKind kind) noexcept {
    switch (kind) {
        case AtmosphereKind::none:
            return "none";
        case AtmosphereKind::parametric:
            return "parametric";
        case AtmosphereKind::tabulated:
            return "tabulated";
        case AtmosphereKind::simple:
            return "simple";
    }
    return "none";
}

}  // namespace glint::model
