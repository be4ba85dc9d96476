// SPDX-License-Identifier: Apache-2.0
// Tests of the aerosol types and LOWTRAN 7's aerosol profiles (glint/model/aerosol_models.h):
// every name reads back to its mixture; the boundary layer's ground extinction follows
// Koschmieder's law (3.912/V less the Rayleigh extinction) at and between LOWTRAN's
// tabulated visibilities; the troposphere and stratosphere take their season's tables.
#include "glint/model/aerosol_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace glint::model {
namespace aerosol_models_test {

TEST(AerosolModels, EveryNameReadsBackToItsMixture) {
    const std::string names = aerosol_mixture_names();
    std::size_t start = 0;
    int count = 0;
    while (start < names.size()) {
        const std::size_t end = std::min(names.find(", ", start), names.size());
        const std::string name = names.substr(start, end - start);
        const auto mixture = aerosol_mixture_named(name);
        ASSERT_TRUE(mixture.has_value()) << name;
        EXPECT_EQ(std::string(mixture->name), name);
        EXPECT_FALSE(mixture->components.empty());
        for (const AerosolComponentNumber& c : mixture->components)
            EXPECT_GT(c.number_per_cm3, 0.0);
        ++count;
        start = end + 2;
    }
    EXPECT_EQ(count, 14);
    EXPECT_FALSE(aerosol_mixture_named("haze").has_value());
    // The aliases are the mixtures they name.
    EXPECT_EQ(aerosol_mixture_named("rural")->components.data(),
              aerosol_mixture_named("continental_average")->components.data());
    EXPECT_FALSE(aerosol_mixture_named("stratospheric")->humidity_growth);
}

// At the ground LOWTRAN's boundary layer is Koschmieder's extinction 3.912/V minus the
// Rayleigh extinction of sea-level air at 550 nm (0.0116 km⁻¹): its table holds that to its
// printed digits, and the interpolation in 1/V keeps it between and beyond the tabulated
// visibilities: within 1 %, or 6e-4 km⁻¹ where the extinction is small (the 50 km entry,
// 0.0662, is already 4.4e-4 below the law's 0.0666, and the extrapolation to clearer air
// carries that).
TEST(AerosolModels, TheGroundExtinctionIsKoschmiedersLaw) {
    for (double v : {1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 23.0, 35.0, 50.0, 100.0, 200.0}) {
        const double expected = 3.912 / v - 0.0116;
        EXPECT_NEAR(lowtran_aerosol_extinction(0, v, AerosolSeason::spring_summer).boundary_layer,
                    expected, std::max(0.01 * expected, 6e-4))
            << v << " km";
    }
    // Beyond Koschmieder's clear limit (3.912/0.0116 = 337 km) there is no aerosol.
    EXPECT_EQ(lowtran_aerosol_extinction(0, 1000.0, AerosolSeason::spring_summer).boundary_layer,
              0.0);
}

TEST(AerosolModels, TheTablesAreLowtransAtTheirLevels) {
    const auto levels = aerosol_profile_levels_km();
    ASSERT_EQ(levels.size(), 33u);
    EXPECT_EQ(levels[2], 2.0);
    EXPECT_EQ(levels[26], 30.0);
    EXPECT_EQ(levels[32], 100.0);
    const auto summer = AerosolSeason::spring_summer;
    const auto winter = AerosolSeason::fall_winter;
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(1, 23.0, summer).boundary_layer, 9.91e-02);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(2, 50.0, summer).boundary_layer, 2.60e-02);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(3, 23.0, summer).troposphere, 3.46e-02);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(3, 50.0, winter).troposphere, 1.14e-02);
    // Below 23 km visibility the lower troposphere keeps the 23 km table; above 4 km the
    // visibility does not matter.
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(4, 5.0, summer).troposphere, 1.85e-02);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(6, 5.0, summer).troposphere, 7.71e-03);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(6, 50.0, summer).troposphere, 7.71e-03);
    // Between 23 and 50 km, linear in 1/V: at 1/V halfway, the mean.
    const double v = 1.0 / (0.5 / 23.0 + 0.5 / 50.0);
    EXPECT_NEAR(lowtran_aerosol_extinction(3, v, summer).troposphere, 0.5 * (3.46e-02 + 1.46e-02),
                1e-12);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(11, 23.0, summer).stratosphere, 7.99e-04);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(11, 23.0, winter).stratosphere, 7.14e-04);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(26, 23.0, winter).stratosphere, 3.32e-05);
    EXPECT_DOUBLE_EQ(lowtran_aerosol_extinction(32, 23.0, winter).stratosphere, 9.31e-10);
    // Each level belongs to one regime.
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const RegimeExtinction e = lowtran_aerosol_extinction(k, 23.0, summer);
        const int nonzero = (e.boundary_layer > 0) + (e.troposphere > 0) + (e.stratosphere > 0);
        EXPECT_EQ(nonzero, 1) << levels[k] << " km";
    }
}

}  // namespace aerosol_models_test
}  // namespace glint::model
