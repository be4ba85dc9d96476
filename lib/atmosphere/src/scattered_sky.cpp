// SPDX-License-Identifier: Apache-2.0
// The parametric model's scattered sky radiance by direction (glint/atmosphere/atmosphere.h,
// ParametricAtmosphereModel::scattered_sky_radiance_w_per_cm2_sr_um): the exact single
// scattering of the direct sun along a line of sight from the surface up to the top, plus the
// successive-orders solution's higher orders arriving from that direction. docs/physics.md,
// "The scattered sky's radiance".
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
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
    const double zenith[] = {zenith_deg};
    const double azimuth[] = {azimuth_deg};
    return std::move(scattered_sky_radiances(grid, geometry, toa, zenith, azimuth).front());
}

std::vector<std::vector<double>> ParametricAtmosphereModel::scattered_sky_at_directions(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry, std::span<const double> toa,
    std::span<const double> zeniths_deg, std::span<const double> azimuths_deg) const {
    if (!m_parameters.directional_sky) return {};
    return scattered_sky_radiances(grid, geometry, toa, zeniths_deg, azimuths_deg);
}

std::vector<std::vector<double>> ParametricAtmosphereModel::scattered_sky_radiances(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry, std::span<const double> toa,
    std::span<const double> zeniths_deg, std::span<const double> azimuths_deg) const {
    check_geometry(geometry);
    check_size(grid, toa);
    for (const double d : zeniths_deg) {
        if (!std::isfinite(d)) throw input_error("sky radiance at a non-finite zenith");
    }
    for (const double d : azimuths_deg) {
        if (!std::isfinite(d)) throw input_error("sky radiance at a non-finite azimuth");
    }
    const std::size_t n = grid.size();
    const std::size_t azimuths = azimuths_deg.size();
    std::vector<std::vector<double>> out(zeniths_deg.size() * azimuths,
                                         std::vector<double>(n, 0.0));
    const double z0 = geometry.surface_altitude_m;
    if (!sun_up(geometry) || z0 >= kTopOfAtmosphereM || out.empty()) return out;
    const double m_sun = relative_air_mass(geometry.sun_zenith_deg);
    // Light from the sun travels along −ŝ and, scattered, along −v̂ towards the surface (v̂
    // points from the surface into the sky): cos Θ = ŝ · v̂ (1 looking at the sun).
    const auto unit = [](double zenith_d, double azimuth_d) {
        const double t = zenith_d * kDegToRad;
        const double p = azimuth_d * kDegToRad;
        return std::array<double, 3>{std::sin(t) * std::sin(p), std::sin(t) * std::cos(p),
                                     std::cos(t)};
    };
    const auto s = unit(geometry.sun_zenith_deg, geometry.sun_azimuth_deg);

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
    std::vector<GasAmounts> gas_at;  // above the middle of each layer
    std::vector<double> log_gas_sun, log_gas_view;
    const GasAmounts at_surface = gases ? gas_amounts_above(z0) : GasAmounts{};
    if (gases) {
        log_gas_sun.assign(layers * n, 0.0);
        log_gas_view.assign(layers * n, 0.0);
        for (std::size_t k = 0; k < layers; ++k) {
            gas_at.push_back(gas_amounts_above(0.5 * (bounds[k] + bounds[k + 1])));
            gases->log_transmittance(slant(gas_at[k], {}, m_sun),
                                     std::span<double>(&log_gas_sun[k * n], n));
        }
    }
    const std::shared_ptr<const Scattering> ms = scattering(grid, geometry);
    // Gases on the solver's light as on the diffuse sky's: the direct beam's to the surface.
    const std::vector<double> ms_gas =
        ms ? gas_transmittance(grid, slant(gas_amounts_above(z0), {}, m_sun))
           : std::vector<double>{};

    std::vector<double> ratio(regimes), albedo(regimes);
    std::vector<double> cos_scatter(azimuths), p_rayleigh(azimuths);
    std::vector<std::vector<double>> phase(regimes);
    std::vector<double> sums(1 + regimes);
    for (std::size_t z = 0; z < zeniths_deg.size(); ++z) {
        const double zenith = std::clamp(zeniths_deg[z], 0.0, 89.999);
        const double m_view = relative_air_mass(zenith);
        for (std::size_t a = 0; a < azimuths; ++a) {
            const auto v = unit(zenith, azimuths_deg[a]);
            cos_scatter[a] = std::clamp(s[0] * v[0] + s[1] * v[1] + s[2] * v[2], -1.0, 1.0);
            p_rayleigh[a] = 0.75 * (1.0 + cos_scatter[a] * cos_scatter[a]);
        }
        if (gases) {
            for (std::size_t k = 0; k < layers; ++k) {
                gases->log_transmittance(slant(at_surface, gas_at[k], m_view),
                                         std::span<double>(&log_gas_view[k * n], n));
            }
        }
        std::vector<double>* row = &out[z * azimuths];
        for (std::size_t i = 0; i < n; ++i) {
            const double wl = grid.wavelength_um(i);
            for (std::size_t j = 0; j < regimes; ++j) {
                const RegimeOptics o = m_aerosol.optics(j, wl, 0);
                ratio[j] = o.extinction_ratio;
                albedo[j] = o.single_scatter_albedo;
                phase[j] = m_aerosol.phases(j, wl, cos_scatter);
            }
            const auto tau_at = [&](std::size_t k) {  // total optical depth above boundary k
                double tau = rayleigh_optical_depth(wl, bounds[k]);
                for (std::size_t j = 0; j < regimes; ++j)
                    tau += ratio[j] * aerosol_bounds[k * regimes + j];
                return tau;
            };
            // The phase functions do not depend on the layer: Σ_k w_k Δτ_k p(Θ) is p(Θ) times
            // the sum of the weighted depths, one sum for the air and one per regime.
            std::fill(sums.begin(), sums.end(), 0.0);
            const double tau_surface = tau_at(0);
            double tau_a = tau_surface;
            for (std::size_t k = 0; k < layers; ++k) {
                const double tau_b = tau_at(k + 1);
                const double tau_mid = 0.5 * (tau_a + tau_b);
                const double sun =
                    std::exp(-tau_mid * m_sun + (gases ? log_gas_sun[k * n + i] : 0.0));
                const double to_surface = std::exp(-(tau_surface - tau_mid) * m_view +
                                                   (gases ? log_gas_view[k * n + i] : 0.0));
                const double w = toa[i] / (4.0 * kPi) * sun * m_view * to_surface;
                sums[0] += w * (rayleigh_optical_depth(wl, bounds[k]) -
                                rayleigh_optical_depth(wl, bounds[k + 1]));
                for (std::size_t j = 0; j < regimes; ++j) {
                    sums[1 + j] +=
                        w * albedo[j] * ratio[j] *
                        (aerosol_bounds[k * regimes + j] - aerosol_bounds[(k + 1) * regimes + j]);
                }
                tau_a = tau_b;
            }
            for (std::size_t a = 0; a < azimuths; ++a) {
                double value = sums[0] * p_rayleigh[a];
                for (std::size_t j = 0; j < regimes; ++j) value += sums[1 + j] * phase[j][a];
                row[a][i] = value;
            }
        }
        // The higher orders (and the light the ground sends up that the sky returns), from
        // the solver: its down radiance at the ground, azimuth from the beam's direction of
        // travel (the radiance travels towards azimuth + 180°; the beam towards the sun's +
        // 180°).
        if (ms) {
            const std::size_t ground = ms->solutions.front().levels() - 1;
            const double mu = std::max(std::cos(zenith * kDegToRad), 0.01);
            // The Fourier terms of each node's radiance at this zenith, summed per azimuth.
            std::vector<std::vector<double>> modes;
            for (const ScatteringSolution& solution : ms->solutions) {
                modes.push_back(solution.multiple_scatter_down_modes(ground, mu));
            }
            for (std::size_t a = 0; a < azimuths; ++a) {
                const double phi = (azimuths_deg[a] - geometry.sun_azimuth_deg) * kDegToRad;
                const std::vector<double> multiple =
                    ms->per_band([&](std::size_t k) { return sum_modes(modes[k], phi); });
                for (std::size_t i = 0; i < n; ++i) {
                    row[a][i] += toa[i] * std::max(multiple[i], 0.0) * ms_gas[i];
                }
            }
        }
    }
    return out;
}

}  // namespace glint::atmosphere
