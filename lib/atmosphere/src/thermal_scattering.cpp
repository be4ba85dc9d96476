// SPDX-License-Identifier: Apache-2.0
// The parametric model's thermal multiple scattering (glint/atmosphere/atmosphere.h): the
// successive-orders solution of the emitting, absorbing and scattering atmosphere above a
// surface, per band, and the in-scattered radiance it adds to the emission integral of
// air_emission.cpp along the sensor path and from the sky. docs/thermal.md, "Thermal
// multiple scattering".
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "atmosphere_detail.h"
#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/scattering_orders.h"
#include "glint/core/spectral.h"
#include "parametric_scattering.h"

namespace glint::atmosphere {

using namespace detail;

namespace {

/// A layer's absorption optical depth from its gas transmittance is capped here: such a
/// layer is opaque (e^−30), and the cap bounds the solver's sublayers.
constexpr double kMaxGasDepth = 30.0;

}  // namespace

std::shared_ptr<const ParametricAtmosphereModel::ThermalScattering>
ParametricAtmosphereModel::thermal_scattering(const SpectralGrid& grid, double surface_m,
                                              double sensor_m) const {
    const double z0 = std::round(surface_m / kScatteringAltitudeStepM) * kScatteringAltitudeStepM;
    const double z1 =
        std::max(z0, std::round(sensor_m / kScatteringAltitudeStepM) * kScatteringAltitudeStepM);
    const std::vector<double> wavelengths(grid.wavelengths_um().begin(),
                                          grid.wavelengths_um().end());
    const std::lock_guard<std::mutex> lock(m_scattering_mutex);
    for (const auto& cached : m_thermal_scattering) {
        if (cached->surface_altitude_m == z0 && cached->sensor_altitude_m == z1 &&
            cached->grid == wavelengths) {
            return cached;
        }
    }
    auto out = std::make_shared<ThermalScattering>();
    out->grid = wavelengths;
    out->surface_altitude_m = z0;
    out->sensor_altitude_m = z1;
    out->bands.resize(grid.size());
    // The solar solutions' layers.
    const ScatteringLevels levels = scattering_levels(z0, z1);
    const std::vector<double>& bounds = levels.bounds;
    const std::size_t layers = bounds.size() - 1;
    out->sensor_level = levels.sensor_level;
    out->ground_level = layers;
    if (!m_parameters.multiple_scattering || z0 >= kTopOfAtmosphereM) return out;

    // ln of each layer's vertical gas transmittance, [layer][band] (bottom first).
    const std::shared_ptr<const GasTransmittance> gases = gases_on(grid);
    const std::size_t n = grid.size();
    std::vector<double> log_gas(layers * n, 0.0);
    if (gases) {
        for (std::size_t k = 0; k < layers; ++k) {
            gases->log_transmittance(
                slant(gas_amounts_above(bounds[k]), gas_amounts_above(bounds[k + 1]), 1.0),
                std::span<double>(&log_gas[k * n], n));
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double wl = grid.wavelength_um(i);
        if (wl < kThermalScatteringFromUm) continue;
        constexpr int kStreams = 8;
        const std::vector<RegimeOptics> aerosol = solver_aerosol_optics(m_aerosol, wl, kStreams);
        double column_scattering = rayleigh_optical_depth(wl, z0);
        for (std::size_t j = 0; j < aerosol.size(); ++j) {
            column_scattering += aerosol[j].single_scatter_albedo * aerosol[j].extinction_ratio *
                                 m_aerosol.depth_550_above(j, z0);
        }
        if (column_scattering < kThermalScatteringMinDepth) continue;
        ScatteringProblem problem;
        problem.beam_irradiance = 0.0;
        problem.streams = kStreams;
        problem.azimuth_modes = 1;  // isotropic sources: the field has no azimuth
        problem.max_sublayer_depth = 0.05;
        problem.tolerance = 1e-5;
        // A black ground at the air's temperature there: the surface's own emission and
        // reflection are the renderer's.
        problem.ground_albedo = 0.0;
        problem.ground_planck = planck_radiance_w_per_cm2_sr_um(wl, air_temperature_k(z0));
        for (std::size_t k = layers + 1; k-- > 0;) {  // levels, top first
            problem.level_planck.push_back(
                planck_radiance_w_per_cm2_sr_um(wl, air_temperature_k(bounds[k])));
        }
        for (std::size_t k = layers; k-- > 0;) {  // layers, top first
            const double rayleigh =
                rayleigh_optical_depth(wl, bounds[k]) - rayleigh_optical_depth(wl, bounds[k + 1]);
            std::vector<AerosolShare> shares;
            for (std::size_t j = 0; j < aerosol.size(); ++j) {
                const double depth = (m_aerosol.depth_550_above(j, bounds[k]) -
                                      m_aerosol.depth_550_above(j, bounds[k + 1])) *
                                     aerosol[j].extinction_ratio;
                shares.push_back({depth, aerosol[j].single_scatter_albedo, aerosol[j].moments});
            }
            const double gas = std::min(-log_gas[k * n + i], kMaxGasDepth);
            problem.layers.push_back(scattering_layer(rayleigh, shares, gas, problem.streams));
        }
        out->bands[i] = solve_scattering_orders(problem);
    }
    constexpr std::size_t kKept = 64;
    if (m_thermal_scattering.size() >= kKept)
        m_thermal_scattering.erase(m_thermal_scattering.begin());
    m_thermal_scattering.push_back(out);
    return out;
}

std::vector<double> ParametricAtmosphereModel::thermal_in_scatter_w_per_cm2_sr_um(
    const SpectralGrid& grid, double surface_m, double sensor_m, double mu, bool upward) const {
    std::vector<double> out(grid.size(), 0.0);
    if (!m_parameters.multiple_scattering) return out;
    const std::shared_ptr<const ThermalScattering> ts =
        thermal_scattering(grid, surface_m, sensor_m);
    // Grazing directions take the horizon's slant through the plane-parallel layers at this
    // cosine (the Kasten–Young air mass caps near 38 as well).
    const double cosine = std::clamp(mu, 1.0 / 38.0, 1.0);
    for (std::size_t i = 0; i < grid.size(); ++i) {
        if (!ts->bands[i]) continue;
        const ScatteringSolution& s = *ts->bands[i];
        out[i] =
            std::max(0.0, upward ? s.multiple_scatter_up_radiance(ts->sensor_level, cosine, 0.0)
                                 : s.multiple_scatter_down_radiance(ts->ground_level, cosine, 0.0));
    }
    return out;
}

}  // namespace glint::atmosphere
