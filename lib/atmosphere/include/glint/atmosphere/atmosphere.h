// SPDX-License-Identifier: Apache-2.0
// Atmosphere models: per-wavelength-grid queries of the direct sun transmittance, the
// surface-to-sensor transmittance and path radiance, the diffuse sky irradiance and the
// isotropic sky radiance (scattered + thermal emission). Implementations: none (exo-atmospheric
// sun, black sky, no path effects; plain_atmospheres.cpp), parametric (Rayleigh + aerosol + gas
// bands, single- or multiple-scattering path radiance and sky; parametric_atmosphere.cpp,
// parametric_scattering.cpp), tabulated (a user table for one geometry;
// tabulated_atmosphere.cpp) and simple (DIRSIG .atm: sky at a temperature).
// Formulas, parameters and limits: docs/physics.md ("Atmosphere and sun"). Units: radiance W/(cm²
// sr µm), irradiance W/(cm² µm), altitudes m, angles degrees.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "glint/atmosphere/aerosol_column.h"
#include "glint/atmosphere/aerosol_table.h"
#include "glint/atmosphere/gas_absorption.h"
#include "glint/atmosphere/solar.h"
#include "glint/core/spectral.h"
#include "glint/model/atmosphere.h"

namespace glint::atmosphere {

/// The geometry of one atmosphere query.
struct AtmosphereGeometry {
    double sun_zenith_deg = 0.0;      ///< at the surface point; ≥ 90: sun below the horizon
    double sun_azimuth_deg = 0.0;     ///< clockwise from north
    double surface_altitude_m = 0.0;  ///< of the surface point, above sea level
    double sensor_altitude_m = 0.0;   ///< of the sensor, above sea level (≥ surface)
    double view_zenith_deg = 0.0;     ///< direction surface → sensor, from the zenith, < 90
    double view_azimuth_deg = 0.0;    ///< direction surface → sensor, clockwise from north
};

/// An atmosphere model. Every query returns one value per wavelength of `grid`; the ones that
/// scale sunlight take the top-of-atmosphere solar irradiance on the same grid
/// (SolarSpectrum::resample). Queries throw glint::Error (input) for a size mismatch or a
/// non-finite geometry.
class AtmosphereModel {
public:
    virtual ~AtmosphereModel() = default;

    /// Direct-beam transmittance from the top of the atmosphere to the surface point along
    /// the sun's direction, [0, 1] (0 when the sun is below the horizon).
    virtual std::vector<double> sun_transmittance(const SpectralGrid& grid,
                                                  const AtmosphereGeometry& geometry) const = 0;

    /// Direct transmittance from the surface point to the sensor, [0, 1].
    virtual std::vector<double> sensor_transmittance(const SpectralGrid& grid,
                                                     const AtmosphereGeometry& geometry) const = 0;

    /// Radiance added along the surface → sensor path (scattered sunlight, plus emission where
    /// the model has it), W/(cm² sr µm) at the sensor.
    virtual std::vector<double> path_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const = 0;

    /// The path radiance at each view azimuth of `view_azimuths_deg` (the geometry's own view
    /// azimuth unused): one spectrum per azimuth, each equal to path_radiance_w_per_cm2_sr_um
    /// at that azimuth. This default asks once per azimuth; a model may share the work that
    /// does not depend on the azimuth.
    virtual std::vector<std::vector<double>> path_radiance_at_azimuths(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um,
        std::span<const double> view_azimuths_deg) const;

    /// Diffuse (scattered sunlight) irradiance on a horizontal surface at the surface point,
    /// W/(cm² µm).
    virtual std::vector<double> diffuse_sky_irradiance_w_per_cm2_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const = 0;

    /// Thermal emission of the sky, W/(cm² sr µm): the isotropic sky, or for a directional
    /// one the radiance of equal irradiance on a horizontal surface (2∫L(μ)μ dμ).
    virtual std::vector<double> thermal_sky_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry) const = 0;

    /// Whether the thermal sky depends on the direction (thermal_sky_radiance_at_zenith).
    virtual bool directional_thermal_sky() const noexcept { return false; }

    /// The thermal sky radiance arriving at the surface point from zenith angle
    /// `zenith_deg` (0 overhead, 90 at the horizon), W/(cm² sr µm). Default: the isotropic
    /// thermal_sky_radiance_w_per_cm2_sr_um.
    virtual std::vector<double> thermal_sky_radiance_at_zenith(const SpectralGrid& grid,
                                                               const AtmosphereGeometry& geometry,
                                                               double zenith_deg) const {
        (void)zenith_deg;
        return thermal_sky_radiance_w_per_cm2_sr_um(grid, geometry);
    }

