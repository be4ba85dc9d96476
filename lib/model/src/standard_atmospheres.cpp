// SPDX-License-Identifier: Apache-2.0
// The standard atmospheres of glint/model/standard_atmospheres.h: lookup by name, the columns
// of their water and ozone, and temperature interpolation. The tables themselves are in
// standard_atmospheres_data.cpp.
#include "glint/model/standard_atmospheres.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "standard_atmospheres_data.h"

namespace glint::model {

namespace {

/// Mass of precipitable water per cm of column: 1 g/cm² is 1 cm of liquid water; the
/// tables' g/m³ times m gives g/m², / 10⁴ gives g/cm².
constexpr double kGramsPerM2PerCmWater = 1.0e4;
/// An atm-cm of ozone: 2.6867 × 10¹⁹ molecules/cm² (Loschmidt's number × 1 cm) × 47.998 g/mol
/// / 6.02214 × 10²³ /mol = 2.1414 × 10⁻³ g/cm² = 21.414 g/m².
constexpr double kGramsPerM2PerAtmCmOzone = 21.414;

struct Entry {
    StandardAtmosphere which;
    const char* name;
};
constexpr Entry kNames[] = {
    {StandardAtmosphere::tropical, "tropical"},
    {StandardAtmosphere::midlatitude_summer, "midlatitude_summer"},
    {StandardAtmosphere::midlatitude_winter, "midlatitude_winter"},
    {StandardAtmosphere::subarctic_summer, "subarctic_summer"},
    {StandardAtmosphere::subarctic_winter, "subarctic_winter"},
    {StandardAtmosphere::us_standard_1976, "us_standard_1976"},
    {StandardAtmosphere::isothermal, "isothermal"},
};

/// ∫ density dz over the levels, g/m², the density exponential between two levels (as
/// LOWTRAN integrates its profiles): Δz (ρ₁ − ρ₂) / ln(ρ₁/ρ₂), linear where either is 0.
template <typename Field>
double column_g_per_m2(std::span<const AtmosphereLevel> levels, Field field) {
    double sum = 0.0;
    for (std::size_t i = 1; i < levels.size(); ++i) {
        const double dz_m = (levels[i].altitude_km - levels[i - 1].altitude_km) * 1000.0;
        const double a = field(levels[i - 1]);
        const double b = field(levels[i]);
        if (a > 0.0 && b > 0.0 && std::abs(a - b) > 1e-12 * a) {
            sum += dz_m * (a - b) / std::log(a / b);
        } else {
            sum += dz_m * 0.5 * (a + b);
        }
    }
    return sum;
}

/// ∫ density dz from `z_m` up to the level above it (index `upper`), the density exponential
/// between levels upper − 1 and upper.
template <typename Field>
double partial_g_per_m2(std::span<const AtmosphereLevel> levels, std::size_t upper, double z_m,
                        Field field) {
    const AtmosphereLevel& lo = levels[upper - 1];
    const AtmosphereLevel& hi = levels[upper];
    const double dz_m = (hi.altitude_km - lo.altitude_km) * 1000.0;
    const double f = (z_m - lo.altitude_km * 1000.0) / dz_m;
    const double a = field(lo);
    const double b = field(hi);
    const double rest_m = (1.0 - f) * dz_m;
    if (a > 0.0 && b > 0.0 && std::abs(a - b) > 1e-12 * a) {
        const double at_z = a * std::pow(b / a, f);
        return dz_m * (at_z - b) / std::log(a / b);
    }
    const double at_z = a + f * (b - a);
    return rest_m * 0.5 * (at_z + b);
}

/// Column above every level, g/m².
template <typename Field>
std::vector<double> columns_above(std::span<const AtmosphereLevel> levels, Field field) {
    std::vector<double> above(levels.size(), 0.0);
    for (std::size_t i = levels.size(); i-- > 1;) {
        above[i - 1] = above[i] + column_g_per_m2(levels.subspan(i - 1, 2), field);
    }
    return above;
}

template <typename Field>
double share_above(std::span<const AtmosphereLevel> levels, const std::vector<double>& above,
                   double altitude_m, Field field) {
    if (levels.empty() || above.empty()) return -1.0;
    if (!(above.front() > 0.0)) return 0.0;
    const double z_km = altitude_m / 1000.0;
    if (!(z_km > levels.front().altitude_km)) return 1.0;
    if (!(z_km < levels.back().altitude_km)) return 0.0;
    const auto it = std::upper_bound(
        levels.begin(), levels.end(), z_km,
        [](double z, const AtmosphereLevel& level) { return z < level.altitude_km; });
    const auto upper = static_cast<std::size_t>(it - levels.begin());
    const double column = partial_g_per_m2(levels, upper, altitude_m, field) + above[upper];
    return std::clamp(column / above.front(), 0.0, 1.0);
}

double water_of(const AtmosphereLevel& l) { return l.water_g_per_m3; }
double ozone_of(const AtmosphereLevel& l) { return l.ozone_g_per_m3; }

StandardAtmosphereProfile make_profile(StandardAtmosphere which) {
    StandardAtmosphereProfile p;
    for (const Entry& e : kNames) {
        if (e.which == which) p.name = e.name;
    }
    p.levels = detail::standard_atmosphere_levels(which);
    p.water_column_cm =
        column_g_per_m2(p.levels, [](const AtmosphereLevel& l) { return l.water_g_per_m3; }) /
        kGramsPerM2PerCmWater;
    p.ozone_column_atm_cm =
        column_g_per_m2(p.levels, [](const AtmosphereLevel& l) { return l.ozone_g_per_m3; }) /
        kGramsPerM2PerAtmCmOzone;
    p.water_above_g_per_m2 = columns_above(p.levels, water_of);
    p.ozone_above_g_per_m2 = columns_above(p.levels, ozone_of);
    return p;
}

}  // namespace

const StandardAtmosphereProfile& standard_atmosphere(StandardAtmosphere which) noexcept {
    static const std::array<StandardAtmosphereProfile, 7> profiles = {
        make_profile(StandardAtmosphere::tropical),
        make_profile(StandardAtmosphere::midlatitude_summer),
        make_profile(StandardAtmosphere::midlatitude_winter),
        make_profile(StandardAtmosphere::subarctic_summer),
        make_profile(StandardAtmosphere::subarctic_winter),
        make_profile(StandardAtmosphere::us_standard_1976),
        make_profile(StandardAtmosphere::isothermal),
    };
    return profiles[static_cast<std::size_t>(which)];
}

std::optional<StandardAtmosphere> standard_atmosphere_named(std::string_view name) noexcept {
    for (const Entry& e : kNames) {
        if (name == e.name) return e.which;
    }
    return std::nullopt;
}

const char* standard_atmosphere_names() noexcept {
    return "tropical, midlatitude_summer, midlatitude_winter, subarctic_summer, "
           "subarctic_winter, us_standard_1976 or isothermal";
}

double water_share_above(const StandardAtmosphereProfile& profile, double altitude_m) noexcept {
    return share_above(profile.levels, profile.water_above_g_per_m2, altitude_m, water_of);
}

double ozone_share_above(const StandardAtmosphereProfile& profile, double altitude_m) noexcept {
    return share_above(profile.levels, profile.ozone_above_g_per_m2, altitude_m, ozone_of);
}

double pressure_share_above(const StandardAtmosphereProfile& profile, double altitude_m) noexcept {
    const auto& levels = profile.levels;
    if (levels.size() < 2) return -1.0;
    const double z_km = altitude_m / 1000.0;
    // The segment whose exponential holds z: the first below the profile, the last above it.
    const auto above = std::upper_bound(
        levels.begin() + 1, levels.end() - 1, z_km,
        [](double z, const AtmosphereLevel& level) { return z < level.altitude_km; });
    const AtmosphereLevel& hi = *above;
    const AtmosphereLevel& lo = *(above - 1);
    const double f = (z_km - lo.altitude_km) / (hi.altitude_km - lo.altitude_km);
    const double ln_ratio = std::log(lo.pressure_hpa / levels.front().pressure_hpa) +
                            f * std::log(hi.pressure_hpa / lo.pressure_hpa);
    return std::exp(ln_ratio);
}

double profile_temperature_k(std::span<const AtmosphereLevel> levels, double altitude_m) noexcept {
    if (levels.empty()) return 0.0;
    const double z_km = altitude_m / 1000.0;
    if (!(z_km > levels.front().altitude_km)) return levels.front().temperature_k;
    if (!(z_km < levels.back().altitude_km)) return levels.back().temperature_k;
    const auto above = std::upper_bound(
        levels.begin(), levels.end(), z_km,
        [](double z, const AtmosphereLevel& level) { return z < level.altitude_km; });
    const AtmosphereLevel& hi = *above;
    const AtmosphereLevel& lo = *(above - 1);
    const double f = (z_km - lo.altitude_km) / (hi.altitude_km - lo.altitude_km);
    return lo.temperature_k + f * (hi.temperature_k - lo.temperature_k);
}

}  // namespace glint::model
