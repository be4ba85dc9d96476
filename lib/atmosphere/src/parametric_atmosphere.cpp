// SPDX-License-Identifier: Apache-2.0
// The parametric atmosphere of glint/atmosphere/atmosphere.h: Rayleigh + aerosol with
// exponential scale heights, Beer–Lambert paths with the Kasten–Young air mass, the single-
// scatter path radiance integrated over altitude layers, the Bird–Hulstrom or multiply
// scattered sky (parametric_scattering.cpp) and the gas band model on every path; the air's
// emission and the thermal sky are in air_emission.cpp. Formulas: docs/physics.md ("Parametric
// model").
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <utility>

#include "atmosphere_detail.h"
#include "glint/atmosphere/atmosphere.h"
#include "glint/core/error.h"
#include "glint/model/standard_atmospheres.h"
#include "parametric_scattering.h"

namespace glint::atmosphere {

using namespace detail;

namespace {

/// Altitude layers of the single-scatter integration (spacing ∝ k², finer near the ground).
constexpr int kPathLayers = 256;

/// Standard sea-level pressure, hPa (the Hansen–Travis Rayleigh depth is for it).
constexpr double kStandardPressureHpa = 1013.25;

/// The Rayleigh optical depth of the whole atmosphere above sea level at λ (the Hansen–Travis
/// fit scaled by the surface pressure); at altitude z it is this × e^(−z/H_R).
double rayleigh_sea_level(const model::ParametricAtmosphere& p, double wavelength_um) {
    const double l2 = 1.0 / (wavelength_um * wavelength_um);
    const double l4 = l2 * l2;
    const double sea_level = 0.008569 * l4 * (1.0 + 0.0113 * l2 + 0.00013 * l4);
    return sea_level * (p.sea_level_pressure_hpa / kStandardPressureHpa);
}

/// Unit vector in ENU for (zenith, azimuth clockwise from north), degrees.
std::array<double, 3> direction(double zenith_deg, double azimuth_deg) {
    const double t = zenith_deg * kDegToRad;
    const double p = azimuth_deg * kDegToRad;
    return {std::sin(t) * std::sin(p), std::sin(t) * std::cos(p), std::cos(t)};
}

double rayleigh_phase(double cos_theta) { return 0.75 * (1.0 + cos_theta * cos_theta); }

/// Fraction of Henyey–Greenstein scattering into the forward hemisphere.
double hg_forward_fraction(double g) {
    if (std::abs(g) < 1e-6) return 0.5;
    return (1.0 + g) / (2.0 * g) - (1.0 - g * g) / (2.0 * g * std::sqrt(1.0 + g * g));
}

}  // namespace

// ---- parametric ----

ParametricAtmosphereModel::ParametricAtmosphereModel(model::ParametricAtmosphere parameters,
                                                     std::shared_ptr<const GasBandModel> gases,
                                                     std::shared_ptr<const AerosolTable> aerosols)
    : m_parameters(parameters), m_gases(std::move(gases)), m_aerosol(m_parameters, aerosols) {
    const auto& p = m_parameters;
    const auto bad = [](double v) { return !std::isfinite(v); };
    if (bad(p.aerosol_optical_depth_550) || p.aerosol_optical_depth_550 < 0.0) {
        throw input_error("aerosol_optical_depth_550 must be >= 0");
    }
    if (bad(p.angstrom_exponent)) throw input_error("angstrom_exponent must be finite");
    if (bad(p.aerosol_scale_height_m) || p.aerosol_scale_height_m <= 0.0 ||
        (p.rayleigh_scale_height_m &&
         (bad(*p.rayleigh_scale_height_m) || *p.rayleigh_scale_height_m <= 0.0))) {
        throw input_error("scale heights must be > 0 m");
    }
    if (bad(p.aerosol_asymmetry) || std::abs(p.aerosol_asymmetry) >= 1.0) {
        throw input_error("aerosol_asymmetry must lie in (-1, 1)");
    }
    if (bad(p.aerosol_single_scatter_albedo) || p.aerosol_single_scatter_albedo < 0.0 ||
        p.aerosol_single_scatter_albedo > 1.0) {
        throw input_error("aerosol_single_scatter_albedo must lie in [0, 1]");
    }
    if (bad(p.sea_level_pressure_hpa) || p.sea_level_pressure_hpa < 0.0 ||
        bad(p.air_temperature_k) || p.air_temperature_k < 0.0 || bad(p.water_vapor_pressure_hpa) ||
        p.water_vapor_pressure_hpa < 0.0) {
        throw input_error("pressures and temperatures must be >= 0");
    }
    if (bad(p.water_vapor_cm) || p.water_vapor_cm < 0.0 || bad(p.ozone_atm_cm) ||
        p.ozone_atm_cm < 0.0) {
        throw input_error("water_vapor_cm and ozone_atm_cm must be >= 0");
    }
    if (p.gas_absorption && !m_gases) {
        throw input_error(std::string("gas absorption needs the band-model table (") +
                          GasBandModel::kRelativePath + " in glint's data folder)");
    }
}

GasAmounts ParametricAtmosphereModel::gas_amounts_above(double altitude_m) const noexcept {
    if (!m_parameters.gas_absorption) return {};
    const double z = std::max(altitude_m, 0.0);
    // The columns' shapes: the profile's densities (scaled to the columns asked for), or,
    // for the isothermal atmosphere, which has none, an exponential water and an ozone
    // layer between kOzoneBottomM and kOzoneTopM.
    const model::StandardAtmosphereProfile& profile =
        model::standard_atmosphere(m_parameters.profile);
    double water_share = model::water_share_above(profile, z);
    double ozone_share = model::ozone_share_above(profile, z);
    if (water_share < 0.0) water_share = std::exp(-z / kWaterScaleHeightM);
    if (ozone_share < 0.0) {
        ozone_share = std::clamp((kOzoneTopM - z) / (kOzoneTopM - kOzoneBottomM), 0.0, 1.0);
    }
    return GasAmounts{
        m_parameters.water_vapor_cm * water_share, m_parameters.ozone_atm_cm * ozone_share,
        m_parameters.sea_level_pressure_hpa / kStandardPressureHpa * air_share_above(z)};
}

std::shared_ptr<const GasTransmittance> ParametricAtmosphereModel::gases_on(
    const SpectralGrid& grid) const {
    if (!m_parameters.gas_absorption) return nullptr;
    const std::vector<double> key(grid.wavelengths_um().begin(), grid.wavelengths_um().end());
    const std::lock_guard<std::mutex> lock(m_grids_mutex);
    auto& slot = m_grids[key];
    if (!slot) slot = std::make_shared<const GasTransmittance>(*m_gases, grid);
    return slot;
}

std::vector<double> ParametricAtmosphereModel::gas_transmittance(const SpectralGrid& grid,
                                                                 const GasAmounts& amounts) const {
    const auto gases = gases_on(grid);
    if (!gases) return filled(grid, 1.0);
    return gases->transmittance(amounts);
}

double ParametricAtmosphereModel::rayleigh_optical_depth(double wavelength_um,
                                                         double altitude_m) const noexcept {
    return rayleigh_sea_level(m_parameters, wavelength_um) * air_share_above(altitude_m);
}

double ParametricAtmosphereModel::air_share_above(double altitude_m) const noexcept {
    if (!m_parameters.rayleigh_scale_height_m) {
        const double share = model::pressure_share_above(
            model::standard_atmosphere(m_parameters.profile), altitude_m);
        if (share >= 0.0) return share;
    }
    return std::exp(-altitude_m /
                    m_parameters.rayleigh_scale_height_m.value_or(kIsothermalRayleighScaleHeightM));
}

double ParametricAtmosphereModel::aerosol_optical_depth(double wavelength_um,
                                                        double altitude_m) const {
    return m_aerosol.optical_depth(wavelength_um, altitude_m);
}

double ParametricAtmosphereModel::sky_emissivity(double altitude_m) const noexcept {
    const double t = m_parameters.air_temperature_k;
    if (t <= 0.0 || altitude_m >= kTopOfAtmosphereM) return 0.0;
    // The vapour pressure falls with the water column above: e · e^(−z/H_w) (sea level 0).
    const double vapour_hpa = m_parameters.water_vapor_pressure_hpa *
                              std::exp(-std::max(altitude_m, 0.0) / kWaterScaleHeightM);
    return std::clamp(1.24 * std::pow(vapour_hpa / t, 1.0 / 7.0), 0.0, 1.0);
}

std::vector<double> ParametricAtmosphereModel::sun_transmittance(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    if (!sun_up(geometry)) return filled(grid, 0.0);
    const double z = geometry.surface_altitude_m;
    if (z >= kTopOfAtmosphereM) return filled(grid, 1.0);  // exo-atmospheric
    const double m = relative_air_mass(geometry.sun_zenith_deg);
    std::vector<double> out = gas_transmittance(grid, slant(gas_amounts_above(z), {}, m));
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double wl = grid.wavelength_um(i);
        out[i] *= std::exp(-(rayleigh_optical_depth(wl, z) + aerosol_optical_depth(wl, z)) * m);
    }
    return out;
}

