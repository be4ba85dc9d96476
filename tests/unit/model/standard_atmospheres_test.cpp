// SPDX-License-Identifier: Apache-2.0
// Tests of the standard atmospheres (glint/model/standard_atmospheres.h): every name reads
// back; the tables' columns are LOWTRAN 7's (its model atmospheres' precipitable water and
// ozone); the temperature interpolates between levels and
// holds its ends.
#include "glint/model/standard_atmospheres.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

namespace glint::model {
namespace standard_atmospheres_test {

struct Published {
    StandardAtmosphere which;
    double sea_level_k;
    double water_cm;
};

// The models' sea-level temperatures and precipitable water as LOWTRAN 7 computes them for
// its vertical paths (docs/physics.md, "Gas absorption": 4.117, 2.924, 0.854, 2.085, 0.418,
// 1.418 cm). Tolerance 0.5 %: the same levels, LOWTRAN's own layering of them. Ozone: the
// 0.28-0.38 atm-cm LOWTRAN reports for the six.
constexpr Published kPublished[] = {
    {StandardAtmosphere::tropical, 299.7, 4.117},
    {StandardAtmosphere::midlatitude_summer, 294.2, 2.924},
    {StandardAtmosphere::midlatitude_winter, 272.2, 0.854},
    {StandardAtmosphere::subarctic_summer, 287.2, 2.085},
    {StandardAtmosphere::subarctic_winter, 257.2, 0.418},
    {StandardAtmosphere::us_standard_1976, 288.2, 1.418},
};

TEST(StandardAtmospheres, ColumnsAreLowtransAndNamesReadBack) {
    for (const Published& p : kPublished) {
        const StandardAtmosphereProfile& profile = standard_atmosphere(p.which);
        ASSERT_EQ(profile.levels.size(), 46u) << profile.name;
        EXPECT_EQ(profile.levels.front().altitude_km, 0.0);
        EXPECT_EQ(profile.levels.back().altitude_km, 100.0);
        EXPECT_EQ(profile_temperature_k(profile.levels, 0.0), p.sea_level_k) << profile.name;
        EXPECT_NEAR(profile.water_column_cm, p.water_cm, 0.005 * p.water_cm) << profile.name;
        EXPECT_GE(profile.ozone_column_atm_cm, 0.28) << profile.name;
        EXPECT_LE(profile.ozone_column_atm_cm, 0.38) << profile.name;
        EXPECT_EQ(standard_atmosphere_named(profile.name), p.which);
        EXPECT_NE(std::string(standard_atmosphere_names()).find(profile.name), std::string::npos);
    }
    EXPECT_EQ(standard_atmosphere_named("isothermal"), StandardAtmosphere::isothermal);
    EXPECT_TRUE(standard_atmosphere(StandardAtmosphere::isothermal).levels.empty());
    EXPECT_FALSE(standard_atmosphere_named("midlatitude"));
}

TEST(StandardAtmospheres, TemperatureIsLinearBetweenLevelsAndHeldBeyond) {
    const auto levels = standard_atmosphere(StandardAtmosphere::us_standard_1976).levels;
    // 1976 standard: 288.2 K at 0 km, 281.7 K at 1 km (6.5 K/km), 216.7 K in 11-20 km.
    EXPECT_NEAR(profile_temperature_k(levels, 500.0), 0.5 * (288.2 + 281.7), 1e-9);
    EXPECT_NEAR(profile_temperature_k(levels, 15'000.0), 216.7, 1e-9);
    EXPECT_EQ(profile_temperature_k(levels, -300.0), 288.2);
    EXPECT_EQ(profile_temperature_k(levels, 150'000.0), levels.back().temperature_k);
    EXPECT_EQ(profile_temperature_k({}, 1000.0), 0.0);
}

/// The column above `altitude_m` by a 1 m midpoint sum of the density, interpolated
/// geometrically between levels (the columns' own convention, integrated another way), g/m².
template <typename Field>
double summed_column_above(std::span<const AtmosphereLevel> levels, double altitude_m,
                           Field field) {
    double sum = 0.0;
    for (std::size_t i = 1; i < levels.size(); ++i) {
        const double z0 = levels[i - 1].altitude_km * 1000.0;
        const double z1 = levels[i].altitude_km * 1000.0;
        const double a = field(levels[i - 1]);
        const double b = field(levels[i]);
        for (double z = std::max(z0, altitude_m) + 0.5; z < z1; z += 1.0) {
            const double f = (z - z0) / (z1 - z0);
            sum += a > 0.0 && b > 0.0 ? a * std::pow(b / a, f) : a + f * (b - a);
        }
    }
    return sum;
}

// The share of the water and ozone columns above an altitude: 1 at the ground, 0 at the
// top, falling, and equal to an independent 1 m sum of the densities within 10⁻⁴ (the sum's
// own error: the midpoint rule over whole metres against the levels' exact bounds).
TEST(StandardAtmospheres, SharesOfTheColumnsAboveAnAltitude) {
    for (const auto which : {StandardAtmosphere::midlatitude_summer, StandardAtmosphere::tropical,
                             StandardAtmosphere::subarctic_winter}) {
        const StandardAtmosphereProfile& p = standard_atmosphere(which);
        const auto water = [](const AtmosphereLevel& l) { return l.water_g_per_m3; };
        const auto ozone = [](const AtmosphereLevel& l) { return l.ozone_g_per_m3; };
        EXPECT_EQ(water_share_above(p, 0.0), 1.0);
        EXPECT_EQ(water_share_above(p, -50.0), 1.0);
        EXPECT_EQ(ozone_share_above(p, 100'000.0), 0.0);
        double previous = 1.0;
        for (double z : {500.0, 1000.0, 2500.0, 8000.0, 15'000.0, 27'300.0, 60'000.0}) {
            const double w = water_share_above(p, z);
            const double o = ozone_share_above(p, z);
            EXPECT_LE(w, previous) << p.name << " " << z;
            previous = w;
            EXPECT_NEAR(
                w,
                summed_column_above(p.levels, z, water) / summed_column_above(p.levels, 0.0, water),
                1e-4)
                << p.name << " water " << z;
            EXPECT_NEAR(
                o,
                summed_column_above(p.levels, z, ozone) / summed_column_above(p.levels, 0.0, ozone),
                1e-4)
                << p.name << " ozone " << z;
        }
        // Most of the water is in the lowest 2.5 km, most of the ozone above 15 km.
        EXPECT_LT(water_share_above(p, 2500.0), 0.36) << p.name;
        EXPECT_GT(ozone_share_above(p, 15'000.0), 0.6) << p.name;
    }
    EXPECT_EQ(water_share_above(standard_atmosphere(StandardAtmosphere::isothermal), 10.0), -1.0);
}

// The air's share above an altitude: the table's pressure ratio at its levels, ln p linear
// between them and extended beyond; and, independently, the hydrostatic column of the table's
// own temperatures and water, p(z)/p₀ = exp(−∫ g M / (R T_v) dz) (g falling from 9.80665 m/s²
// as the inverse square of the distance from the Earth's centre, M 28.9644 g/mol for dry air,
// T_v the virtual temperature of the moist air: within 1 % to 20 km, measured −0.4 … +0.66 %,
// the tables' rounding and their temperatures taken linear between levels).
TEST(StandardAtmospheres, TheAirsShareAboveIsThePressureRatio) {
    for (const auto which : {StandardAtmosphere::us_standard_1976, StandardAtmosphere::tropical,
                             StandardAtmosphere::subarctic_winter}) {
        const StandardAtmosphereProfile& p = standard_atmosphere(which);
        const double p0 = p.levels.front().pressure_hpa;
        EXPECT_DOUBLE_EQ(pressure_share_above(p, 0.0), 1.0) << p.name;
        for (const AtmosphereLevel& level : p.levels) {
            EXPECT_NEAR(pressure_share_above(p, level.altitude_km * 1000.0),
                        level.pressure_hpa / p0, 1e-12 * level.pressure_hpa / p0)
                << p.name << " " << level.altitude_km;
        }
        // Halfway between two levels: their geometric mean.
        const AtmosphereLevel& a = p.levels[3];
        const AtmosphereLevel& b = p.levels[4];
        EXPECT_NEAR(pressure_share_above(p, 500.0 * (a.altitude_km + b.altitude_km)),
                    std::sqrt(a.pressure_hpa * b.pressure_hpa) / p0, 1e-12);
        EXPECT_GT(pressure_share_above(p, -300.0), 1.0);
        EXPECT_LT(pressure_share_above(p, 120'000.0), p.levels.back().pressure_hpa / p0);
        constexpr double kGravity = 9.80665, kMolarMass = 0.0289644, kGas = 8.314462618;
        constexpr double kEarthRadiusM = 6'356'766.0;
        double integral = 0.0;
        constexpr double kStepM = 10.0;
        for (double z = 0.0; z < 20'000.0; z += kStepM) {
            const double mid = z + 0.5 * kStepM;
            const double g = kGravity * std::pow(kEarthRadiusM / (kEarthRadiusM + mid), 2.0);
            // Moist air is lighter: the virtual temperature T / (1 − 0.378 e/p), e the water's
            // vapour pressure (ρ_w R_v T, the density linear between levels).
            const double t = profile_temperature_k(p.levels, mid);
            const auto above = std::upper_bound(
                p.levels.begin(), p.levels.end(), mid / 1000.0,
                [](double zk, const AtmosphereLevel& l) { return zk < l.altitude_km; });
            const AtmosphereLevel& lo = *(above - 1);
            const AtmosphereLevel& hi = *above;
            const double f = (mid / 1000.0 - lo.altitude_km) / (hi.altitude_km - lo.altitude_km);
            const double water = lo.water_g_per_m3 + f * (hi.water_g_per_m3 - lo.water_g_per_m3);
            const double vapour_pa = water * 1e-3 * 461.5 * t;
            const double pressure_pa = 100.0 * p0 * std::exp(-integral);
            const double virtual_t = t / (1.0 - 0.378 * vapour_pa / pressure_pa);
            integral += g * kMolarMass / (kGas * virtual_t) * kStepM;
            if (std::fmod(z + kStepM, 5000.0) == 0.0) {
                EXPECT_NEAR(pressure_share_above(p, z + kStepM) / std::exp(-integral), 1.0, 0.01)
                    << p.name << " at " << z + kStepM << " m";
            }
        }
    }
    EXPECT_EQ(pressure_share_above(standard_atmosphere(StandardAtmosphere::isothermal), 10.0),
              -1.0);
}

}  // namespace standard_atmospheres_test
}  // namespace glint::model
