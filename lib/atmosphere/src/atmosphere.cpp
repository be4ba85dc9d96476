// SPDX-License-Identifier: Apache-2.0
// The atmosphere models of glint/atmosphere/atmosphere.h: none, simple (.atm), parametric
// (Rayleigh + aerosol, Beer–Lambert with the Kasten–Young air mass, single scattering
// integrated over altitude layers) and tabulated. Formulas: docs/physics.md ("Atmosphere and sun").
#include "glint/atmosphere/atmosphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <utility>

#include "glint/atmosphere/scattering_orders.h"
#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::atmosphere {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegToRad = kPi / 180.0;
/// Top of the parametric atmosphere: above it the optical depth is < 1e-5 of the total.
constexpr double kTopOfAtmosphereM = 100'000.0;
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

/// Slant amounts: the vertical amounts between two altitudes (`above_low` − `above_high`)
/// times the air mass `m`.
GasAmounts slant(const GasAmounts& above_low, const GasAmounts& above_high, double m) {
    return GasAmounts{std::max(above_low.water_cm - above_high.water_cm, 0.0) * m,
                      std::max(above_low.ozone_atm_cm - above_high.ozone_atm_cm, 0.0) * m,
                      std::max(above_low.mixed_air_masses - above_high.mixed_air_masses, 0.0) * m};
}

/// The aerosol optical depth above sea level at λ (Ångström's law from τ(550 nm)); at
/// altitude z it is this × e^(−z/H_A).
double aerosol_sea_level(const model::ParametricAtmosphere& p, double wavelength_um) {
    return p.aerosol_optical_depth_550 * std::pow(wavelength_um / 0.55, -p.angstrom_exponent);
}

void check_geometry(const AtmosphereGeometry& g) {
    const std::array<double, 6> values{g.sun_zenith_deg,    g.sun_azimuth_deg, g.surface_altitude_m,
                                       g.sensor_altitude_m, g.view_zenith_deg, g.view_azimuth_deg};
    for (double v : values) {
        if (!std::isfinite(v)) throw input_error("atmosphere query with a non-finite geometry");
    }
}

void check_size(const SpectralGrid& grid, std::span<const double> values) {
    if (values.size() != grid.size()) {
        throw input_error("solar irradiance has " + std::to_string(values.size()) +
                          " values for a grid of " + std::to_string(grid.size()));
    }
}

bool sun_up(const AtmosphereGeometry& g) { return g.sun_zenith_deg < 90.0; }

/// Unit vector in ENU for (zenith, azimuth clockwise from north), degrees.
std::array<double, 3> direction(double zenith_deg, double azimuth_deg) {
    const double t = zenith_deg * kDegToRad;
    const double p = azimuth_deg * kDegToRad;
    return {std::sin(t) * std::sin(p), std::sin(t) * std::cos(p), std::cos(t)};
}

double rayleigh_phase(double cos_theta) { return 0.75 * (1.0 + cos_theta * cos_theta); }

double henyey_greenstein(double g, double cos_theta) {
    const double denom = 1.0 + g * g - 2.0 * g * cos_theta;
    return (1.0 - g * g) / (denom * std::sqrt(denom));
}

/// Fraction of Henyey–Greenstein scattering into the forward hemisphere.
double hg_forward_fraction(double g) {
    if (std::abs(g) < 1e-6) return 0.5;
    return (1.0 + g) / (2.0 * g) - (1.0 - g * g) / (2.0 * g * std::sqrt(1.0 + g * g));
}

std::vector<double> filled(const SpectralGrid& grid, double value) {
    return std::vector<double>(grid.size(), value);
}

}  // namespace

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

// ---- parametric ----

