// SPDX-License-Identifier: Apache-2.0
// The parametric model's scattered sky radiance by direction (glint/atmosphere/atmosphere.h,
// ParametricAtmosphereModel::scattered_sky_radiance_w_per_cm2_sr_um): the exact single
// scattering of the direct sun along a line of sight from the surface up to the top, plus the
// successive-orders solution's higher orders arriving from that direction. docs/physics.md,
// "The scattered sky's radiance".
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "atmosphere_detail.h"
#include "glint/atmosphere/atmosphere.h"
#include "parametric_scattering.h"

namespace glint::atmosphere {

using namespace detail;

namespace {

/// Layers of the single-scatter integral along the line of sight (spacing ∝ k², finer near
/// the ground, as the path radiance's).
constexpr int kSkyLayers = 256;

}  // namespace

std::vector<double> ParametricAtmosphereModel::scattered_sky_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry, std::span<const double> toa,
    double zenith_deg, double azimuth_deg) const {
    check_geometry(geometry);
    check_size(grid, toa);
    if (!std::isfinite(zenith_deg) || !std::isfinite(azimuth_deg)) {
        throw input_error("sky radiance at a non-finite direction");
    }
    std::vector<double> out(grid.size(), 0.0);
    const double z0 = geometry.surface_altitude_m;
    if (!sun_up(geometry) || z0 >= kTopOfAtmosphereM) return out;
    const double zenith = std::clamp(zenith_deg, 0.0, 89.999);
    const double m_sun = relative_air_mass(geometry.sun_zenith_deg);
    const double m_view = relative_air_mass(zenith);
    // Light from the sun travels along −ŝ and, scattered, along −v̂ towards the surface (v̂
    // points from the surface into the sky): cos Θ = ŝ · v̂ (1 looking at the sun).
    const auto unit = [](double zenith_d, double azimuth_d) {
        const double t = zenith_d * kDegToRad;
        const double p = azimuth_d * kDegToRad;
        return std::array<double, 3>{std::sin(t) * std::sin(p), std::sin(t) * std::cos(p),
                                     std::cos(t)};
    };
    const auto s = unit(geometry.sun_zenith_deg, geometry.sun_azimuth_deg);
    const auto v = unit(zenith, azimuth_deg);
    const double cos_scatter = s[0] * v[0] + s[1] * v[1] + s[2] * v[2];
    const double mu_scatter[] = {cos_scatter};
    const double p_rayleigh = 0.75 * (1.0 + cos_scatter * cos_scatter);

    // Layers from the surface to the top; each one's altitude, 550 nm aerosol depths and gases.
    const double top = kTopOfAtmosphereM;
    const std::size_t layers = static_cast<std::size_t>(kSkyLayers);
    const std::size_t regimes = m_aerosol.regimes();
    std::vector<double> bounds(layers + 1);
    for (std::size_t k = 0; k <= layers; ++k) {
        const double f = static_cast<double>(k) / kSkyLayers;
        bounds[k] = z0 + (top - z0) * f * f;
    }
    std::vector<double> aerosol_bounds((layers + 1) * regimes);
    for (std::size_t k = 0; k <= layers; ++k) {
        for (std::size_t j = 0; j < regimes; ++j) {
            aerosol_bounds[k * regimes + j] = m_aerosol.depth_550_above(j, bounds[k]);
        }
    }
    const std::shared_ptr<const GasTransmittance> gases = gases_on(grid);
    const std::size_t n = grid.size();
    std::vector<double> log_gas_sun, log_gas_view;
    if (gases) {
        log_gas_sun.assign(layers * n, 0.0);
        log_gas_view.assign(layers * n, 0.0);
        const GasAmounts at_surface = gas_amounts_above(z0);
        for (std::size_t k = 0; k < layers; ++k) {
            const GasAmounts at = gas_amounts_above(0.5 * (bounds[k] + bounds[k + 1]));
            gases->log_transmittance(slant(at, {}, m_sun),
                                     std::span<double>(&log_gas_sun[k * n], n));
            gases->log_transmittance(slant(at_surface, at, m_view),
                                     std::span<double>(&log_gas_view[k * n], n));
        }
    }
    std::vector<double> ratio(regimes), albedo(regimes), phase(regimes);
    for (std::size_t i = 0; i < n; ++i) {
        const double wl = grid.wavelength_um(i);
        for (std::size_t j = 0; j < regimes; ++j) {
            const RegimeOptics o = m_aerosol.optics(j, wl, 0);
            ratio[j] = o.extinction_ratio;
            albedo[j] = o.single_scatter_albedo;
            phase[j] = m_aerosol.phases(j, wl, mu_scatter)[0];
        }
        const auto tau_at = [&](std::size_t k) {  // total optical depth above boundary k
            double tau = rayleigh_optical_depth(wl, bounds[k]);
            for (std::size_t j = 0; j < regimes; ++j)
                tau += ratio[j] * aerosol_bounds[k * regimes + j];
            return tau;
        };
        const double tau_surface = tau_at(0);
        double tau_a = tau_surface;
        double sum = 0.0;
        for (std::size_t k = 0; k < layers; ++k) {
            const double tau_b = tau_at(k + 1);
            const double tau_mid = 0.5 * (tau_a + tau_b);
            double source = (rayleigh_optical_depth(wl, bounds[k]) -
                             rayleigh_optical_depth(wl, bounds[k + 1])) *
                            p_rayleigh;
            for (std::size_t j = 0; j < regimes; ++j) {
                source +=
                    albedo[j] * ratio[j] *
                    (aerosol_bounds[k * regimes + j] - aerosol_bounds[(k + 1) * regimes + j]) *
                    phase[j];
            }
            const double sun = std::exp(-tau_mid * m_sun + (gases ? log_gas_sun[k * n + i] : 0.0));
            const double to_surface = std::exp(-(tau_surface - tau_mid) * m_view +
                                               (gases ? log_gas_view[k * n + i] : 0.0));
            sum += toa[i] / (4.0 * kPi) * sun * source * m_view * to_surface;
            tau_a = tau_b;
        }
        out[i] = sum;
    }
    // The higher orders (and the light the ground sends up that the sky returns), from the
    // solver: its down radiance at the ground, azimuth from the beam's direction of travel
    // (the radiance travels towards azimuth + 180°; the beam towards the sun's + 180°).
    if (const std::shared_ptr<const Scattering> ms = scattering(grid, geometry)) {
        const std::size_t ground = ms->solutions.front().levels() - 1;
        const double mu = std::max(std::cos(zenith * kDegToRad), 0.01);
        const double phi = (azimuth_deg - geometry.sun_azimuth_deg) * kDegToRad;
        const std::vector<double> multiple = ms->per_band([&](std::size_t k) {
            return ms->solutions[k].multiple_scatter_down_radiance(ground, mu, phi);
        });
        // Gases as the diffuse sky's: the direct beam's to the surface.
        const std::vector<double> gas =
            gas_transmittance(grid, slant(gas_amounts_above(z0), {}, m_sun));
        for (std::size_t i = 0; i < n; ++i) out[i] += toa[i] * std::max(multiple[i], 0.0) * gas[i];
    }
    return out;
}

}  // namespace glint::atmosphere