    /// thermal_sky_radiance_at_zenith at each of `zeniths_deg` (one spectrum each). This
    /// default asks once per zenith; a model may share the work.
    virtual std::vector<std::vector<double>> thermal_sky_at_zeniths(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> zeniths_deg) const {
        std::vector<std::vector<double>> out;
        for (double zenith : zeniths_deg) {
            out.push_back(thermal_sky_radiance_at_zenith(grid, geometry, zenith));
        }
        return out;
    }

    /// The scattered sunlight arriving at the surface point from the sky directions of zenith
    /// zeniths_deg[z] (< 90) and azimuth azimuths_deg[a] (clockwise from north), W/(cm² sr
    /// µm): one spectrum per direction, [z · azimuths + a]. Empty when the model's scattered
    /// sky has no directional structure: its radiance is then diffuse_sky_irradiance / π from
    /// every direction. This default: empty.
    virtual std::vector<std::vector<double>> scattered_sky_at_directions(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um, std::span<const double> zeniths_deg,
        std::span<const double> azimuths_deg) const {
        (void)grid, (void)geometry, (void)toa_irradiance_w_per_cm2_um, (void)zeniths_deg,
            (void)azimuths_deg;
        return {};
    }

    /// The isotropic sky radiance: diffuse_sky_irradiance / π + thermal_sky_radiance.
    std::vector<double> sky_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const;
};

/// The none model: transmittances 1 (sun transmittance 0 below the horizon), no path
/// radiance, black sky.
class NoAtmosphere final : public AtmosphereModel {
public:
    std::vector<double> sun_transmittance(const SpectralGrid& grid,
                                          const AtmosphereGeometry& geometry) const override;
    std::vector<double> sensor_transmittance(const SpectralGrid& grid,
                                             const AtmosphereGeometry& geometry) const override;
    std::vector<double> path_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const override;
    std::vector<double> diffuse_sky_irradiance_w_per_cm2_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const override;
    std::vector<double> thermal_sky_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry) const override;
};

/// The DIRSIG .atm simpleradiativetransfer subset: as none, but the sky radiates as a
/// blackbody at the apparent sky temperature.
class SimpleAtmosphereModel final : public AtmosphereModel {
public:
    explicit SimpleAtmosphereModel(model::SimpleAtmosphere parameters);
    std::vector<double> sun_transmittance(const SpectralGrid& grid,
                                          const AtmosphereGeometry& geometry) const override;
    std::vector<double> sensor_transmittance(const SpectralGrid& grid,
                                             const AtmosphereGeometry& geometry) const override;
    std::vector<double> path_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const override;
    std::vector<double> diffuse_sky_irradiance_w_per_cm2_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const override;
    std::vector<double> thermal_sky_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry) const override;

private:
    model::SimpleAtmosphere m_parameters;
};

/// Rayleigh + aerosol extinction with exponential scale heights, Kasten–Young air mass,
/// single-scatter path radiance (Rayleigh and Henyey–Greenstein phase functions), a
/// Bird–Hulstrom-type diffuse sky and (with gas_absorption) molecular absorption from the gas
/// band model on every path, and the air's thermal emission along every path and from every
/// direction of the sky at the temperatures of a standard profile (without gas absorption,
/// the aerosol's emission on paths and a grey Brutsaert sky).
class ParametricAtmosphereModel final : public AtmosphereModel {
public:
    /// The isothermal profile's water (the standard profiles use their own densities):
    /// the water above altitude z is W·e^(−z/H), H this scale height, m.
    static constexpr double kWaterScaleHeightM = 2000.0;
    /// The isothermal profile's ozone: all of the column lies above kOzoneBottomM, none above
    /// kOzoneTopM, and the share above z falls linearly between.
    static constexpr double kOzoneBottomM = 10'000.0;
    static constexpr double kOzoneTopM = 40'000.0;