ParametricAtmosphereModel::ParametricAtmosphereModel(model::ParametricAtmosphere parameters,
                                                     std::shared_ptr<const GasBandModel> gases)
    : m_parameters(parameters), m_gases(std::move(gases)) {
    const auto& p = m_parameters;
    const auto bad = [](double v) { return !std::isfinite(v); };
    if (bad(p.aerosol_optical_depth_550) || p.aerosol_optical_depth_550 < 0.0) {
        throw input_error("aerosol_optical_depth_550 must be >= 0");
    }
    if (bad(p.angstrom_exponent)) throw input_error("angstrom_exponent must be finite");
    if (bad(p.aerosol_scale_height_m) || p.aerosol_scale_height_m <= 0.0 ||
        bad(p.rayleigh_scale_height_m) || p.rayleigh_scale_height_m <= 0.0) {
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
    const double ozone_share =
        std::clamp((kOzoneTopM - z) / (kOzoneTopM - kOzoneBottomM), 0.0, 1.0);
    return GasAmounts{
        m_parameters.water_vapor_cm * std::exp(-z / kWaterScaleHeightM),
        m_parameters.ozone_atm_cm * ozone_share,
        m_parameters.sea_level_pressure_hpa / kStandardPressureHpa *
            std::exp(-z / m_parameters.rayleigh_scale_height_m)};
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

std::vector<double> ParametricAtmosphereModel::gas_transmittance(
    const SpectralGrid& grid, const GasAmounts& amounts) const {
    const auto gases = gases_on(grid);
    if (!gases) return filled(grid, 1.0);
    return gases->transmittance(amounts);
}

/// Multiple-scattering solutions of one geometry at wavelength nodes, and how each band of
/// the grid interpolates between them.
struct ParametricAtmosphereModel::Scattering {
    std::vector<double> grid;  ///< the grid's wavelengths (part of the key)
    double sun_zenith_deg = 0.0;
    double surface_altitude_m = 0.0;
    double sensor_altitude_m = 0.0;
    std::vector<ScatteringSolution> solutions;  ///< one per node
    std::size_t sensor_level = 0;               ///< level of the sensor altitude
    std::vector<std::size_t> lower;             ///< per band: the node below
    std::vector<double> fraction;               ///< per band: weight of the node above

    /// Per band, the value of `at_node` interpolated in ln λ.
    template <typename PerNode>
    std::vector<double> per_band(PerNode&& at_node) const {
        std::vector<double> nodes(solutions.size());
        for (std::size_t k = 0; k < solutions.size(); ++k) nodes[k] = at_node(k);
        std::vector<double> out(lower.size());
        for (std::size_t i = 0; i < lower.size(); ++i) {
            const std::size_t k = lower[i];
            const double f = fraction[i];
            out[i] = f == 0.0 ? nodes[k] : (1.0 - f) * nodes[k] + f * nodes[k + 1];
        }
        return out;
    }
};

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
    const double sun_zenith_deg =
        std::min(std::round(geometry.sun_zenith_deg / kScatteringZenithStepDeg) *
                     kScatteringZenithStepDeg,
                 89.95);
    const double z0 = std::round(geometry.surface_altitude_m / kScatteringAltitudeStepM) *
                      kScatteringAltitudeStepM;
    const double z1 = std::max(
        z0, std::round(geometry.sensor_altitude_m / kScatteringAltitudeStepM) *
                kScatteringAltitudeStepM);
    const std::vector<double> wavelengths(grid.wavelengths_um().begin(),
                                          grid.wavelengths_um().end());
    const std::lock_guard<std::mutex> lock(m_scattering_mutex);
    for (const auto& cached : m_scattering) {
        if (cached->sun_zenith_deg == sun_zenith_deg &&
            cached->surface_altitude_m == z0 && cached->sensor_altitude_m == z1 &&
            cached->grid == wavelengths) {
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
        std::size_t k = above == nodes.begin() ? 0 : static_cast<std::size_t>(above - nodes.begin()) - 1;
        double f = 0.0;
        if (k + 1 >= nodes.size()) {
            k = nodes.size() - 1;
        } else {
            f = std::clamp(std::log(wl / nodes[k]) / std::log(nodes[k + 1] / nodes[k]), 0.0, 1.0);
        }
        out->lower.push_back(k);
        out->fraction.push_back(f);
    }
    // Layer boundaries: the surface to 100 km, denser near the ground (∝ (k/K)³), and the
    // sensor's altitude.
    const double top = std::max(z0, kTopOfAtmosphereM);
    std::vector<double> bounds;
    for (int k = 0; k <= kScatteringLayers; ++k) {
        const double f = static_cast<double>(k) / kScatteringLayers;
        bounds.push_back(z0 + (top - z0) * f * f * f);
    }
    if (z1 > z0 && z1 < top) bounds.push_back(z1);
    std::sort(bounds.begin(), bounds.end());
    bounds.erase(std::unique(bounds.begin(), bounds.end()), bounds.end());
    const std::size_t layers = bounds.size() - 1;
    // Levels count from the top: the sensor's is the boundary at z1 (0 above the model).
    const auto at_sensor = std::find(bounds.begin(), bounds.end(), std::min(z1, top));
    out->sensor_level = layers - static_cast<std::size_t>(at_sensor - bounds.begin());
    const double g = m_parameters.aerosol_asymmetry;
    const double omega_a = m_parameters.aerosol_single_scatter_albedo;
    for (const double wl : nodes) {
        ScatteringProblem problem;
        problem.sun_cos_zenith = std::min(1.0, 1.0 / relative_air_mass(sun_zenith_deg));
        problem.ground_albedo = m_parameters.ground_albedo;
        problem.streams = 8;
        problem.azimuth_modes = 6;
        problem.max_sublayer_depth = 0.02;
        problem.tolerance = 1e-5;
        for (std::size_t k = layers; k-- > 0;) {  // top first
            const double rayleigh =
                rayleigh_optical_depth(wl, bounds[k]) - rayleigh_optical_depth(wl, bounds[k + 1]);
            const double aerosol =
                aerosol_optical_depth(wl, bounds[k]) - aerosol_optical_depth(wl, bounds[k + 1]);
            ScatteringLayer layer;
            layer.optical_depth = std::max(0.0, rayleigh + aerosol);
            const double scattering = rayleigh + omega_a * aerosol;
            layer.single_scatter_albedo =
                layer.optical_depth > 0.0 ? std::clamp(scattering / layer.optical_depth, 0.0, 1.0)
                                          : 0.0;
            layer.moments.assign(static_cast<std::size_t>(2 * problem.streams), 0.0);
            for (std::size_t l = 0; l < layer.moments.size(); ++l) {
                const double rayleigh_moment = l == 0 ? 1.0 : (l == 2 ? 0.1 : 0.0);
                const double aerosol_moment = std::pow(g, static_cast<double>(l));
                layer.moments[l] =
                    scattering > 0.0 ? (rayleigh * rayleigh_moment +
                                        omega_a * aerosol * aerosol_moment) / scattering
                                     : (l == 0 ? 1.0 : 0.0);
            }
            layer.moments[0] = 1.0;
            problem.layers.push_back(std::move(layer));
        }
        out->solutions.push_back(solve_scattering_orders(problem));
    }
    // Enough for every level of a scene's environment (sky and sensor path of each), so a
    // sequence of captures at one sun geometry solves each level once.
    constexpr std::size_t kKept = 64;
    if (m_scattering.size() >= kKept) m_scattering.erase(m_scattering.begin());
    m_scattering.push_back(out);
    return out;
}

double ParametricAtmosphereModel::rayleigh_optical_depth(double wavelength_um,
                                                         double altitude_m) const noexcept {
    return rayleigh_sea_level(m_parameters, wavelength_um) *
           std::exp(-altitude_m / m_parameters.rayleigh_scale_height_m);
}

double ParametricAtmosphereModel::aerosol_optical_depth(double wavelength_um,
                                                        double altitude_m) const noexcept {
    return aerosol_sea_level(m_parameters, wavelength_um) *
           std::exp(-altitude_m / m_parameters.aerosol_scale_height_m);
}

double ParametricAtmosphereModel::sky_emissivity(double altitude_m) const noexcept {
    const double t = m_parameters.air_temperature_k;
    if (t <= 0.0 || altitude_m >= kTopOfAtmosphereM) return 0.0;
    // The vapour pressure falls with the water column above: e · e^(−z/H_w) (sea level 0).
    const double vapour_hpa =
        m_parameters.water_vapor_pressure_hpa * std::exp(-std::max(altitude_m, 0.0) /
                                                         kWaterScaleHeightM);
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
    const double g = m_parameters.aerosol_asymmetry;
    // The phase functions at each azimuth: light travels along −s from the sun and leaves
    // along v towards the sensor.
    std::vector<double> p_rayleigh;
    std::vector<double> p_aerosol;
    for (double azimuth : view_azimuths_deg) {
        const auto v = direction(std::clamp(geometry.view_zenith_deg, 0.0, 90.0), azimuth);
        const double cos_scatter = -(s[0] * v[0] + s[1] * v[1] + s[2] * v[2]);
        p_rayleigh.push_back(rayleigh_phase(cos_scatter));
        p_aerosol.push_back(henyey_greenstein(g, cos_scatter));
    }
    const double omega = m_parameters.aerosol_single_scatter_albedo;
    const double temperature_k = m_parameters.air_temperature_k;
    // τ(λ, z) = τ_R(λ)·e^(−z/H_R) + τ_A(λ)·e^(−z/H_A): the altitude factors of every layer
    // boundary and midpoint are computed once, the spectral ones once per band, and each
    // optical depth is their product, computed exactly as rayleigh_optical_depth and
    // aerosol_optical_depth compute it.
    struct Level {
        double rayleigh = 0.0;  ///< e^(−z/H_R)
        double aerosol = 0.0;   ///< e^(−z/H_A)
    };
    const auto level = [&](double z) {
        return Level{std::exp(-z / m_parameters.rayleigh_scale_height_m),
                     std::exp(-z / m_parameters.aerosol_scale_height_m)};
    };
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
            if (sunlit) {
                gases->log_transmittance(slant(at_layer, {}, m_sun),
                                         std::span<double>(&gas_sun[k * n], n));
            }
        }
    }
    // Per layer of one band: its Rayleigh and aerosol optical depths and its transmittances
    // from the sun and to the sensor, the same at every azimuth.
    std::vector<double> d_r(layers), d_a(layers), sun(layers), to_sensor(layers);
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double wl = grid.wavelength_um(i);
        const double rayleigh = rayleigh_sea_level(m_parameters, wl);
        const double aerosol = aerosol_sea_level(m_parameters, wl);
        const auto tau_r = [&](const Level& at) { return rayleigh * at.rayleigh; };
        const auto tau_a = [&](const Level& at) { return aerosol * at.aerosol; };
        const double tau_sensor = tau_r(top) + tau_a(top);
        const double emission = planck_radiance_w_per_cm2_sr_um(wl, temperature_k);
        double tau_r_a = tau_r(bounds[0]);
        double tau_a_a = tau_a(bounds[0]);
        for (std::size_t k = 0; k < layers; ++k) {
            const double tau_r_b = tau_r(bounds[k + 1]);
            const double tau_a_b = tau_a(bounds[k + 1]);
            d_r[k] = tau_r_a - tau_r_b;
            d_a[k] = tau_a_a - tau_a_b;
            const double tau_m = tau_r(middles[k]) + tau_a(middles[k]);
            const double log_gas_view = gases ? gas_view[k * grid.size() + i] : 0.0;
            const double log_gas_sun = gases ? gas_sun[k * grid.size() + i] : 0.0;
            to_sensor[k] = std::exp(-(tau_m - tau_sensor) * m_view + log_gas_view);
            if (sunlit) sun[k] = std::exp(-tau_m * m_sun + log_gas_sun);
            tau_r_a = tau_r_b;
            tau_a_a = tau_a_b;
        }
        for (std::size_t a = 0; a < view_azimuths_deg.size(); ++a) {
            double sum = 0.0;
            for (std::size_t k = 0; k < layers; ++k) {
                double source = (1.0 - omega) * d_a[k] * emission;
                if (sunlit) {
                    source += toa[i] / (4.0 * kPi) * sun[k] *
                              (d_r[k] * p_rayleigh[a] + omega * d_a[k] * p_aerosol[a]);
                }
                sum += source * m_view * to_sensor[k];
            }
            out[a][i] = sum;
        }
    }
    add_multiple_scattering(grid, geometry, toa, view_azimuths_deg, out);
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
    const std::vector<double> gas_sun = gas_transmittance(grid, slant(gas_amounts_above(z0), {}, m_sun));
    const std::vector<double> gas_view =
        gas_transmittance(grid, slant(gas_amounts_above(z0), gas_amounts_above(z1), m_view));
    for (std::size_t a = 0; a < view_azimuths_deg.size(); ++a) {
        // Azimuth from the beam's direction of travel (the sun's azimuth + 180°).
        const double phi =
            (view_azimuths_deg[a] - geometry.sun_azimuth_deg - 180.0) * kDegToRad;
        const std::vector<double> reflectance = ms->per_band([&](std::size_t k) {
            double sum = 0.0;
            for (std::size_t m = 0; m < modes[k].size(); ++m) {
                sum += modes[k][m] * std::cos(static_cast<double>(m) * phi);
            }
            return sum;
        });
        for (std::size_t i = 0; i < grid.size(); ++i) {
            out[a][i] += toa[i] * std::max(reflectance[i], 0.0) * gas_sun[i] * gas_view[i];
        }
    }
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
    const double omega = m_parameters.aerosol_single_scatter_albedo;
    const double forward = hg_forward_fraction(m_parameters.aerosol_asymmetry);
    // Gas absorption of the diffuse light: the direct beam's, at the sun's air mass (the
    // Bird–Riordan approximation).
    const std::vector<double> gas = gas_transmittance(grid, slant(gas_amounts_above(z), {}, m));
    if (const std::shared_ptr<const Scattering> ms = scattering(grid, geometry)) {
        // Multiple scattering: the diffuse flux reaching the ground per unit beam irradiance.
        const std::size_t ground = ms->solutions.front().levels() - 1;
        const std::vector<double> diffuse = ms->per_band(
            [&](std::size_t k) { return ms->solutions[k].diffuse_down_flux(ground); });
        for (std::size_t i = 0; i < grid.size(); ++i) out[i] = toa[i] * diffuse[i] * gas[i];
        return out;
    }
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double wl = grid.wavelength_um(i);
        const double tau_r = rayleigh_optical_depth(wl, z);
        const double tau_a = aerosol_optical_depth(wl, z);
        const double t_r = std::exp(-tau_r * m);
        const double t_as = std::exp(-omega * tau_a * m);
        const double t_aa = std::exp(-(1.0 - omega) * tau_a * m);
        out[i] = toa[i] * mu * gas[i] * t_aa * (0.5 * (1.0 - t_r) + forward * (1.0 - t_as));
    }
    return out;
}

