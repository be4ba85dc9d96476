// SPDX-License-Identifier: Apache-2.0
// The parametric model's multiple scattering (glint/atmosphere/atmosphere.h): the
// plane-parallel successive-orders solutions of a geometry's layered atmosphere at wavelength
// nodes (kept for the last few geometries), and the path radiance they add. docs/physics.md,
// "Multiple scattering".
#include "parametric_scattering.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "atmosphere_detail.h"
#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/scattering_orders.h"

namespace glint::atmosphere {

using namespace detail;

ScatteringLevels scattering_levels(double z0, double z1) {
    constexpr int kLayers = ParametricAtmosphereModel::kScatteringLayers;
    const double top = std::max(z0, kTopOfAtmosphereM);
    ScatteringLevels out;
    for (int k = 0; k <= kLayers; ++k) {
        const double f = static_cast<double>(k) / kLayers;
        out.bounds.push_back(z0 + (top - z0) * f * f * f);
    }
    if (z1 > z0 && z1 < top) out.bounds.push_back(z1);
    std::sort(out.bounds.begin(), out.bounds.end());
    out.bounds.erase(std::unique(out.bounds.begin(), out.bounds.end()), out.bounds.end());
    const std::size_t layers = out.bounds.size() - 1;
    const auto at_sensor = std::find(out.bounds.begin(), out.bounds.end(), std::min(z1, top));
    out.sensor_level = layers - static_cast<std::size_t>(at_sensor - out.bounds.begin());
    return out;
}

ScatteringLayer scattering_layer(double rayleigh, std::span<const AerosolShare> aerosols,
                                 double absorption, int streams, double* truncated_depth) {
    const std::size_t kept = static_cast<std::size_t>(2 * streams);
    double tau = std::max(0.0, rayleigh) + std::max(0.0, absorption);
    double scattering = std::max(0.0, rayleigh);
    std::vector<double> mixed(kept + 1, 0.0);  // Σ scattering depth × χ_l
    for (std::size_t l = 0; l <= kept; ++l) {
        mixed[l] = scattering * (l == 0 ? 1.0 : (l == 2 ? 0.1 : 0.0));
    }
    for (const AerosolShare& a : aerosols) {
        if (!(a.optical_depth > 0.0)) continue;
        tau += a.optical_depth;
        const double s = a.single_scatter_albedo * a.optical_depth;
        scattering += s;
        for (std::size_t l = 0; l <= kept && l < a.moments.size(); ++l)
            mixed[l] += s * a.moments[l];
    }
    ScatteringLayer layer;
    layer.moments.assign(kept, 0.0);
    layer.moments[0] = 1.0;
    if (truncated_depth) *truncated_depth = 0.0;
    if (!(tau > 0.0) || !(scattering > 0.0)) {
        layer.optical_depth = tau;
        layer.single_scatter_albedo = 0.0;
        return layer;
    }
    const double omega = std::clamp(scattering / tau, 0.0, 1.0);
    const double f = std::clamp(mixed[kept] / scattering, 0.0, 1.0 - 1e-9);
    layer.optical_depth = (1.0 - omega * f) * tau;
    layer.single_scatter_albedo = std::clamp(omega * (1.0 - f) / (1.0 - omega * f), 0.0, 1.0);
    for (std::size_t l = 1; l < kept; ++l) {
        layer.moments[l] = (mixed[l] / scattering - f) / (1.0 - f);
    }
    if (truncated_depth) *truncated_depth = omega * f * tau;
    return layer;
}

std::vector<RegimeOptics> solver_aerosol_optics(const AerosolColumn& column, double wavelength_um,
                                                int streams) {
    std::vector<RegimeOptics> out;
    for (std::size_t j = 0; j < column.regimes(); ++j) {
        out.push_back(column.optics(j, wavelength_um, static_cast<std::size_t>(2 * streams + 1)));
    }
    return out;
}

std::shared_ptr<const ParametricAtmosphereModel::Scattering> ParametricAtmosphereModel::scattering(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    if (!m_parameters.multiple_scattering || !sun_up(geometry) ||
        geometry.surface_altitude_m >= kTopOfAtmosphereM) {
        return nullptr;
    }
    // The solutions are computed for the geometry rounded (sun zenith to
    // kScatteringZenithStepDeg, altitudes to kScatteringAltitudeStepM), always, so that the
    // captures of a sequence share them and what a cached entry holds never depends on which
    // query made it.
    const double sun_zenith_deg = std::min(
        std::round(geometry.sun_zenith_deg / kScatteringZenithStepDeg) * kScatteringZenithStepDeg,
        89.95);
    const double z0 = std::round(geometry.surface_altitude_m / kScatteringAltitudeStepM) *
                      kScatteringAltitudeStepM;
    const double z1 =
        std::max(z0, std::round(geometry.sensor_altitude_m / kScatteringAltitudeStepM) *
                         kScatteringAltitudeStepM);
    const std::vector<double> wavelengths(grid.wavelengths_um().begin(),
                                          grid.wavelengths_um().end());
    const std::lock_guard<std::mutex> lock(m_scattering_mutex);
    for (const auto& cached : m_scattering) {
        if (cached->sun_zenith_deg == sun_zenith_deg && cached->surface_altitude_m == z0 &&
            cached->sensor_altitude_m == z1 && cached->grid == wavelengths) {
            return cached;
        }
    }
    auto out = std::make_shared<Scattering>();
    out->grid = wavelengths;
    out->sun_zenith_deg = sun_zenith_deg;
    out->surface_altitude_m = z0;
    out->sensor_altitude_m = z1;
    // Nodes.
    std::vector<double> nodes;
    if (grid.size() <= kScatteringNodes) {
        nodes = wavelengths;
    } else {
        const double lo = std::log(grid.min_um());
        const double hi = std::log(grid.max_um());
        for (std::size_t k = 0; k < kScatteringNodes; ++k) {
            nodes.push_back(std::exp(lo + (hi - lo) * static_cast<double>(k) /
                                              static_cast<double>(kScatteringNodes - 1)));
        }
    }
    for (const double wl : wavelengths) {
        const auto above = std::upper_bound(nodes.begin(), nodes.end(), wl);
        std::size_t k =
            above == nodes.begin() ? 0 : static_cast<std::size_t>(above - nodes.begin()) - 1;
        double f = 0.0;
        if (k + 1 >= nodes.size()) {
            k = nodes.size() - 1;
        } else {
            f = std::clamp(std::log(wl / nodes[k]) / std::log(nodes[k + 1] / nodes[k]), 0.0, 1.0);
        }
        out->lower.push_back(k);
        out->fraction.push_back(f);
    }
    const ScatteringLevels levels = scattering_levels(z0, z1);
    const std::vector<double>& bounds = levels.bounds;
    const std::size_t layers = bounds.size() - 1;
    out->sensor_level = levels.sensor_level;
    for (const double wl : nodes) {
        ScatteringProblem problem;
        problem.sun_cos_zenith = std::min(1.0, 1.0 / relative_air_mass(sun_zenith_deg));
        problem.ground_albedo = m_parameters.ground_albedo;
        problem.streams = 8;
        problem.azimuth_modes = 6;
        problem.max_sublayer_depth = 0.02;
        problem.tolerance = 1e-5;
        const std::vector<RegimeOptics> aerosol =
            solver_aerosol_optics(m_aerosol, wl, problem.streams);
        double truncated = 0.0;  // the column's forward peak, moved to the direct beam
        for (std::size_t k = layers; k-- > 0;) {  // top first
            const double rayleigh =
                rayleigh_optical_depth(wl, bounds[k]) - rayleigh_optical_depth(wl, bounds[k + 1]);
            std::vector<AerosolShare> shares;
            for (std::size_t j = 0; j < aerosol.size(); ++j) {
                const double depth = (m_aerosol.depth_550_above(j, bounds[k]) -
                                      m_aerosol.depth_550_above(j, bounds[k + 1])) *
                                     aerosol[j].extinction_ratio;
                shares.push_back({depth, aerosol[j].single_scatter_albedo, aerosol[j].moments});
            }
            double cut = 0.0;
            problem.layers.push_back(
                scattering_layer(rayleigh, shares, 0.0, problem.streams, &cut));
            truncated += cut;
        }
        // The peak's light reaches the ground with the scaled beam, e^(−τ'/μ₀) where the
        // direct sun is e^(−τ/μ₀): what the scaled beam carries beyond the direct sun is
        // diffuse light from around the sun.
        const double tau = rayleigh_optical_depth(wl, z0) + aerosol_optical_depth(wl, z0);
        const double mu0 = problem.sun_cos_zenith;
        out->forward_peak.push_back(mu0 *
                                    (std::exp(-(tau - truncated) / mu0) - std::exp(-tau / mu0)));
        out->solutions.push_back(solve_scattering_orders(problem));
    }
    // Enough for every level of a scene's environment (sky and sensor path of each), so a
    // sequence of captures at one sun geometry solves each level once.
    constexpr std::size_t kKept = 64;
    if (m_scattering.size() >= kKept) m_scattering.erase(m_scattering.begin());
    m_scattering.push_back(out);
    return out;
}

void ParametricAtmosphereModel::add_multiple_scattering(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry, std::span<const double> toa,
    std::span<const double> view_azimuths_deg, std::vector<std::vector<double>>& out) const {
    const std::shared_ptr<const Scattering> ms = scattering(grid, geometry);
    if (!ms) return;
    const double z0 = geometry.surface_altitude_m;
    const double z1 = std::max(z0, geometry.sensor_altitude_m);
    const double mu_v =
        std::max(std::cos(std::clamp(geometry.view_zenith_deg, 0.0, 90.0) * kDegToRad), 0.01);
    std::vector<std::vector<double>> modes;
    for (const ScatteringSolution& solution : ms->solutions) {
        modes.push_back(solution.multiple_scatter_up_modes(ms->sensor_level, mu_v));
    }
    // Gases: the direct beam's to the surface and the view path's (the 6S approximation:
    // multiply scattered light by the transmittances of the sun's and the sensor's paths).
    const double m_sun = relative_air_mass(geometry.sun_zenith_deg);
    const double m_view = relative_air_mass(geometry.view_zenith_deg);
    const std::vector<double> gas_sun =
        gas_transmittance(grid, slant(gas_amounts_above(z0), {}, m_sun));
    const std::vector<double> gas_view =
        gas_transmittance(grid, slant(gas_amounts_above(z0), gas_amounts_above(z1), m_view));
    for (std::size_t a = 0; a < view_azimuths_deg.size(); ++a) {
        // Azimuth from the beam's direction of travel (the sun's azimuth + 180°).
        const double phi = (view_azimuths_deg[a] - geometry.sun_azimuth_deg - 180.0) * kDegToRad;
        const std::vector<double> reflectance =
            ms->per_band([&](std::size_t k) { return sum_modes(modes[k], phi); });
        for (std::size_t i = 0; i < grid.size(); ++i) {
            out[a][i] += toa[i] * std::max(reflectance[i], 0.0) * gas_sun[i] * gas_view[i];
        }
    }
}

}  // namespace glint::atmosphere