    /// `gases` is the band-model table, required when parameters.gas_absorption is set;
    /// `aerosols` the aerosol optics table, required with parameters.aerosol_model or
    /// aerosol_profile. Throws
    /// glint::Error (input) for parameters out of the ranges of model/atmosphere.h or a table
    /// missing.
    explicit ParametricAtmosphereModel(model::ParametricAtmosphere parameters,
                                       std::shared_ptr<const GasBandModel> gases = nullptr,
                                       std::shared_ptr<const AerosolTable> aerosols = nullptr);

    /// The vertical absorber amounts above `altitude_m` (zero without gas absorption): the
    /// water and ozone columns shared out by the profile's densities (docs/thermal.md), the
    /// mixed gases by the Rayleigh scale height.
    GasAmounts gas_amounts_above(double altitude_m) const noexcept;
    /// Gas transmittance of every band of `grid` for slant amounts `amounts` (1 without gas
    /// absorption).
    std::vector<double> gas_transmittance(const SpectralGrid& grid,
                                          const GasAmounts& amounts) const;

    /// Vertical Rayleigh optical depth above `altitude_m` at `wavelength_um`.
    double rayleigh_optical_depth(double wavelength_um, double altitude_m) const noexcept;
    /// The share of the air's column above `altitude_m` (1 at sea level): the profile's
    /// pressure over its sea-level one, or e^(−z/H_R) with rayleigh_scale_height_m (8000 m
    /// for the isothermal profile). Rayleigh scattering and the mixed gases follow it.
    double air_share_above(double altitude_m) const noexcept;
    /// The isothermal profile's Rayleigh scale height, m.
    static constexpr double kIsothermalRayleighScaleHeightM = 8000.0;
    /// Vertical aerosol optical depth above `altitude_m` at `wavelength_um`.
    double aerosol_optical_depth(double wavelength_um, double altitude_m) const;
    /// The aerosol: its regimes, their profiles and optics.
    const AerosolColumn& aerosol() const noexcept { return m_aerosol; }
    /// Effective clear-sky emissivity (Brutsaert 1975), grey, seen from `altitude_m` (above
    /// sea level): the vapour pressure scaled by the water column above, e · e^(−z/H_w);
    /// 0 above the model's top (100 km).
    double sky_emissivity(double altitude_m = 0.0) const noexcept;

    /// The shift of air_temperature_k from the profile fades linearly to 0 at this altitude.
    static constexpr double kTemperatureShiftTopM = 11'000.0;
    /// The air temperature at `altitude_m` (above sea level), K: the profile's, shifted by
    /// air_temperature_k minus the profile's sea-level temperature below
    /// kTemperatureShiftTopM (docs/thermal.md).
    double air_temperature_k(double altitude_m) const noexcept;

    /// The thermal emission of the air between altitudes `observer_m` and `far_m`, seen
    /// from `observer_m` along a straight path of relative air mass `air_mass`, W/(cm² sr µm)
    /// per band of `grid`: over 256 layers, Σ B(λ, T_k) (A_near − A_far) S_k, A the
    /// transmittance of the absorbers (gas bands and aerosol absorption) from the observer to
    /// a layer's boundary, S the scattering transmittance to its middle (docs/thermal.md).
    /// Nothing above the model's top (100 km).
    std::vector<double> air_emission_w_per_cm2_sr_um(const SpectralGrid& grid, double observer_m,
                                                     double far_m, double air_mass) const;
    /// air_emission_w_per_cm2_sr_um along each of `air_masses` (one spectrum each; the
    /// layers, their temperatures and Planck radiances shared).
    std::vector<std::vector<double>> air_emission_at_air_masses(
        const SpectralGrid& grid, double observer_m, double far_m,
        std::span<const double> air_masses) const;