std::vector<double> ParametricAtmosphereModel::thermal_sky_radiance_w_per_cm2_sr_um(
    const SpectralGrid& grid, const AtmosphereGeometry& geometry) const {
    check_geometry(geometry);
    const double emissivity = sky_emissivity(geometry.surface_altitude_m);
    std::vector<double> out;
    out.reserve(grid.size());
    for (double wl : grid.wavelengths_um()) {
        out.push_back(emissivity *
                      planck_radiance_w_per_cm2_sr_um(wl, m_parameters.air_temperature_k));
    }
    return out;
}

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

std::unique_ptr<AtmosphereModel> make_atmosphere_model(const model::Atmosphere& atmosphere,
                                                       std::shared_ptr<const GasBandModel> gases) {
    try {
        switch (atmosphere.kind) {
            case model::AtmosphereKind::none:
                return std::make_unique<NoAtmosphere>();
            case model::AtmosphereKind::parametric:
                return std::make_unique<ParametricAtmosphereModel>(atmosphere.parametric,
                                                                   std::move(gases));
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

std::unique_ptr<AtmosphereModel> load_atmosphere_model(const model::Atmosphere& atmosphere,
                                                       const std::filesystem::path& data_dir) {
    std::shared_ptr<const GasBandModel> gases;
    if (atmosphere.kind == model::AtmosphereKind::parametric &&
        atmosphere.parametric.gas_absorption) {
        const std::filesystem::path table = data_dir / GasBandModel::kRelativePath;
        gases = std::make_shared<const GasBandModel>(GasBandModel::load(table, table.string()));
    }
    return make_atmosphere_model(atmosphere, std::move(gases));
}

}  // namespace glint::atmosphere
