// SPDX-License-Identifier: Apache-2.0
// The tabulated atmosphere of glint/atmosphere/atmosphere.h: a user table of one geometry,
// linearly interpolated in wavelength.
#include <utility>
#include <vector>

#include "atmosphere_detail.h"
#include "glint/atmosphere/atmosphere.h"
#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::atmosphere {

using namespace detail;

// ---- tabulated ----

TabulatedAtmosphereModel::TabulatedAtmosphereModel(model::TabulatedAtmosphere table)
    : m_table(std::move(table)) {
    const std::size_t n = m_table.wavelengths_um.size();
    const bool thermal_ok = m_table.thermal_sky_radiance_w_per_cm2_sr_um.empty() ||
                            m_table.thermal_sky_radiance_w_per_cm2_sr_um.size() == n;
    if (n < 2 || m_table.sun_transmittance.size() != n ||
        m_table.sensor_transmittance.size() != n ||
        m_table.path_radiance_w_per_cm2_sr_um.size() != n ||
        m_table.sky_irradiance_w_per_cm2_um.size() != n || !thermal_ok) {
        throw input_error("atmosphere table needs at least 2 rows and columns of equal length",
                          ErrorContext{m_table.table_file, 0, {}});
    }
    // Validates increasing, finite wavelengths.
    (void)SpectralCurve(m_table.wavelengths_um, m_table.sun_transmittance,
                        ErrorContext{m_table.table_file, 0, {}});
}

std::vector<double> TabulatedAtmosphereModel::sample(const SpectralGrid& grid,
                                                     const std::vector<double>& column) const {
    const double lo = m_table.wavelengths_um.front();
    const double hi = m_table.wavelengths_um.back();
    const double tolerance = 1e-9 * hi;
    if (grid.min_um() < lo - tolerance || grid.max_um() > hi + tolerance) {
        throw input_error("spectral grid " + format_shortest(grid.min_um()) + "-" +
                              format_shortest(grid.max_um()) +
                              " um reaches outside the atmosphere table's " + format_shortest(lo) +
                              "-" + format_shortest(hi) + " um",
                          ErrorContext{m_table.table_file, 0, {}});
    }
    const SpectralCurve curve(m_table.wavelengths_um, column);
    std::vector<double> out;
    out.reserve(grid.size());
    for (double wl : grid.wavelengths_um()) {
        out.push_back(curve.value_at(std::clamp(wl, lo, hi)));
    }
    return out;
}

std::vector<double> TabulatedAtmosphereModel::sun_transmittance(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    if (!sun_up(geometry)) return filled(grid, 0.0);
    return sample(grid, m_table.sun_transmittance);
}

std::vector<double> TabulatedAtmosphereModel::sensor_transmittance(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    return sample(grid, m_table.sensor_transmittance);
}

std::vector<double> TabulatedAtmosphereModel::path_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> toa) const {
    check_geometry(geometry);
    check_size(grid, toa);
    return sample(grid, m_table.path_radiance_w_per_cm2_sr_um);
}

std::vector<double> TabulatedAtmosphereModel::diffuse_sky_irradiance_w_per_cm2_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> toa) const {
    check_geometry(geometry);
    check_size(grid, toa);
    return sample(grid, m_table.sky_irradiance_w_per_cm2_um);
}

std::vector<double> TabulatedAtmosphereModel::thermal_sky_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    if (!m_table.thermal_sky_radiance_w_per_cm2_sr_um.empty()) {
        return sample(grid, m_table.thermal_sky_radiance_w_per_cm2_sr_um);
    }
    std::vector<double> out;
    out.reserve(grid.size());
    for (double wl : grid.wavelengths_um()) {
        out.push_back(planck_radiance_w_per_cm2_sr_um(wl, m_table.sky_temperature_k));
    }
    return out;
}

}  // namespace glint::atmosphere