    std::vector<double> sun_transmittance(const SpectralGrid& grid,
                                          const AtmosphereGeometry& geometry) const override;
    std::vector<double> sensor_transmittance(const SpectralGrid& grid,
                                             const AtmosphereGeometry& geometry) const override;
    std::vector<double> path_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const override;
    /// The layers' transmittances towards the sun and the sensor do not depend on the view
    /// azimuth: computed once for every azimuth (the same numbers as one query each).
    std::vector<std::vector<double>> path_radiance_at_azimuths(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um,
        std::span<const double> view_azimuths_deg) const override;
    std::vector<double> diffuse_sky_irradiance_w_per_cm2_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const override;
    /// The scattered sunlight arriving at the surface point from the sky direction of zenith
    /// `zenith_deg` (< 90) and azimuth `azimuth_deg` (clockwise from north), W/(cm² sr µm)
    /// per band: the direct sun's single scattering along that line of sight (256 layers, the
    /// exact Rayleigh and aerosol phase functions, the gases on both legs) plus the solver's
    /// higher orders and ground-coupled light (none without multiple scattering); 0 with the
    /// sun down. The sky's directional structure: its aureole around the sun, its horizon
    /// (docs/physics.md, "The scattered sky's radiance").
    std::vector<double> scattered_sky_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um, double zenith_deg,
        double azimuth_deg) const;
    /// scattered_sky_radiance_w_per_cm2_sr_um at every (zenith, azimuth) pair, the layers and
    /// the line of sight's gases shared; empty with directional_sky false.
    std::vector<std::vector<double>> scattered_sky_at_directions(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um, std::span<const double> zeniths_deg,
        std::span<const double> azimuths_deg) const override;
    /// With gas absorption, the air's emission seen from the surface; without, the grey
    /// Brutsaert sky.
    std::vector<double> thermal_sky_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry) const override;
    bool directional_thermal_sky() const noexcept override { return m_parameters.gas_absorption; }
    /// The air's emission from the surface to the top along zenith `zenith_deg` (Kasten–Young
    /// air mass); the isotropic Brutsaert sky without gas absorption.
    std::vector<double> thermal_sky_radiance_at_zenith(const SpectralGrid& grid,
                                                       const AtmosphereGeometry& geometry,
                                                       double zenith_deg) const override;
    /// The zeniths share the layers, their temperatures and Planck radiances.
    std::vector<std::vector<double>> thermal_sky_at_zeniths(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> zeniths_deg) const override;

    /// Wavelength nodes of the multiple-scattering solutions: a grid of at most this many
    /// bands is solved at its own wavelengths, a larger one at this many nodes spaced evenly
    /// in ln λ across it (interpolated linearly in ln λ between them).
    static constexpr std::size_t kScatteringNodes = 24;
    /// Layers of the multiple-scattering atmosphere between the surface and 100 km (and
    /// the sensor's altitude as one more boundary).
    static constexpr int kScatteringLayers = 24;
    /// The multiple-scattering solutions are computed for the sun's zenith rounded to this
    /// step and the surface and sensor altitudes rounded to this one (shared by the captures
    /// of a sequence; the rounding moves the diffuse light by < 0.1 %).
    static constexpr double kScatteringZenithStepDeg = 0.05;
    static constexpr double kScatteringAltitudeStepM = 1.0;

    /// The gas band-model table in use; nullptr without gas absorption.
    const GasBandModel* gas_table() const noexcept { return m_gases.get(); }

    /// Thermal multiple scattering (with multiple_scattering on) is solved for the bands at
    /// or beyond this wavelength whose column above the surface scatters at least
    /// kThermalScatteringMinDepth (vertical optical depth); elsewhere what it adds is below
    /// 10⁻⁴ of the emission, or the sun's light dwarfs it (docs/thermal.md).
    static constexpr double kThermalScatteringFromUm = 2.5;
    static constexpr double kThermalScatteringMinDepth = 1e-4;
    /// What thermal multiple scattering adds, W/(cm² sr µm) per band of `grid`: upward at
    /// `sensor_m` along cos(zenith) `mu` when `upward`, else downward at `surface_m`
    /// arriving from cos(zenith) `mu`, in the plane-parallel atmosphere from `surface_m` to
    /// the top, emitting at the profile's temperatures over a black ground at the air's
    /// temperature there (docs/thermal.md). Zero for the bands it is not solved for.
    std::vector<double> thermal_in_scatter_w_per_cm2_sr_um(const SpectralGrid& grid,
                                                           double surface_m, double sensor_m,
                                                           double mu, bool upward) const;

