// SPDX-License-Identifier: Apache-2.0
// What every atmosphere model shares (glint/atmosphere/atmosphere.h): the relative air mass
// and its inverse, the interface's default sky radiance and per-azimuth path radiance, and the
// factory. The models: plain_atmospheres.cpp (none, simple), parametric_atmosphere.cpp and
// parametric_scattering.cpp, tabulated_atmosphere.cpp. Formulas: docs/physics.md
// ("Atmosphere and sun").
#include "glint/atmosphere/atmosphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <utility>

#include "atmosphere_detail.h"
#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::atmosphere {

using namespace detail;

double relative_air_mass(double zenith_deg) noexcept {
    const double z = std::clamp(zenith_deg, 0.0, 90.0);
    return 1.0 / (std::cos(z * kDegToRad) + 0.50572 * std::pow(96.07995 - z, -1.6364));
}

double zenith_for_relative_air_mass(double air_mass) {
    if (!(air_mass >= relative_air_mass(0.0)) || !(air_mass <= relative_air_mass(90.0))) {
        throw input_error("air mass " + format_shortest(air_mass) + " is outside " +
                          format_shortest(relative_air_mass(0.0)) + "-" +
                          format_shortest(relative_air_mass(90.0)));
    }
    double lo = 0.0;
    double hi = 90.0;
    while (hi - lo > 1e-12) {  // relative_air_mass grows with the zenith angle
        const double mid = 0.5 * (lo + hi);
        (relative_air_mass(mid) < air_mass ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

std::vector<double> AtmosphereModel::sky_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry,
    std::span<const double> toa_irradiance_w_per_cm2_um) const {
    std::vector<double> sky =
        diffuse_sky_irradiance_w_per_cm2_um(grid, geometry, toa_irradiance_w_per_cm2_um);
    const std::vector<double> thermal = thermal_sky_radiance_w_per_cm2_sr_um(grid, geometry);
    for (std::size_t i = 0; i < sky.size(); ++i) sky[i] = sky[i] / kPi + thermal[i];
    return sky;
}

// ---- every model ----

std::vector<std::vector<double>> AtmosphereModel::path_radiance_at_azimuths(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry, std::span<const double> toa,
    std::span<const double> view_azimuths_deg) const {
    std::vector<std::vector<double>> out;
    AtmosphereGeometry g = geometry;
    for (double azimuth : view_azimuths_deg) {
        g.view_azimuth_deg = azimuth;
        out.push_back(path_radiance_w_per_cm2_sr_um(grid, g, toa));
    }
    return out;
}

std::unique_ptr<AtmosphereModel> make_atmosphere_model(
    const model::Atmosphere& atmosphere, std::shared_ptr<const GasBandModel> gases,
    std::shared_ptr<const AerosolTable> aerosols) {
    try {
        switch (atmosphere.kind) {
            case model::AtmosphereKind::none:
                return std::make_unique<NoAtmosphere>();
            case model::AtmosphereKind::parametric:
                return std::make_unique<ParametricAtmosphereModel>(
                    atmosphere.parametric, std::move(gases), std::move(aerosols));
            case model::AtmosphereKind::tabulated:
                return std::make_unique<TabulatedAtmosphereModel>(atmosphere.tabulated);
            case model::AtmosphereKind::simple:
                return std::make_unique<SimpleAtmosphereModel>(atmosphere.simple);
        }
    } catch (const Error& e) {
        throw e.with_file(atmosphere.where.file, atmosphere.where.line);
    }
    throw internal_error("unknown atmosphere kind");
}

bool needs_gas_table(const model::Atmosphere& atmosphere) {
    return atmosphere.kind == model::AtmosphereKind::parametric &&
           atmosphere.parametric.gas_absorption;
}

bool needs_aerosol_table(const model::Atmosphere& atmosphere) {
    return atmosphere.kind == model::AtmosphereKind::parametric &&
           (!atmosphere.parametric.aerosol_model.empty() ||
            atmosphere.parametric.aerosol_profile.has_value());
}

}  // namespace glint::atmosphere
