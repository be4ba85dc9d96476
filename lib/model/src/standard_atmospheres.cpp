// SPDX-License-Identifier: Apache-2.0
// The standard atmospheres of glint/model/standard_atmospheres.h: lookup by name, the columns
// of their water and ozone, and temperature interpolation. The tables themselves are in
// standard_atmospheres_data.cpp.
#include "glint/model/standard_atmospheres.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

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
