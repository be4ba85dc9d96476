// SPDX-License-Identifier: Apache-2.0
// The thermal emission of the parametric atmosphere's air (glint/atmosphere/atmosphere.h):
// the temperature profile, the emission along a path, and the directional thermal sky.
// Formulas: docs/thermal.md ("The emitting atmosphere").
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "atmosphere_detail.h"
#include "glint/atmosphere/atmosphere.h"
#include "glint/core/spectral.h"
#include "glint/model/standard_atmospheres.h"

namespace glint::atmosphere {

using namespace detail;

namespace {

/// Layers of the emission integration, spaced ∝ k² from the lower end (where the air is
/// warmest and wettest).
constexpr int kEmissionLayers = 256;

/// Gauss–Legendre nodes and weights on [0, 1] for the cosine-weighted hemispheric mean of
/// the sky, 2∫₀¹ L(μ) μ dμ (8 points: exact for polynomials in μ of degree 15).
constexpr double kMu[8] = {0.019855071751231856, 0.10166676129318664, 0.2372337950418355,
                           0.4082826787521751,   0.5917173212478249,  0.7627662049581645,
                           0.8983332387068134,   0.9801449282487681};
constexpr double kMuWeight[8] = {0.05061426814518813, 0.11119051722668724, 0.15685332293894363,
                                 0.18134189168918100, 0.18134189168918100, 0.15685332293894363,
                                 0.11119051722668724, 0.05061426814518813};

}  // namespace

double ParametricAtmosphereModel::air_temperature_k(double altitude_m) const noexcept {
    const auto& p = m_parameters;
    if (p.profile == model::StandardAtmosphere::isothermal) return p.air_temperature_k;
    const auto levels = model::standard_atmosphere(p.profile).levels;
    const double shift = p.air_temperature_k - model::profile_temperature_k(levels, 0.0);
    const double fade =
        std::clamp(1.0 - std::max(altitude_m, 0.0) / kTemperatureShiftTopM, 0.0, 1.0);
    return std::max(model::profile_temperature_k(levels, altitude_m) + shift * fade, 0.0);
}

std::vector<double> ParametricAtmosphereModel::air_emission_w_per_cm2_sr_um(
    const SpectralGrid& grid, double observer_m, double far_m, double air_mass) const {
    const double air_masses[] = {air_mass};
    return std::move(air_emission_at_air_masses(grid, observer_m, far_m, air_masses).front());
}

std::vector<std::vector<double>> ParametricAtmosphereModel::air_emission_at_air_masses(
    const SpectralGrid& grid, double observer_m, double far_m,
    std::span<const double> air_masses) const {
    std::vector<std::vector<double>> result(air_masses.size(),
                                            std::vector<double>(grid.size(), 0.0));
    const double z_lo = std::max(std::min(observer_m, far_m), 0.0);
    const double z_hi = std::min(std::max(observer_m, far_m), kTopOfAtmosphereM);
    if (!(z_hi > z_lo)) return result;
    const bool observer_low = observer_m <= far_m;
    const double z_observer = observer_low ? z_lo : z_hi;
    const std::size_t layers = static_cast<std::size_t>(kEmissionLayers);

    // Boundaries z_lo … z_hi (∝ k²) and the layers' temperatures at their middles.
    std::vector<double> bounds(layers + 1);
    for (std::size_t k = 0; k <= layers; ++k) {
        const double f = static_cast<double>(k) / kEmissionLayers;
        bounds[k] = z_lo + (z_hi - z_lo) * f * f;
    }
    bounds[layers] = z_hi;
    std::vector<double> temperature(layers);
    for (std::size_t k = 0; k < layers; ++k) {
        temperature[k] = air_temperature_k(0.5 * (bounds[k] + bounds[k + 1]));
    }
    const std::size_t n = grid.size();
    // B(λ, T_k) of every layer, [band][layer]: the same along every air mass.
    std::vector<double> planck(n * layers);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < layers; ++k) {
            planck[i * layers + k] =
                planck_radiance_w_per_cm2_sr_um(grid.wavelength_um(i), temperature[k]);
        }
    }
    // The altitude factors of the scatterers' optical depths at every boundary.
    const std::size_t regimes = m_aerosol.regimes();
    std::vector<double> rayleigh_factor(layers + 1);
    std::vector<double> aerosol_depth((layers + 1) * regimes);  // [boundary][regime], 550 nm
    for (std::size_t k = 0; k <= layers; ++k) {
        rayleigh_factor[k] = air_share_above(bounds[k]);
        for (std::size_t j = 0; j < regimes; ++j) {
            aerosol_depth[k * regimes + j] = m_aerosol.depth_550_above(j, bounds[k]);
        }
    }
    const std::size_t obs = observer_low ? 0 : layers;
    // Each regime's extinction relative to 550 nm and albedo, [band][regime].
    std::vector<double> ratio(n * regimes), albedo(n * regimes);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < regimes; ++j) {
            const RegimeOptics o = m_aerosol.optics(j, grid.wavelength_um(i), 0);
            ratio[i * regimes + j] = o.extinction_ratio;
            albedo[i * regimes + j] = o.single_scatter_albedo;
        }
    }
    const std::shared_ptr<const GasTransmittance> gases = gases_on(grid);
    const GasAmounts at_observer = gas_amounts_above(z_observer);
    std::vector<double> log_gas;
    std::vector<double> absorbed(layers + 1);
    std::vector<double> scattered(layers + 1);
    for (std::size_t m = 0; m < air_masses.size(); ++m) {
        const double air_mass = air_masses[m];
        if (!(air_mass > 0.0)) continue;
        std::vector<double>& out = result[m];

        // ln of the gas transmittance from the observer to every boundary, [boundary][band].
        if (gases) {
            log_gas.assign((layers + 1) * n, 0.0);
            for (std::size_t k = 0; k <= layers; ++k) {
                const GasAmounts at = gas_amounts_above(bounds[k]);
                const GasAmounts slant_amounts = observer_low ? slant(at_observer, at, air_mass)
                                                              : slant(at, at_observer, air_mass);
                gases->log_transmittance(slant_amounts, std::span<double>(&log_gas[k * n], n));
            }
        }
        // Per band: absorption depth a_k and scattering depth s_k from the observer to each
        // boundary; the layer between k and k+1 adds B(T_k) |e^(−a_k) − e^(−a_k+1)| e^(−s_mid).
        for (std::size_t i = 0; i < n; ++i) {
            const double wl = grid.wavelength_um(i);
            const double rayleigh = rayleigh_optical_depth(wl, 0.0);
            for (std::size_t k = 0; k <= layers; ++k) {
                const double d_r = std::abs(rayleigh_factor[obs] - rayleigh_factor[k]) * rayleigh;
                double absorbing = 0.0;
                double scattering = 0.0;
                for (std::size_t j = 0; j < regimes; ++j) {
                    const double d_a = std::abs(aerosol_depth[obs * regimes + j] -
                                                aerosol_depth[k * regimes + j]) *
                                       ratio[i * regimes + j];
                    absorbing += (1.0 - albedo[i * regimes + j]) * d_a;
                    scattering += albedo[i * regimes + j] * d_a;
                }
                const double log_g = gases ? log_gas[k * n + i] : 0.0;
                absorbed[k] = std::exp(-absorbing * air_mass + log_g);
                scattered[k] = (d_r + scattering) * air_mass;
            }
            double sum = 0.0;
            for (std::size_t k = 0; k < layers; ++k) {
                const double emissivity = std::abs(absorbed[k] - absorbed[k + 1]);
                if (emissivity == 0.0) continue;
                const double out_scattered = std::exp(-0.5 * (scattered[k] + scattered[k + 1]));
                sum += planck[i * layers + k] * emissivity * out_scattered;
            }
            out[i] = sum;
        }
    }
    return result;
}

