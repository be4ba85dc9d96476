// SPDX-License-Identifier: Apache-2.0
// The parametric atmosphere's aerosol regimes (glint/atmosphere/aerosol_column.h).
#include "glint/atmosphere/aerosol_column.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>

#include "atmosphere_detail.h"
#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/model/aerosol_models.h"
#include "glint/model/standard_atmospheres.h"

namespace glint::atmosphere {

using detail::kPi;

namespace {

constexpr double kReferenceUm = 0.55;

/// Saturation vapour pressure over water, hPa (A. L. Buck, "New equations for computing vapor
/// pressure and enhancement factor", Journal of Applied Meteorology 20, 1981, 1527–1532).
double saturation_hpa(double temperature_k) {
    const double t = temperature_k - 273.15;
    return 6.1121 * std::exp((18.678 - t / 234.5) * (t / (257.14 + t)));
}

/// The humidity glint takes for an atmosphere without levels (the isothermal profile), %.
constexpr double kLevellessHumidityPercent = 70.0;

/// The relative humidity of a standard profile at `altitude_km`, %: its water density as a
/// vapour pressure (ρ R_v T) over the saturation pressure at its temperature, the temperature
/// linear and the water density exponential between the profile's levels (held beyond them).
double profile_humidity_percent(const model::StandardAtmosphereProfile& profile,
                                double altitude_km) {
    const auto& levels = profile.levels;
    if (levels.empty()) return kLevellessHumidityPercent;
    const double z = std::clamp(altitude_km, levels.front().altitude_km, levels.back().altitude_km);
    std::size_t i = 0;
    while (i + 2 < levels.size() && levels[i + 1].altitude_km < z) ++i;
    const model::AtmosphereLevel& a = levels[i];
    const model::AtmosphereLevel& b = levels[std::min(i + 1, levels.size() - 1)];
    const double t =
        b.altitude_km > a.altitude_km ? (z - a.altitude_km) / (b.altitude_km - a.altitude_km) : 0.0;
    const double temperature_k = a.temperature_k + t * (b.temperature_k - a.temperature_k);
    const double water_g_per_m3 =
        a.water_g_per_m3 > 0.0 && b.water_g_per_m3 > 0.0
            ? a.water_g_per_m3 * std::pow(b.water_g_per_m3 / a.water_g_per_m3, t)
            : a.water_g_per_m3 + t * (b.water_g_per_m3 - a.water_g_per_m3);
    constexpr double kWaterGasConstant = 461.5;  // J/(kg K)
    const double vapour_hpa = water_g_per_m3 * 1e-3 * kWaterGasConstant * temperature_k / 100.0;
    return std::clamp(100.0 * vapour_hpa / saturation_hpa(temperature_k), 0.0, 100.0);
}

/// ln-λ interpolation weights of `wavelength_um` on the increasing `grid`.
std::pair<std::size_t, double> bracket(const std::vector<double>& grid, double wavelength_um) {
    if (grid.size() == 1 || wavelength_um <= grid.front()) return {0, 0.0};
    if (wavelength_um >= grid.back()) return {grid.size() - 1, 0.0};
    const std::size_t hi = static_cast<std::size_t>(
        std::upper_bound(grid.begin(), grid.end(), wavelength_um) - grid.begin());
    const std::size_t lo = hi - 1;
    return {lo, std::log(wavelength_um / grid[lo]) / std::log(grid[hi] / grid[lo])};
}

}  // namespace

/// One regime: its 550 nm extinction profile and its optics.
struct AerosolColumn::Regime {
    // --- vertical: 550 nm extinction (1/m) at ascending altitudes (m), exponential between
    // two non-zero values, linear where one is zero, 0 outside; or an exponential of scale
    // height `scale_height_m` holding `sea_level_depth` above sea level.
    std::vector<double> levels_m;
    std::vector<double> extinction_per_m;
    std::vector<double> depth_above;  ///< ∫ above each level
    double scale_height_m = 0.0;
    double sea_level_depth = 0.0;

