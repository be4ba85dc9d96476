// SPDX-License-Identifier: Apache-2.0
// The atmosphere description read from a .jsim BasicAtmosphere's atmosphere_filename: a glint
// YAML atmosphere (model none, parametric or tabulated) or the simpleradiativetransfer subset
// of a DIRSIG .atm file. Plain data; the physics lives in glint/atmosphere/atmosphere.h and the
// formulas in docs/physics.md ("Atmosphere and sun").
//
// YAML keys (glint/yaml/atmosphere_reader.h reads them; unknown keys are warnings):
//
// | key | type | unit | default | model |
// |---|---|---|---|---|
// | `model` | none, parametric, tabulated | – | (required) | all |
// | `aerosol_optical_depth_550` | number ≥ 0 | – | 0.1 | parametric |
// | `angstrom_exponent` | number | – | 1.3 | parametric |
// | `aerosol_scale_height_m` | number > 0 | m | 1200 | parametric |
// | `aerosol_asymmetry` | number in (−1, 1) | – | 0.7 | parametric (Henyey–Greenstein g) |
// | `aerosol_single_scatter_albedo` | number in [0, 1] | – | 0.95 | parametric |
// | `rayleigh_scale_height_m` | number > 0 | m | 8000 | parametric |
// | `sea_level_pressure_hpa` | number ≥ 0 | hPa | 1013.25 | parametric (0: no Rayleigh) |
// | `profile` | tropical, midlatitude_summer, midlatitude_winter, subarctic_summer,
// subarctic_winter, us_standard_1976, isothermal | – | us_standard_1976 | parametric (air
// temperatures; when given, also the defaults of `air_temperature_k`, `water_vapor_cm`,
// `ozone_atm_cm`) | | `air_temperature_k` | number ≥ 0 | K | 288.15 (the profile's sea level) |
// parametric (emission) | | `water_vapor_pressure_hpa` | number ≥ 0 | hPa | 10 | parametric
// (Brutsaert sky without gas absorption) | | `gas_absorption` | true, false | – | true | parametric
// (H₂O, O₃, O₂, CO₂, CH₄, … bands) | | `water_vapor_cm` | number ≥ 0 | cm | 2.924 (the profile's,
// when given) | parametric (precipitable water, vertical) | | `ozone_atm_cm` | number ≥ 0 | atm-cm
// | 0.332 (the profile's, when given) | parametric (ozone column, vertical) | | `aerosol_model` |
// rural, urban, maritime, desert | – | (none) | parametric: sets the next three | | `visibility_km`
// | number > 0 | km | – | parametric: τ₅₅₀ by Koschmieder (not with τ₅₅₀) | | `multiple_scattering`
// | true, false | – | true | parametric (sky and path radiance) | | `ground_albedo` | number in [0,
// 1] | – | 0.2 | parametric (Lambertian ground of the sky) | | `table` | path | – | (required) |
// tabulated (relative to the YAML file) | | `sky_temperature_k` | number ≥ 0 | K | 0 (black) |
// tabulated without a thermal column |
//
// DIRSIG .atm subset: `<atmosphericconditions>` > `<simpleradiativetransfer>` >
// `<apparentskytemperature>` (K, default 0) gives kind simple.
#pragma once

#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/model/standard_atmospheres.h"

namespace glint::model {

/// Which atmosphere model a description selects.
enum class AtmosphereKind {
    none,        ///< exo-atmospheric sun, black sky, no path effects
    parametric,  ///< Rayleigh + aerosol extinction and single scattering
    tabulated,   ///< a user table (MODTRAN, libRadtran, 6S output) for one geometry
    simple,      ///< DIRSIG .atm simpleradiativetransfer: no path effects, sky at a temperature
};

/// Parameters of the parametric model (units in the names; defaults in the file table).
struct ParametricAtmosphere {
    double aerosol_optical_depth_550 = 0.1;       ///< vertical, at 0.55 µm, from sea level
    double angstrom_exponent = 1.3;               ///< α in τ_a(λ) = τ_550 (λ/0.55)^−α
    double aerosol_scale_height_m = 1200.0;       ///< aerosol extinction ∝ exp(−z/H_a)
    double aerosol_asymmetry = 0.7;               ///< Henyey–Greenstein asymmetry g
    double aerosol_single_scatter_albedo = 0.95;  ///< ω_a
    double rayleigh_scale_height_m = 8000.0;      ///< Rayleigh extinction ∝ exp(−z/H_R)
    double sea_level_pressure_hpa = 1013.25;      ///< Rayleigh optical depth ∝ pressure
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
};

/// Representative optical properties of an aerosol type at 70-80 % relative humidity:
/// rural, urban and maritime after E. P. Shettle and R. W. Fenn, "Models for the aerosols of
/// the lower atmosphere and the effects of humidity variations on their optical properties",
/// AFGL-TR-79-0214, 1979; desert after J. D. Longtin, E. P. Shettle, J. R. Hummel,
/// J. D. Pryce, "A wind dependent desert aerosol model", AFGL-TR-88-0112, 1988. Values
/// for 0.4-1 µm (docs/physics.md, "Aerosol types").
struct AerosolType {
    const char* name;
    double angstrom_exponent;
    double single_scatter_albedo;
    double asymmetry;
};
inline constexpr AerosolType kAerosolTypes[] = {
    {"rural", 1.25, 0.95, 0.68},
    {"urban", 1.15, 0.80, 0.67},
    {"maritime", 0.35, 0.99, 0.76},
    {"desert", 0.30, 0.90, 0.72},
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