std::vector<double> ParametricAtmosphereModel::thermal_sky_radiance_at_zenith(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry, double zenith_deg) const {
    check_geometry(geometry);
    if (!std::isfinite(zenith_deg)) throw input_error("thermal sky at a non-finite zenith");
    const double z = geometry.surface_altitude_m;
    if (!m_parameters.gas_absorption) {
        const double emissivity = sky_emissivity(z);
        std::vector<double> out;
        out.reserve(grid.size());
        for (double wl : grid.wavelengths_um()) {
            out.push_back(emissivity *
                          planck_radiance_w_per_cm2_sr_um(wl, m_parameters.air_temperature_k));
        }
        return out;
    }
    const double zeniths[] = {zenith_deg};
    return std::move(thermal_sky_at_zeniths(grid, geometry, zeniths).front());
}

std::vector<std::vector<double>> ParametricAtmosphereModel::thermal_sky_at_zeniths(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> zeniths_deg) const {
    check_geometry(geometry);
    std::vector<double> air_masses;
    for (double zenith : zeniths_deg) {
        if (!std::isfinite(zenith)) throw input_error("thermal sky at a non-finite zenith");
        air_masses.push_back(relative_air_mass(std::clamp(zenith, 0.0, 90.0)));
    }
    if (!m_parameters.gas_absorption) {
        return std::vector<std::vector<double>>(
            zeniths_deg.size(), thermal_sky_radiance_at_zenith(grid, geometry, 0.0));
    }
    std::vector<std::vector<double>> sky = air_emission_at_air_masses(
        grid, geometry.surface_altitude_m, kTopOfAtmosphereM, air_masses);
    // What scattering adds (thermal multiple scattering; zero where it is not solved).
    for (std::size_t j = 0; j < zeniths_deg.size(); ++j) {
        const double mu = std::cos(std::clamp(zeniths_deg[j], 0.0, 90.0) * kDegToRad);
        const std::vector<double> in_scatter = thermal_in_scatter_w_per_cm2_sr_um(
            grid, geometry.surface_altitude_m, geometry.surface_altitude_m, mu, false);
        for (std::size_t i = 0; i < grid.size(); ++i) sky[j][i] += in_scatter[i];
    }
    return sky;
}

std::vector<double> ParametricAtmosphereModel::thermal_sky_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    if (!m_parameters.gas_absorption) return thermal_sky_radiance_at_zenith(grid, geometry, 0.0);
    std::vector<double> zeniths;
    for (double mu : kMu) zeniths.push_back(std::acos(mu) / kDegToRad);
    const auto sky = thermal_sky_at_zeniths(grid, geometry, zeniths);
    std::vector<double> out(grid.size(), 0.0);
    for (std::size_t j = 0; j < zeniths.size(); ++j) {
        for (std::size_t i = 0; i < out.size(); ++i) {
            out[i] += 2.0 * kMuWeight[j] * kMu[j] * sky[j][i];
        }
    }
    return out;
}

}  // namespace glint::atmosphere