private:
    struct Scattering;
    struct ThermalScattering;

    /// The band model on `grid`, computed once per grid (null without gas absorption).
    std::shared_ptr<const GasTransmittance> gases_on(const SpectralGrid& grid) const;
    /// The multiple-scattering solutions of `geometry` at the nodes of `grid` (null without
    /// multiple scattering or with the sun down); the last few are kept.
    std::shared_ptr<const Scattering> scattering(const SpectralGrid& grid,
                                                 const AtmosphereGeometry& geometry) const;
    /// scattered_sky_at_directions whatever directional_sky says.
    std::vector<std::vector<double>> scattered_sky_radiances(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um, std::span<const double> zeniths_deg,
        std::span<const double> azimuths_deg) const;
    /// Adds the multiple-scatter path radiance to `out` (one spectrum per azimuth).
    void add_multiple_scattering(const SpectralGrid& grid, const AtmosphereGeometry& geometry,
                                 std::span<const double> toa,
                                 std::span<const double> view_azimuths_deg,
                                 std::vector<std::vector<double>>& out) const;

    model::ParametricAtmosphere m_parameters;
    std::shared_ptr<const GasBandModel> m_gases;
    AerosolColumn m_aerosol;
    mutable std::mutex m_grids_mutex;
    mutable std::map<std::vector<double>, std::shared_ptr<const GasTransmittance>> m_grids;
    mutable std::mutex m_scattering_mutex;
    mutable std::vector<std::shared_ptr<const Scattering>> m_scattering;  ///< most recent last
    mutable std::vector<std::shared_ptr<const ThermalScattering>> m_thermal_scattering;

    /// The thermal scattering solutions between `surface_m` and the top with a level at
    /// `sensor_m` (both rounded to kScatteringAltitudeStepM), per band of `grid`; the last
    /// few are kept.
    std::shared_ptr<const ThermalScattering> thermal_scattering(const SpectralGrid& grid,
                                                                double surface_m,
                                                                double sensor_m) const;
};

/// A user table for one geometry: the geometry is ignored, values are linearly interpolated
/// in wavelength. Queries throw glint::Error (input) when the grid reaches outside the table.
class TabulatedAtmosphereModel final : public AtmosphereModel {
public:
    /// Throws glint::Error (input) for columns of unequal length or fewer than 2 rows.
    explicit TabulatedAtmosphereModel(model::TabulatedAtmosphere table);
    std::vector<double> sun_transmittance(const SpectralGrid& grid,
                                          const AtmosphereGeometry& geometry) const override;
    std::vector<double> sensor_transmittance(const SpectralGrid& grid,
                                             const AtmosphereGeometry& geometry) const override;
    std::vector<double> path_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const override;
    std::vector<double> diffuse_sky_irradiance_w_per_cm2_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry,
        std::span<const double> toa_irradiance_w_per_cm2_um) const override;
    std::vector<double> thermal_sky_radiance_w_per_cm2_sr_um(
        const SpectralGrid& grid, const AtmosphereGeometry& geometry) const override;

private:
    std::vector<double> sample(const SpectralGrid& grid, const std::vector<double>& column) const;
    model::TabulatedAtmosphere m_table;
};

/// Kasten & Young (1989) relative air mass at zenith angle `zenith_deg` (1 overhead, ≈ 38 at
/// the horizon, capped there for larger angles).
double relative_air_mass(double zenith_deg) noexcept;

/// A zenith angle, degrees, at which relative_air_mass is `air_mass` (its inverse, by
/// bisection to 1e-12°; 48.26° for air mass 1.5). Throws glint::Error (input) outside
/// [relative_air_mass(0), relative_air_mass(90)].
double zenith_for_relative_air_mass(double air_mass);

/// The model an atmosphere description selects; `gases` is the band-model table the
/// parametric model needs when its gas absorption is on (glint/atmosphere/gas_absorption.h),
/// `aerosols` the aerosol optics table it needs with an aerosol_model.
std::unique_ptr<AtmosphereModel> make_atmosphere_model(
    const model::Atmosphere& atmosphere, std::shared_ptr<const GasBandModel> gases = nullptr,
    std::shared_ptr<const AerosolTable> aerosols = nullptr);

/// Whether the model `atmosphere` selects needs the gas band-model table (the parametric
/// model with its gas absorption on).
bool needs_gas_table(const model::Atmosphere& atmosphere);
/// Whether it needs the aerosol optics table (the parametric model with an aerosol_model or an
/// aerosol_profile).
bool needs_aerosol_table(const model::Atmosphere& atmosphere);

/// glint's own data a render needs, read from its data folder by the readers
/// (glint/inputs/data_tables.h): the solar spectrum, and the gas band-model and aerosol optics
/// tables when the atmosphere needs them (needs_gas_table, needs_aerosol_table; null
/// otherwise).
struct DataTables {
    std::shared_ptr<const SolarSpectrum> sun;
    std::shared_ptr<const GasBandModel> gases;
    std::shared_ptr<const AerosolTable> aerosols;
};

}  // namespace glint::atmosphere