    // --- optics: either Ångström + Henyey–Greenstein, or sampled at the table's wavelengths.
    bool henyey_greenstein = false;
    double angstrom = 0.0, asymmetry = 0.0, albedo = 1.0;
    std::vector<double> wavelengths_um;
    std::vector<ComponentOptics> sampled;   ///< per wavelength, cross sections per particle
    double reference_extinction_um2 = 0.0;  ///< at 550 nm
    std::vector<double> angles_rad;         ///< the table's angles (increasing)

    double segment_depth(std::size_t k, double from_m) const {
        // ∫ from `from_m` to levels_m[k + 1] within segment k.
        const double za = levels_m[k];
        const double zb = levels_m[k + 1];
        const double ba = extinction_per_m[k];
        const double bb = extinction_per_m[k + 1];
        const double t = (from_m - za) / (zb - za);
        if (ba > 0.0 && bb > 0.0 && std::abs(ba - bb) > 1e-12 * ba) {
            const double rate = std::log(bb / ba) / (zb - za);  // per m
            const double b_from = ba * std::exp(rate * (from_m - za));
            return (bb - b_from) / rate;
        }
        const double b_from = ba + t * (bb - ba);
        return 0.5 * (b_from + bb) * (zb - from_m);
    }

    double depth_550_above(double z) const {
        if (levels_m.empty()) return sea_level_depth * std::exp(-z / scale_height_m);
        if (z <= levels_m.front()) return depth_above.front();
        if (z >= levels_m.back()) return 0.0;
        const std::size_t k = static_cast<std::size_t>(
            std::upper_bound(levels_m.begin(), levels_m.end(), z) - levels_m.begin() - 1);
        return segment_depth(k, z) + depth_above[k + 1];
    }

    ComponentOptics at(double wavelength_um) const {
        const auto [k, t] = bracket(wavelengths_um, wavelength_um);
        return t == 0.0 ? sampled[k] : interpolate(sampled[k], sampled[k + 1], t, true);
    }

    /// The depths above each level, once the levels and extinctions are set.
    void integrate() {
        depth_above.assign(levels_m.size(), 0.0);
        for (std::size_t k = levels_m.size() - 1; k-- > 0;) {
            depth_above[k] = depth_above[k + 1] + segment_depth(k, levels_m[k]);
        }
    }

