// SPDX-License-Identifier: Apache-2.0
// The plain atmospheres of glint/atmosphere/atmosphere.h: none (the exo-atmospheric sun, a
// black sky, no path) and simple (DIRSIG .atm: the same with the sky at a temperature).
#include <cmath>
#include <vector>

#include "atmosphere_detail.h"
#include "glint/atmosphere/atmosphere.h"
#include "glint/core/error.h"

namespace glint::atmosphere {

using namespace detail;

// ---- none ----

std::vector<double> NoAtmosphere::sun_transmittance(const SpectralGrid& grid,
                                                    const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    return filled(grid, sun_up(geometry) ? 1.0 : 0.0);
}

std::vector<double> NoAtmosphere::sensor_transmittance(const SpectralGrid& grid,
                                                       const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    return filled(grid, 1.0);
}

std::vector<double> NoAtmosphere::path_radiance_w_per_cm2_sr_um(const SpectralGrid& grid,
                                                                const AtmosphereGeometry& geometry,
                                                                std::span<const double> toa) const {
    check_geometry(geometry);
    check_size(grid, toa);
    return filled(grid, 0.0);
}

std::vector<double> NoAtmosphere::diffuse_sky_irradiance_w_per_cm2_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> toa) const {
    check_geometry(geometry);
    check_size(grid, toa);
    return filled(grid, 0.0);
}

std::vector<double> NoAtmosphere::thermal_sky_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    return filled(grid, 0.0);
}

// ---- simple (.atm) ----

SimpleAtmosphereModel::SimpleAtmosphereModel(model::SimpleAtmosphere parameters)
    : m_parameters(parameters) {
    if (!std::isfinite(m_parameters.apparent_sky_temperature_k) ||
        m_parameters.apparent_sky_temperature_k < 0.0) {
        throw input_error("apparent sky temperature must be >= 0 K");
    }
}

std::vector<double> SimpleAtmosphereModel::sun_transmittance(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    return NoAtmosphere{}.sun_transmittance(grid, geometry);
}

std::vector<double> SimpleAtmosphereModel::sensor_transmittance(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    return NoAtmosphere{}.sensor_transmittance(grid, geometry);
}

std::vector<double> SimpleAtmosphereModel::path_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> toa) const {
    return NoAtmosphere{}.path_radiance_w_per_cm2_sr_um(grid, geometry, toa);
}

std::vector<double> SimpleAtmosphereModel::diffuse_sky_irradiance_w_per_cm2_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> toa) const {
    return NoAtmosphere{}.diffuse_sky_irradiance_w_per_cm2_um(grid, geometry, toa);
}

std::vector<double> SimpleAtmosphereModel::thermal_sky_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    std::vector<double> out;
    out.reserve(grid.size());
    for (double wl : grid.wavelengths_um()) {
        out.push_back(planck_radiance_w_per_cm2_sr_um(wl, m_parameters.apparent_sky_temperature_k));
    }
    return out;
}

}  // namespace glint::atmosphere
