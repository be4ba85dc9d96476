// SPDX-License-Identifier: Apache-2.0
// Tests of the standard atmospheres (glint/model/standard_atmospheres.h): every name reads
// back; the tables' columns are LOWTRAN 7's (its model atmospheres' precipitable water and
// ozone); the temperature interpolates between levels and
// holds its ends.
#include "glint/model/standard_atmospheres.h"

#include <gtest/gtest.h>

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

}  // namespace standard_atmospheres_test
}  // namespace glint::model
