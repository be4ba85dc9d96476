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

}  // namespace standard_atmospheres_test
}  // namespace glint::model
