// SPDX-License-Identifier: Apache-2.0
// SGP4/SDP4 and TEME: GMST against Example 3-5 of D. A. Vallado, "Fundamentals of
// Astrodynamics and Applications" (docs/references.md), TEME ↔ ECEF properties, states
// hand-copied from the verification output tcppver.out of Vallado, Crawford, Hujsak & Kelso,
// "Revisiting Spacetrack Report #3" (AIAA 2006-6753) (near-Earth, deep-space, 12 h and 24 h
// resonant), the error codes of decaying orbits, and the guarantees of the API (no NaN,
// invalid elements refused, DateTime and minutes agree). The full verification set runs in
// tests/oracle/motion.
#include "glint/motion/sgp4.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "glint/motion/teme.h"
#include "glint/motion/tle.h"
#include "glint/test/angles.h"

namespace glint::motion {
namespace sgp4_test {

using ::testing::HasSubstr;

using glint::test::kPi;
constexpr double kMetre_km = 1.0e-3;
constexpr double kMmPerS_km_s = 1.0e-6;

Sgp4 satellite(const char* line1, const char* line2) { return Sgp4(Tle::parse(line1, line2)); }

const char* const k00005[2] = {
    "1 00005U 58002B   00179.78495062  .00000023  00000-0  28098-4 0  4753",
    "2 00005  34.2682 348.7242 1859667 331.7664  19.3264 10.82419157413667"};
const char* const k04632[2] = {
    "1 04632U 70093B   04031.91070959 -.00000084  00000-0  10000-3 0  9955",
    "2 04632  11.4628 273.1101 1450506 207.6000 143.9350  1.20231981 44145"};
const char* const k08195[2] = {
    "1 08195U 75081A   06176.33215444  .00000099  00000-0  11873-3 0   813",
    "2 08195  64.1586 279.0717 6877146 264.7651  20.2257  2.00491383225656"};
const char* const k24208[2] = {
    "1 24208U 96044A   06177.04061740 -.00000094  00000-0  10000-3 0  1600",
    "2 24208   3.8536  80.0121 0026640 311.0977  48.3000  1.00778054 36119"};
const char* const k28350[2] = {
    "1 28350U 04020A   06167.21788666  .16154492  76267-5  18678-3 0  8894",
    "2 28350  64.9977 345.6130 0024870 260.7578  99.9590 16.47856722116490"};
const char* const k28872[2] = {
    "1 28872U 05037B   05333.02012661  .25992681  00000-0  24476-3 0  1534",
    "2 28872  96.4736 157.9986 0303955 244.0492 110.6523 16.46015938 10708"};

/// Expects `state` within 1 m and 1 mm/s of a tcppver.out line.
void expect_state(const Sgp4State& state, Vec3 r_km, Vec3 v_km_s) {
    ASSERT_TRUE(state.ok()) << describe(state.error);
    EXPECT_LT(norm(state.position_km - r_km), kMetre_km);
    EXPECT_LT(norm(state.velocity_km_s - v_km_s), kMmPerS_km_s);
}

TEST(Gmst, ValladoExample3_5) {
    // 1992-08-20 12:14:00 UT1 (JD 2448855.009722...) → GMST 152.578787886° in the book; the
    // exact evaluation of the same formula gives 152.5787878103° (the book rounds T_UT1),
    // 7.6e-8° = 0.3 mas away.
    const double jd = 2448854.5 + (12.0 + 14.0 / 60.0) / 24.0;
    EXPECT_NEAR(gmst_rad(jd) * 180.0 / kPi, 152.578787886, 1e-7);
    EXPECT_NEAR(gmst_rad(jd) * 180.0 / kPi, 152.5787878103, 1e-9);
}

TEST(Gmst, AtJ2000AndRange) {
    // 67310.54841 s of sidereal time = 280.46061837504°.
    EXPECT_NEAR(gmst_rad(2451545.0) * 180.0 / kPi, 280.46061837504, 1e-9);
    for (double jd = 2400000.5; jd < 2500000.0; jd += 1234.567) {
        const double g = gmst_rad(jd);
        EXPECT_GE(g, 0.0);
        EXPECT_LT(g, 2.0 * kPi);
    }
    // One sidereal rotation per 0.99726957 solar day.
    EXPECT_NEAR(gmst_rate_rad_s(2451545.0), 7.2921158553e-5, 1e-14);
}

TEST(Teme, RotatesAboutZByGmst) {
    const double jd = 2453101.827406783;
    const double theta = gmst_rad(jd);
    const PositionVelocity out = teme_to_ecef({7000.0, 0.0, 100.0}, {0.0, 0.0, 0.0}, jd);
    EXPECT_NEAR(out.position_km.x, 7000.0 * std::cos(theta), 1e-9);
    EXPECT_NEAR(out.position_km.y, -7000.0 * std::sin(theta), 1e-9);
    EXPECT_DOUBLE_EQ(out.position_km.z, 100.0);
    // A point at rest in TEME moves westward in ECEF at ω r.
    EXPECT_NEAR(norm(out.velocity_km_s), gmst_rate_rad_s(jd) * 7000.0, 1e-12);
}

TEST(Teme, EarthFixedPointHasZeroEcefVelocity) {
    const double jd = 2455000.3;
    const Vec3 r_ecef{1000.0, 6000.0, 2000.0};
    // The point's inertial velocity is ω × r; in ECEF it is at rest.
    const PositionVelocity teme = ecef_to_teme(r_ecef, {0.0, 0.0, 0.0}, jd);
    const double w = gmst_rate_rad_s(jd);
    EXPECT_NEAR(norm(teme.velocity_km_s), w * std::hypot(1000.0, 6000.0), 1e-12);
    const PositionVelocity back = teme_to_ecef(teme.position_km, teme.velocity_km_s, jd);
    EXPECT_LT(norm(back.position_km - r_ecef), 1e-9);
    EXPECT_LT(norm(back.velocity_km_s), 1e-12);
}

TEST(Sgp4, NearEarth00005MatchesTcppver) {
    const Sgp4 sat = satellite(k00005[0], k00005[1]);
    EXPECT_FALSE(sat.deep_space());
    expect_state(sat.propagate_minutes(0.0), {7022.46529266, -1400.08296755, 0.03995155},
                 {1.893841015, 6.405893759, 4.534807250});
    expect_state(sat.propagate_minutes(360.0), {-7154.03120202, -3783.17682504, -3536.19412294},
                 {4.741887409, -4.151817765, -2.093935425});
    expect_state(sat.propagate_minutes(4320.0), {-9060.47373569, 4658.70952502, 813.68673153},
                 {-2.232832783, -4.110453490, -3.157345433});
}

TEST(Sgp4, DeepSpace04632MatchesTcppver) {
    const Sgp4 sat = satellite(k04632[0], k04632[1]);
    EXPECT_TRUE(sat.deep_space());
    expect_state(sat.propagate_minutes(0.0), {2334.11450085, -41920.44035349, -0.03867437},
                 {2.826321032, -0.065091664, 0.570936053});
    expect_state(sat.propagate_minutes(-5184.0), {-29020.02587128, 13819.84419063, -5713.33679183},
                 {-1.768068390, -3.235371192, -0.395206135});
    expect_state(sat.propagate_minutes(-4896.0), {-15129.94694545, -36907.74526221, -3487.56256701},
                 {2.581167187, -1.524204737, 0.504805763});
}

TEST(Sgp4, HalfDayResonance08195MatchesTcppver) {
    const Sgp4 sat = satellite(k08195[0], k08195[1]);
    EXPECT_TRUE(sat.deep_space());
    expect_state(sat.propagate_minutes(0.0), {2349.89483350, -14785.93811562, 0.02119378},
                 {2.721488096, -3.256811655, 4.498416672});
    expect_state(sat.propagate_minutes(2880.0), {3417.20931586, -16038.79510665, 1894.74934058},
                 {2.585515864, -2.596818146, 4.456882556});
}

TEST(Sgp4, SynchronousResonance24208MatchesTcppver) {
    const Sgp4 sat = satellite(k24208[0], k24208[1]);
    expect_state(sat.propagate_minutes(0.0), {7534.10987189, 41266.39266843, -0.10801028},
                 {-3.027168008, 0.558848996, 0.207982755});
    expect_state(sat.propagate_minutes(1440.0), {5501.08137100, 41590.27784405, 138.32522930},
                 {-3.050691874, 0.409203052, 0.207958133});
}

TEST(Sgp4, DecayReturnsErrorCodesWithoutNaN) {
    // 28872 is lost within an hour: the reference output ends at 50 min.
    const Sgp4 minotaur = satellite(k28872[0], k28872[1]);
    expect_state(minotaur.propagate_minutes(50.0), {5548.43325922, -2480.16469245, -1979.24314527},
                 {-2.763269534, 0.199691915, -7.482796996});
    const Sgp4State lost = minotaur.propagate_minutes(55.0);
    EXPECT_EQ(lost.error, Sgp4Error::decayed);
    EXPECT_FALSE(lost.ok());
    EXPECT_EQ(lost.position_km, Vec3{});
    EXPECT_EQ(lost.velocity_km_s, Vec3{});
    // 28350: drag drives the mean eccentricity out of range before 1560 min.
    const Sgp4 cosmos = satellite(k28350[0], k28350[1]);
    EXPECT_TRUE(cosmos.propagate_minutes(1440.0).ok());
    EXPECT_EQ(cosmos.propagate_minutes(1560.0).error, Sgp4Error::mean_elements);
}

TEST(Sgp4, ThrowingHelperNamesTheTime) {
    const Sgp4 minotaur = satellite(k28872[0], k28872[1]);
    EXPECT_NO_THROW(minotaur.propagate_or_throw(10.0));
    try {
        minotaur.propagate_or_throw(55.0);
        FAIL() << "no error";
    } catch (const Error& error) {
        EXPECT_EQ(error.category(), ErrorCategory::runtime);
        EXPECT_THAT(error.what(), HasSubstr("satellite 28872 decayed at t=55 min after epoch"));
    }
    const Sgp4 cosmos = satellite(k28350[0], k28350[1]);
    EXPECT_THAT(
        [&] { cosmos.propagate_or_throw(1560.0); },
        ::testing::ThrowsMessage<Error>(HasSubstr("sgp4 error 1 at t=1560 min after epoch")));
}

TEST(Sgp4, InvalidTimesAreErrorsNotNaN) {
    const Sgp4 sat = satellite(k04632[0], k04632[1]);
    for (const double t : {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(), 2.0e8}) {
        const Sgp4State state = sat.propagate_minutes(t);
        EXPECT_EQ(state.error, Sgp4Error::invalid_time);
        EXPECT_EQ(state.position_km, Vec3{});
    }
}

TEST(Sgp4, InvalidElementsAreRefusedAtConstruction) {
    Tle tle = Tle::parse(k00005[0], k00005[1]);
    tle.eccentricity = 1.2;
    EXPECT_THROW(Sgp4{tle}, Error);
    tle = Tle::parse(k00005[0], k00005[1]);
    tle.mean_motion_rev_day = 0.0;
    EXPECT_THROW(Sgp4{tle}, Error);
    tle = Tle::parse(k00005[0], k00005[1]);
    tle.inclination_deg = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THAT([&] { Sgp4{tle}; },
                ::testing::ThrowsMessage<Error>(HasSubstr("satellite 5: element set has a non")));
}

TEST(Sgp4, DateTimeAndMinutesAgree) {
    const Sgp4 sat = satellite(k00005[0], k00005[1]);
    const DateTime later = add_seconds(sat.tle().epoch(), 360.0 * 60.0);
    EXPECT_NEAR(sat.minutes_since_epoch(later), 360.0, 1e-9);
    const Sgp4State a = sat.propagate(later);
    const Sgp4State b = sat.propagate_minutes(360.0);
    EXPECT_LT(norm(a.position_km - b.position_km), 1e-6);
}

TEST(Sgp4, GravityModelsDifferSlightly) {
    const Tle tle = Tle::parse(k00005[0], k00005[1]);
    const Sgp4 wgs72(tle, GravityModel::wgs72);
    const Sgp4 wgs84(tle, GravityModel::wgs84);
    const Sgp4 old(tle, GravityModel::wgs72_old);
    EXPECT_EQ(wgs84.gravity(), GravityModel::wgs84);
    EXPECT_NEAR(gravity_constants(GravityModel::wgs72).xke_per_min, 0.0743669161331734, 1e-15);
    EXPECT_DOUBLE_EQ(gravity_constants(GravityModel::wgs72_old).xke_per_min, 0.0743669161);
    const double d84 = norm(wgs84.propagate_minutes(1440.0).position_km -
                            wgs72.propagate_minutes(1440.0).position_km);
    const double dold = norm(old.propagate_minutes(1440.0).position_km -
                             wgs72.propagate_minutes(1440.0).position_km);
    EXPECT_GT(d84, 1e-4);
    EXPECT_LT(d84, 10.0);
    EXPECT_LT(dold, 1.0);
}

TEST(Sgp4, CopiesShareTheModelAndAgree) {
    const Sgp4 sat = satellite(k08195[0], k08195[1]);
    const Sgp4 copy = sat;  // NOLINT(performance-unnecessary-copy-initialization)
    // The resonance integrator restarts from epoch on every call: order does not matter.
    const Sgp4State late = copy.propagate_minutes(2880.0);
    (void)copy.propagate_minutes(-1000.0);
    const Sgp4State again = copy.propagate_minutes(2880.0);
    EXPECT_EQ(late.position_km, again.position_km);
    EXPECT_EQ(late.position_km, sat.propagate_minutes(2880.0).position_km);
    EXPECT_NEAR(sat.mean_motion_rad_min(), 2.00491383 * 2.0 * kPi / 1440.0, 1e-5);
}

}  // namespace sgp4_test
}  // namespace glint::motion