std::vector<double> ParametricAtmosphereModel::sensor_transmittance(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    const double m = relative_air_mass(geometry.view_zenith_deg);
    const double z0 = geometry.surface_altitude_m;
    const double z1 = std::max(z0, geometry.sensor_altitude_m);
    if (z0 >= kTopOfAtmosphereM) return filled(grid, 1.0);  // the path lies above the model
    std::vector<double> out =
        gas_transmittance(grid, slant(gas_amounts_above(z0), gas_amounts_above(z1), m));
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double wl = grid.wavelength_um(i);
        const double tau = rayleigh_optical_depth(wl, z0) - rayleigh_optical_depth(wl, z1) +
                           aerosol_optical_depth(wl, z0) - aerosol_optical_depth(wl, z1);
        out[i] *= std::exp(-tau * m);
    }
    return out;
}

std::vector<double> ParametricAtmosphereModel::path_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> toa) const {
    const double azimuth[] = {geometry.view_azimuth_deg};
    return std::move(path_radiance_at_azimuths(grid, geometry, toa, azimuth).front());
}

std::vector<std::vector<double>> ParametricAtmosphereModel::path_radiance_at_azimuths(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry, std::span<const double> toa,
    std::span<const double> view_azimuths_deg) const {
    check_geometry(geometry);
    check_size(grid, toa);
    for (double a : view_azimuths_deg) {
        if (!std::isfinite(a)) throw input_error("atmosphere query with a non-finite geometry");
    }
    const double z0 = geometry.surface_altitude_m;
    const double z1 =
        std::min(std::max(z0, geometry.sensor_altitude_m), std::max(z0, kTopOfAtmosphereM));
    std::vector<std::vector<double>> out(view_azimuths_deg.size(),
                                         std::vector<double>(grid.size(), 0.0));
    if (z1 <= z0) return out;
    const bool sunlit = sun_up(geometry);
    const double m_sun = relative_air_mass(geometry.sun_zenith_deg);
    const double m_view = relative_air_mass(geometry.view_zenith_deg);
    const auto s = direction(geometry.sun_zenith_deg, geometry.sun_azimuth_deg);
    // The scattering angles at each azimuth: light travels along −s from the sun and leaves
    // along v towards the sensor.
    std::vector<double> cos_scatter;
    std::vector<double> p_rayleigh;
    for (double azimuth : view_azimuths_deg) {
        const auto v = direction(std::clamp(geometry.view_zenith_deg, 0.0, 90.0), azimuth);
        cos_scatter.push_back(-(s[0] * v[0] + s[1] * v[1] + s[2] * v[2]));
        p_rayleigh.push_back(rayleigh_phase(cos_scatter.back()));
    }
    const std::size_t regimes = m_aerosol.regimes();
    // τ(λ, z) = τ_R(λ)·a(z) + Σ_j r_j(λ) D_j(z), a the air's share above z, D_j the 550 nm depth of
    // aerosol regime j above z and r_j its extinction relative to 550 nm: the altitude parts of
    // every layer boundary and midpoint are computed once, the spectral ones once per band.
    struct Level {
        double rayleigh = 0.0;        ///< the air's share above z
        std::vector<double> aerosol;  ///< D_j(z)
    };
    const auto level = [&](double z) {
        Level at{air_share_above(z), {}};
        for (std::size_t j = 0; j < regimes; ++j) {
            at.aerosol.push_back(m_aerosol.depth_550_above(j, z));
        }
        return at;
    };
    // Sunlight scattered once into the path (none with the sun down).
    if (sunlit) {
        const std::size_t layers = static_cast<std::size_t>(kPathLayers);
        std::vector<Level> bounds(layers + 1);  // z_0 = z0 … z_K = z1
        std::vector<Level> middles(layers);
        {
            double za = z0;
            bounds[0] = level(za);
            for (int k = 1; k <= kPathLayers; ++k) {
                const double f = static_cast<double>(k) / kPathLayers;
                const double zb = z0 + (z1 - z0) * f * f;
                bounds[static_cast<std::size_t>(k)] = level(zb);
                middles[static_cast<std::size_t>(k - 1)] = level(0.5 * (za + zb));
                za = zb;
            }
        }
        const Level top = level(z1);
        // ln of the gas transmittances of each layer's midpoint from the sun and to the sensor,
        // per band ([layer][band]); none without gas absorption.
        const std::shared_ptr<const GasTransmittance> gases = gases_on(grid);
        std::vector<double> gas_sun;
        std::vector<double> gas_view;
        if (gases) {
            const std::size_t n = grid.size();
            gas_sun.assign(layers * n, 0.0);
            gas_view.assign(layers * n, 0.0);
            const GasAmounts at_sensor = gas_amounts_above(z1);
            double za = z0;
            for (std::size_t k = 0; k < layers; ++k) {
                const double f = static_cast<double>(k + 1) / kPathLayers;
                const double zb = z0 + (z1 - z0) * f * f;
                const GasAmounts at_layer = gas_amounts_above(0.5 * (za + zb));
                za = zb;
                const std::span<double> view(&gas_view[k * n], n);
                gases->log_transmittance(slant(at_layer, at_sensor, m_view), view);
                gases->log_transmittance(slant(at_layer, {}, m_sun),
                                         std::span<double>(&gas_sun[k * n], n));
            }
        }
        // Per layer of one band: its Rayleigh optical depth, its aerosol scattering weighted by
        // each azimuth's phase functions, and its transmittances from the sun and to the
        // sensor, the same at every azimuth.
        const std::size_t azimuths = view_azimuths_deg.size();
        std::vector<double> d_r(layers), sun(layers), to_sensor(layers);
        std::vector<double> aerosol_source(layers * azimuths);
        std::vector<double> ratio(regimes), albedo(regimes);
        std::vector<std::vector<double>> p_aerosol(regimes);
        for (std::size_t i = 0; i < grid.size(); ++i) {
            const double wl = grid.wavelength_um(i);
            const double rayleigh = rayleigh_sea_level(m_parameters, wl);
            for (std::size_t j = 0; j < regimes; ++j) {
                const RegimeOptics o = m_aerosol.optics(j, wl, 0);
                ratio[j] = o.extinction_ratio;
                albedo[j] = o.single_scatter_albedo;
                p_aerosol[j] = m_aerosol.phases(j, wl, cos_scatter);
            }
            const auto tau_r = [&](const Level& at) { return rayleigh * at.rayleigh; };
            const auto tau_a = [&](const Level& at) {
                double sum = 0.0;
                for (std::size_t j = 0; j < regimes; ++j) sum += ratio[j] * at.aerosol[j];
                return sum;
            };
            const double tau_sensor = tau_r(top) + tau_a(top);
            double tau_r_a = tau_r(bounds[0]);
            for (std::size_t k = 0; k < layers; ++k) {
                const double tau_r_b = tau_r(bounds[k + 1]);
                d_r[k] = tau_r_a - tau_r_b;
                for (std::size_t a = 0; a < azimuths; ++a) aerosol_source[k * azimuths + a] = 0.0;
                for (std::size_t j = 0; j < regimes; ++j) {
                    const double d_a = ratio[j] * (bounds[k].aerosol[j] - bounds[k + 1].aerosol[j]);
                    if (d_a == 0.0) continue;
                    for (std::size_t a = 0; a < azimuths; ++a) {
                        aerosol_source[k * azimuths + a] += albedo[j] * d_a * p_aerosol[j][a];
                    }
                }
                const double tau_m = tau_r(middles[k]) + tau_a(middles[k]);
                const double log_gas_view = gases ? gas_view[k * grid.size() + i] : 0.0;
                const double log_gas_sun = gases ? gas_sun[k * grid.size() + i] : 0.0;
                to_sensor[k] = std::exp(-(tau_m - tau_sensor) * m_view + log_gas_view);
                sun[k] = std::exp(-tau_m * m_sun + log_gas_sun);
                tau_r_a = tau_r_b;
            }
            for (std::size_t a = 0; a < azimuths; ++a) {
                double sum = 0.0;
                for (std::size_t k = 0; k < layers; ++k) {
                    const double source =
                        toa[i] / (4.0 * kPi) * sun[k] *
                        (d_r[k] * p_rayleigh[a] + aerosol_source[k * azimuths + a]);
                    sum += source * m_view * to_sensor[k];
                }
                out[a][i] = sum;
            }
        }
    }
    // The air's own emission along the path and what scattering adds to it (thermal
    // multiple scattering), the same at every azimuth.
    std::vector<double> emission = air_emission_w_per_cm2_sr_um(grid, z1, z0, m_view);
    const std::vector<double> in_scatter = thermal_in_scatter_w_per_cm2_sr_um(
        grid, z0, z1, std::cos(std::clamp(geometry.view_zenith_deg, 0.0, 90.0) * kDegToRad), true);
    for (std::size_t i = 0; i < grid.size(); ++i) emission[i] += in_scatter[i];
    for (auto& spectrum : out) {
        for (std::size_t i = 0; i < grid.size(); ++i) spectrum[i] += emission[i];
    }
    add_multiple_scattering(grid, geometry, toa, view_azimuths_deg, out);
    return out;
}

