// SPDX-License-Identifier: Apache-2.0
// Tests of the physical constants (against CODATA 2018 and their defining relations) and of
// the unit conversions in glint/core/units.h.
#include "glint/core/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace glint {
namespace units_test {

TEST(Constants, ExactSiValues) {
    EXPECT_EQ(kPlanckJS, 6.62607015e-34);
    EXPECT_EQ(kSpeedOfLightMPerS, 299792458.0);
    EXPECT_EQ(kBoltzmannJPerK, 1.380649e-23);
    EXPECT_EQ(kElementaryChargeC, 1.602176634e-19);
}

TEST(Constants, StefanBoltzmannFromDefinition) {
    // σ = 2π⁵k⁴ / (15 h³ c²); CODATA 2018 quotes 5.670374419e-8 (10 digits).
    const double pi = std::numbers::pi;
    const double sigma = 2.0 * std::pow(pi, 5) * std::pow(kBoltzmannJPerK, 4) /
                         (15.0 * std::pow(kPlanckJS, 3) * kSpeedOfLightMPerS * kSpeedOfLightMPerS);
    EXPECT_NEAR(sigma / kStefanBoltzmannWPerM2K4, 1.0, 1e-9);
}

TEST(Constants, RadiationConstants) {
    // CODATA 2018: c₁L = 2hc² = 1.191042972e-16 W m² sr⁻¹, c₂ = 1.438776877e-2 m K.
    EXPECT_NEAR(kPlanckC1WM2PerSr / 1.191042972e-16, 1.0, 1e-9);
    EXPECT_NEAR(kPlanckC2UmK / 14387.76877, 1.0, 1e-9);
    // Wien: b = c₂ / x where x = 4.965114231744276 solves x = 5(1 − e^(−x)).
    EXPECT_NEAR(kWienDisplacementUmK / (kPlanckC2UmK / 4.965114231744276), 1.0, 1e-9);
}

TEST(Conversions, Length) {
    EXPECT_EQ(um_to_nm(0.55), 550.0);
    EXPECT_DOUBLE_EQ(nm_to_um(550.0), 0.55);
    EXPECT_DOUBLE_EQ(um_to_m(10.0), 1e-5);
    EXPECT_DOUBLE_EQ(m_to_um(1e-5), 10.0);
    EXPECT_DOUBLE_EQ(nm_to_m(500.0), 5e-7);
    EXPECT_DOUBLE_EQ(m_to_nm(5e-7), 500.0);
    static_assert(um_to_nm(1.0) == 1000.0, "constexpr");
}

TEST(Conversions, AreaAndRadiance) {
    EXPECT_DOUBLE_EQ(cm2_to_m2(1e4), 1.0);
    EXPECT_DOUBLE_EQ(m2_to_cm2(1.0), 1e4);
    // 1 W/(m² sr µm) = 1e-4 W/(cm² sr µm)
    EXPECT_DOUBLE_EQ(per_m2_to_per_cm2(1.0), 1e-4);
    EXPECT_DOUBLE_EQ(per_cm2_to_per_m2(1e-4), 1.0);
}

TEST(Conversions, Power) {
    EXPECT_DOUBLE_EQ(w_to_mw(1.5), 1500.0);
    EXPECT_DOUBLE_EQ(mw_to_w(1500.0), 1.5);
    EXPECT_DOUBLE_EQ(w_to_uw(2e-6), 2.0);
    EXPECT_DOUBLE_EQ(uw_to_w(2.0), 2e-6);
}

TEST(Conversions, Angle) {
    EXPECT_DOUBLE_EQ(deg_to_rad(180.0), std::numbers::pi);
    EXPECT_DOUBLE_EQ(rad_to_deg(std::numbers::pi / 2.0), 90.0);
    EXPECT_NEAR(rad_to_deg(deg_to_rad(37.25)), 37.25, 1e-13);
}

}  // namespace units_test
}  // namespace glint