    /// The optics of the mixture `shares` at `rh_percent`, at the table's wavelengths.
    void sample(const AerosolTable& table, std::span<const MixtureShare> shares,
                double rh_percent) {
        wavelengths_um = table.wavelengths_um(shares.front().component);
        for (double w : wavelengths_um) sampled.push_back(table.mixture(shares, w, rh_percent));
        reference_extinction_um2 = table.mixture(shares, kReferenceUm, rh_percent).extinction_um2;
        for (double a : table.angles_deg()) angles_rad.push_back(a * kPi / 180.0);
    }
};

namespace {

void require_table(const std::shared_ptr<const AerosolTable>& table, const std::string& key) {
    if (!table) {
        throw input_error(key + " needs the aerosol optics table (" + AerosolTable::kRelativePath +
                          " in glint's data folder)");
    }
}

}  // namespace

AerosolColumn::AerosolColumn(const model::ParametricAtmosphere& p,
                             std::shared_ptr<const AerosolTable> table) {
    if (p.aerosol_profile) {
        add_profile_layers(p, table);
    } else if (p.aerosol_model.empty()) {
        add_exponential(p);
    } else {
        add_lowtran_layers(p, table);
    }
}

void AerosolColumn::add_exponential(const model::ParametricAtmosphere& p) {
    auto r = std::make_shared<Regime>();
    r->scale_height_m = p.aerosol_scale_height_m;
    r->sea_level_depth = p.aerosol_optical_depth_550;
    r->henyey_greenstein = true;
    r->angstrom = p.angstrom_exponent;
    r->asymmetry = p.aerosol_asymmetry;
    r->albedo = p.aerosol_single_scatter_albedo;
    m_regimes.push_back(std::move(r));
    m_description = "exponential: tau550 " + format_shortest(p.aerosol_optical_depth_550) +
                    ", scale height " + format_shortest(p.aerosol_scale_height_m) +
                    " m, Angstrom " + format_shortest(p.angstrom_exponent) +
                    ", Henyey-Greenstein g " + format_shortest(p.aerosol_asymmetry) + ", albedo " +
                    format_shortest(p.aerosol_single_scatter_albedo);
}

void AerosolColumn::add_lowtran_layers(const model::ParametricAtmosphere& p,
                                       const std::shared_ptr<const AerosolTable>& table) {
    require_table(table, "aerosol_model");
    if (!(p.visibility_km > 0.0) || !std::isfinite(p.visibility_km)) {
        throw input_error("visibility_km must be > 0, got " + format_shortest(p.visibility_km));
    }
    const model::StandardAtmosphereProfile& profile = model::standard_atmosphere(p.profile);
    const double rh = p.relative_humidity_percent.value_or(profile_humidity_percent(profile, 0.0));
    if (!(rh >= 0.0 && rh <= 100.0)) {
        throw input_error("relative_humidity_percent must lie in [0, 100], got " +
                          format_shortest(rh));
    }
    const bool winter = p.profile == model::StandardAtmosphere::midlatitude_winter ||
                        p.profile == model::StandardAtmosphere::subarctic_winter;
    const model::AerosolSeason season = p.aerosol_season.value_or(
        winter ? model::AerosolSeason::fall_winter : model::AerosolSeason::spring_summer);

    // The total 550 nm extinction at LOWTRAN's levels; each regime owns its altitudes (the
    // boundary layer up to 2 km, the troposphere to 10 km, the stratosphere above) and the
    // profile between levels is the exponential through the two neighbours.
    const auto levels_km = model::aerosol_profile_levels_km();
    std::vector<double> total(levels_km.size());
    for (std::size_t k = 0; k < levels_km.size(); ++k) {
        const model::RegimeExtinction e =
            model::lowtran_aerosol_extinction(k, p.visibility_km, season);
        total[k] = (e.boundary_layer + e.troposphere + e.stratosphere) * 1e-3;  // 1/km → 1/m
    }
    struct Layer {
        const char* key;
        std::string type;
        double bottom_km, top_km;
    };
    const Layer layers[] = {{"aerosol_model", p.aerosol_model, 0.0, 2.0},
                            {"tropospheric_aerosol", p.tropospheric_aerosol, 2.0, 10.0},
                            {"stratospheric_aerosol", p.stratospheric_aerosol, 10.0, 100.0}};
    double column = 0.0;
    std::vector<std::string> described;
    for (const Layer& layer : layers) {
        if (layer.type == "none") continue;
        const auto mixture = model::aerosol_mixture_named(layer.type);
        if (!mixture) {
            throw input_error(std::string(layer.key) + ": unknown aerosol type '" + layer.type +
                              "' (expected one of " + model::aerosol_mixture_names() +
                              (layer.bottom_km > 0.0 ? ", none)" : ")"));
        }
        auto r = std::make_shared<Regime>();
        // The regime's profile: the total at the levels within its altitudes (LOWTRAN's
        // regime boundaries, 2 and 10 km, are levels: the segment above a boundary runs from
        // the lower regime's value there to the upper one's next level).
        for (std::size_t k = 0; k < levels_km.size(); ++k) {
            if (levels_km[k] >= layer.bottom_km && levels_km[k] <= layer.top_km) {
                r->levels_m.push_back(levels_km[k] * 1000.0);
                r->extinction_per_m.push_back(total[k]);
            }
        }
        r->integrate();
        // Optics at the table's wavelengths.
        std::vector<MixtureShare> shares;
        for (const model::AerosolComponentNumber& c : mixture->components) {
            shares.push_back({c.component, c.number_per_cm3});
        }
        r->sample(*table, shares, mixture->humidity_growth ? rh : 0.0);
        column += r->depth_above.front();
        described.push_back(std::string(layer.key) + " " + layer.type);
        m_regimes.push_back(std::move(r));
    }
    column = scale_to(p.aerosol_column_depth_550, column);
    m_description = "layered (LOWTRAN 7 profiles, OPAC optics): ";
    for (std::size_t i = 0; i < described.size(); ++i) {
        m_description += (i ? ", " : "") + described[i];
    }
    m_description +=
        "; visibility " + format_shortest(p.visibility_km) + " km, humidity " +
        format_shortest(std::round(rh * 10.0) / 10.0) + " %, " +
        (season == model::AerosolSeason::fall_winter ? "fall-winter" : "spring-summer") +
        ", tau550 " + format_shortest(std::round(column * 1e4) / 1e4);
}

void AerosolColumn::add_profile_layers(const model::ParametricAtmosphere& p,
                                       const std::shared_ptr<const AerosolTable>& table) {
    require_table(table, "aerosol_profile");
    const model::AerosolProfile& profile = *p.aerosol_profile;
    const model::StandardAtmosphereProfile& air = model::standard_atmosphere(p.profile);
    const ErrorContext& where = profile.where;
    for (const std::string& c : profile.components) {
        if (!table->has(c)) {
            throw input_error("the aerosol optics table has no component '" + c + "'", where);
        }
    }
    if (profile.altitudes_km.size() != profile.densities.size() + 1) {
        throw input_error("an aerosol profile needs one row of densities per layer", where);
    }
    double column = 0.0;
    double rh_low = 100.0, rh_high = 0.0;
    for (std::size_t i = 0; i < profile.densities.size(); ++i) {
        const std::vector<double>& densities = profile.densities[i];
        if (densities.size() != profile.components.size()) {
            throw input_error("an aerosol profile's rows need one density per component", where);
        }
        const double bottom_km = profile.altitudes_km[i];
        const double top_km = profile.altitudes_km[i + 1];
        // The layer's humidity: the user's for every layer, or the air's at its middle.
        const double rh = p.relative_humidity_percent.value_or(
            profile_humidity_percent(air, 0.5 * (bottom_km + top_km)));
        // Particle numbers: as given, or the masses over one particle's mass as weighed.
        std::vector<MixtureShare> shares;
        for (std::size_t c = 0; c < densities.size(); ++c) {
            if (!(densities[c] > 0.0)) continue;
            double number_per_cm3 = densities[c];
            if (profile.mass_densities) {
                const double weighed_rh = profile.mass_humidity_percent.value_or(rh);
                const double mass_g =
                    table->optics(profile.components[c], kReferenceUm, weighed_rh).particle_mass_g;
                number_per_cm3 = densities[c] / mass_g * 1e-6;  // g/m³ ÷ g → 1/m³ → 1/cm³
            }
            shares.push_back({profile.components[c], number_per_cm3});
        }
        if (shares.empty()) continue;
        auto r = std::make_shared<Regime>();
        r->sample(*table, shares, rh);
        double number = 0.0;
        for (const MixtureShare& s : shares) number += s.number_per_cm3;
        // n [1/cm³] × σ [µm²] = 1e-8 cm⁻¹ = 1e-6 m⁻¹, the same throughout the layer.
        const double extinction_per_m = number * r->reference_extinction_um2 * 1e-6;
        r->levels_m = {bottom_km * 1000.0, top_km * 1000.0};
        r->extinction_per_m = {extinction_per_m, extinction_per_m};
        r->integrate();
        column += r->depth_above.front();
        rh_low = std::min(rh_low, rh);
        rh_high = std::max(rh_high, rh);
        m_regimes.push_back(std::move(r));
    }
    column = scale_to(p.aerosol_column_depth_550, column);
    const auto percent = [](double v) { return format_shortest(std::round(v * 10.0) / 10.0); };
    m_description = "profile: " + std::to_string(profile.densities.size()) + " layers of " +
                    join(profile.components, ", ") + " (" +
                    (profile.mass_densities ? std::string("g/m^3") : std::string("1/cm^3")) +
                    "), humidity " +
                    (m_regimes.empty()   ? std::string("-")
                     : rh_low == rh_high ? percent(rh_low) + " %"
                                         : percent(rh_low) + "-" + percent(rh_high) + " %") +
                    ", tau550 " + format_shortest(std::round(column * 1e4) / 1e4);
}

double AerosolColumn::scale_to(const std::optional<double>& wanted, double column) {
    if (!wanted) return column;
    if (!(*wanted >= 0.0) || !std::isfinite(*wanted)) {
        throw input_error("aerosol_optical_depth_550 must be >= 0");
    }
    const double scale = column > 0.0 ? *wanted / column : 0.0;
    for (auto& regime : m_regimes) {
        auto r = std::make_shared<Regime>(*regime);
        for (double& b : r->extinction_per_m) b *= scale;
        for (double& d : r->depth_above) d *= scale;
        regime = std::move(r);
    }
    return *wanted;
}

double AerosolColumn::depth_550_above(std::size_t j, double altitude_m) const noexcept {
    return m_regimes[j]->depth_550_above(altitude_m);
}

double AerosolColumn::depth_550_above(double altitude_m) const noexcept {
    double sum = 0.0;
    for (const auto& r : m_regimes) sum += r->depth_550_above(altitude_m);
    return sum;
}

RegimeOptics AerosolColumn::optics(std::size_t j, double wavelength_um,
                                   std::size_t moment_count) const {
    const Regime& r = *m_regimes[j];
    RegimeOptics out;
    out.moments.assign(moment_count, 0.0);
    if (r.henyey_greenstein) {
        out.extinction_ratio = std::pow(wavelength_um / kReferenceUm, -r.angstrom);
        out.single_scatter_albedo = r.albedo;
        for (std::size_t l = 0; l < moment_count; ++l) {
            out.moments[l] = std::pow(r.asymmetry, static_cast<double>(l));
        }
        return out;
    }
    const ComponentOptics o = r.at(wavelength_um);
    out.extinction_ratio = extinction_ratio(j, wavelength_um);
    out.single_scatter_albedo = o.single_scatter_albedo();
    if (moment_count > o.moments.size()) {
        throw input_error("the aerosol optics table holds " + std::to_string(o.moments.size()) +
                          " Legendre moments; " + std::to_string(moment_count) + " asked for");
    }
    std::copy_n(o.moments.begin(), moment_count, out.moments.begin());
    return out;
}

std::vector<double> AerosolColumn::phases(std::size_t j, double wavelength_um,
                                          std::span<const double> cos_thetas) const {
    const Regime& r = *m_regimes[j];
    std::vector<double> out;
    if (r.henyey_greenstein) {
        const double g = r.asymmetry;
        for (double c : cos_thetas) {
            const double denom = 1.0 + g * g - 2.0 * g * c;
            out.push_back((1.0 - g * g) / (denom * std::sqrt(denom)));
        }
        return out;
    }
    const ComponentOptics o = r.at(wavelength_um);
    for (double c : cos_thetas) {
        // Linear in ln P between the table's angles.
        const double theta = std::acos(std::clamp(c, -1.0, 1.0));
        const auto above = std::upper_bound(r.angles_rad.begin(), r.angles_rad.end(), theta);
        const std::size_t i = std::clamp<std::size_t>(
            static_cast<std::size_t>(above - r.angles_rad.begin()), 1, r.angles_rad.size() - 1);
        const double t = std::clamp(
            (theta - r.angles_rad[i - 1]) / (r.angles_rad[i] - r.angles_rad[i - 1]), 0.0, 1.0);
        out.push_back(std::exp((1.0 - t) * std::log(o.phase[i - 1]) + t * std::log(o.phase[i])));
    }
    return out;
}

double AerosolColumn::extinction_ratio(std::size_t j, double wavelength_um) const {
    const Regime& r = *m_regimes[j];
    if (r.henyey_greenstein) return std::pow(wavelength_um / kReferenceUm, -r.angstrom);
    const auto [k, t] = bracket(r.wavelengths_um, wavelength_um);
    double e = r.sampled[k].extinction_um2;
    if (t > 0.0) {
        e = std::exp((1.0 - t) * std::log(e) + t * std::log(r.sampled[k + 1].extinction_um2));
    }
    return e / r.reference_extinction_um2;
}

double AerosolColumn::optical_depth(double wavelength_um, double altitude_m) const {
    double sum = 0.0;
    for (std::size_t j = 0; j < m_regimes.size(); ++j) {
        const double d = depth_550_above(j, altitude_m);
        if (d > 0.0) sum += d * extinction_ratio(j, wavelength_um);
    }
    return sum;
}

}  // namespace glint::atmosphere