std::vector<double> ParametricAtmosphereModel::diffuse_sky_irradiance_w_per_cm2_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> toa) const {
    check_geometry(geometry);
    check_size(grid, toa);
    std::vector<double> out(grid.size(), 0.0);
    const double z = geometry.surface_altitude_m;
    if (!sun_up(geometry) || z >= kTopOfAtmosphereM) return out;
    const double m = relative_air_mass(geometry.sun_zenith_deg);
    const double mu = std::cos(geometry.sun_zenith_deg * kDegToRad);
    // Gas absorption of the diffuse light: the direct beam's, at the sun's air mass (the
    // Bird–Riordan approximation).
    const std::vector<double> gas = gas_transmittance(grid, slant(gas_amounts_above(z), {}, m));
    if (const std::shared_ptr<const Scattering> ms = scattering(grid, geometry)) {
        // Multiple scattering: the diffuse flux reaching the ground per unit beam irradiance.
        const std::size_t ground = ms->solutions.front().levels() - 1;
        const std::vector<double> diffuse = ms->per_band([&](std::size_t k) {
            return ms->solutions[k].diffuse_down_flux(ground) + ms->forward_peak[k];
        });
        for (std::size_t i = 0; i < grid.size(); ++i) out[i] = toa[i] * diffuse[i] * gas[i];
        return out;
    }
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double wl = grid.wavelength_um(i);
        const double tau_r = rayleigh_optical_depth(wl, z);
        // The aerosol regimes above z as one: depth-weighted albedo and asymmetry (the
        // Henyey–Greenstein forward fraction of that asymmetry).
        double tau_a = 0.0;
        double scattering = 0.0;
        double g_scattering = 0.0;
        for (std::size_t j = 0; j < m_aerosol.regimes(); ++j) {
            const double depth = m_aerosol.depth_550_above(j, z);
            if (depth <= 0.0) continue;
            const RegimeOptics o = m_aerosol.optics(j, wl, 2);
            const double d = depth * o.extinction_ratio;
            tau_a += d;
            scattering += o.single_scatter_albedo * d;
            g_scattering += o.single_scatter_albedo * d * o.moments[1];
        }
        const double omega = tau_a > 0.0 ? scattering / tau_a : 1.0;
        const double forward =
            hg_forward_fraction(scattering > 0.0 ? g_scattering / scattering : 0.0);
        const double t_r = std::exp(-tau_r * m);
        const double t_as = std::exp(-omega * tau_a * m);
        const double t_aa = std::exp(-(1.0 - omega) * tau_a * m);
        out[i] = toa[i] * mu * gas[i] * t_aa * (0.5 * (1.0 - t_r) + forward * (1.0 - t_as));
    }
    return out;
}

}  // namespace glint::atmosphere
