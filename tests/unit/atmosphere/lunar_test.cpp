// SPDX-License-Identifier: Apache-2.0
// Tests of the moonlight model (glint/atmosphere/lunar.h): the full moon's brightness against
// its published magnitude, the phase law of Krisciunas & Schaefer (1991), 1/d², and errors.
#include "glint/atmosphere/lunar.h"

#include <gtest/gtest.h>

#include <cmath>

#include "glint/core/error.h"

namespace glint::atmosphere {
namespace lunar_test {

TEST(Moonlight, FullMoonIsMagnitudeMinus12Point7) {
    // V(sun) = −26.74, V(full moon at the mean distance) = −12.73 (Allen's Astrophysical
    // Quantities): a ratio of 10^(−0.4 · 14.01) = 2.49e-6. The grey geometric albedo 0.12
    // gives 2.45e-6: within 0.05 magnitude.
    const double ratio = lunar_irradiance_ratio(0.0, kMoonMeanDistanceKm);
    EXPECT_NEAR(ratio, 0.12 * std::pow(1737.4 / 384400.0, 2), 1e-18);
    const double magnitude_difference = -2.5 * std::log10(ratio);
    EXPECT_NEAR(magnitude_difference, -12.73 - -26.74, 0.05);
}

TEST(Moonlight, PhaseLawAndDistance) {
    const double full = lunar_irradiance_ratio(0.0, kMoonMeanDistanceKm);
    // Quarter moon (α = 90°): 10^(−0.4 (2.34 + 0.26244)) = 0.09100 of full.
    EXPECT_NEAR(lunar_irradiance_ratio(90.0, kMoonMeanDistanceKm) / full, 0.09100, 1e-5);
    EXPECT_EQ(lunar_irradiance_ratio(-90.0, kMoonMeanDistanceKm),
              lunar_irradiance_ratio(90.0, kMoonMeanDistanceKm));
    // Darker with the phase angle, down to nearly nothing at new moon.
    double last = full;
    for (double a = 10.0; a <= 180.0; a += 10.0) {
        const double r = lunar_irradiance_ratio(a, kMoonMeanDistanceKm);
        EXPECT_LT(r, last);
        last = r;
    }
    EXPECT_NEAR(last / full, std::pow(10.0, -0.4 * (4.68 + 4.19904)), 1e-9);  // new moon
    // 1/d².
    EXPECT_NEAR(lunar_irradiance_ratio(30.0, 2.0 * kMoonMeanDistanceKm) /
                    lunar_irradiance_ratio(30.0, kMoonMeanDistanceKm),
                0.25, 1e-15);
    // The disk: 0.259° at the mean distance.
    EXPECT_NEAR(lunar_angular_radius_rad(kMoonMeanDistanceKm) * 180.0 / M_PI, 0.259, 0.001);
}

TEST(Moonlight, BadInputsAreRefused) {
    EXPECT_THROW((void)lunar_irradiance_ratio(NAN, kMoonMeanDistanceKm), Error);
    EXPECT_THROW((void)lunar_irradiance_ratio(0.0, 0.0), Error);
    EXPECT_THROW((void)lunar_angular_radius_rad(1000.0), Error);
}

}  // namespace lunar_test
}  // namespace glint::atmosphere
