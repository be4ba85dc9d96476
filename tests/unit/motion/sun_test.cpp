// SPDX-License-Identifier: Apache-2.0
// Sun and moon positions against published worked examples: the example of the NREL SPA paper
// (I. Reda and A. Andreas, "Solar position algorithm for solar radiation applications",
// Solar Energy 76(5), 2004, §A5 of NREL/TP-560-34302; docs/references.md), with its
// refraction and ΔT; examples 47.a (moon position) and 48.a (illuminated fraction) of
// J. Meeus, "Astronomical Algorithms", 2nd ed., Willmann-Bell, 1998; plus the time-scale
// table, the ENU direction, refraction behaviour and input checks. The independent-program
// comparison (astropy) is in tests/oracle/motion/sun_oracle_test.cpp.
#include "glint/motion/sun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "glint/core/error.h"
#include "glint/motion/moon.h"

namespace glint::motion {
namespace sun_test {

/// The SPA paper's example (§A5): 2003-10-17 12:30:30 local time, zone −7 h, ΔUT1 = 0,
/// ΔT = 67 s, 39.742476° N, 105.1786° W, 1830.14 m, 820 mbar, 11 °C, refraction applied.
TEST(Sun, SpaPaperExample) {
    const DateTime utc = parse_iso8601("2003-10-17T12:30:30-07:00");
    AstroOptions options;
    options.apply_refraction = true;
    options.pressure_mbar = 820.0;
    options.temperature_c = 11.0;
    options.delta_ut1_s = 0.0;
    options.delta_t_s = 67.0;
    const SunPosition sun = sun_position(utc, 39.742476, -105.1786, 1830.14, options);
    EXPECT_NEAR(sun.zenith_deg, 50.11162, 5e-6);
    EXPECT_NEAR(sun.azimuth_deg, 194.34024, 5e-6);
    EXPECT_NEAR(sun.distance_au, 0.9965422974, 1e-9);
    EXPECT_NEAR(sun.right_ascension_deg, 202.22741, 5e-6);
    EXPECT_NEAR(sun.declination_deg, -9.31434, 5e-6);
    // Without refraction the sun is lower (larger zenith), by SPA's 0.016° here.
    options.apply_refraction = false;
    const SunPosition airless = sun_position(utc, 39.742476, -105.1786, 1830.14, options);
    EXPECT_NEAR(airless.zenith_deg - sun.zenith_deg, 0.0161, 0.0005);
    EXPECT_EQ(airless.azimuth_deg, sun.azimuth_deg);
}

TEST(Sun, DirectionMatchesZenithAzimuth) {
    const DateTime utc = parse_iso8601("2021-06-21T15:00:00Z");
    const SunPosition sun = sun_position(utc, 43.0, -78.0, 150.0);
    EXPECT_NEAR(norm(sun.direction_enu), 1.0, 1e-15);
    EXPECT_NEAR(std::acos(sun.direction_enu.z) * 180 / std::numbers::pi, sun.zenith_deg, 1e-9);
    EXPECT_NEAR(std::atan2(sun.direction_enu.x, sun.direction_enu.y) * 180 / std::numbers::pi,
                sun.azimuth_deg - (sun.azimuth_deg > 180 ? 360 : 0), 1e-9);
    // Mid-morning in June at 43° N: sun in the east, well up.
    EXPECT_GT(sun.direction_enu.x, 0.0);
    EXPECT_LT(sun.zenith_deg, 60.0);
    const SunPosition via_frame = sun_position(utc, SceneFrame(43.0, -78.0, 150.0));
    EXPECT_EQ(via_frame.zenith_deg, sun.zenith_deg);
    EXPECT_EQ(via_frame.azimuth_deg, sun.azimuth_deg);
    const Vec3 east = direction_from_zenith_azimuth(90, 90);
    EXPECT_NEAR(east.x, 1.0, 1e-15);
    EXPECT_NEAR(east.y, 0.0, 1e-15);
    EXPECT_NEAR(east.z, 0.0, 1e-15);
}

TEST(Sun, SolsticeNoonAndDistance) {
    // Near the June solstice at local noon on the Tropic of Cancer the sun is nearly overhead;
    // the Earth is near aphelion (1.0167 AU) in early July and perihelion (0.9833) in January.
    const SunPosition june = sun_position(parse_iso8601("2024-06-20T12:01:40Z"), 23.44, 0.0, 0);
    EXPECT_LT(june.zenith_deg, 0.05);
    const SunPosition july = sun_position(parse_iso8601("2024-07-05T00:00:00Z"), 0, 0, 0);
    const SunPosition jan = sun_position(parse_iso8601("2024-01-03T00:00:00Z"), 0, 0, 0);
    EXPECT_NEAR(july.distance_au, 1.0167, 0.0002);
    EXPECT_NEAR(jan.distance_au, 0.9833, 0.0002);
    // Polar night: the sun stays below the horizon at the north pole in December.
    for (int hour = 0; hour < 24; hour += 3) {
        DateTime t = parse_iso8601("2023-12-21T00:00:00Z");
        t = add_seconds(t, hour * 3600.0);
        EXPECT_GT(sun_position(t, 89.9, 0, 0).zenith_deg, 90.0);
        EXPECT_LT(sun_position(t, -89.9, 0, 0).zenith_deg, 90.0);  // polar day in the south
    }
}

TEST(Sun, RefractionOnlyNearOrAboveHorizon) {
    const DateTime utc = parse_iso8601("2023-03-01T00:00:00Z");
    AstroOptions on;
    on.apply_refraction = true;
    // Deep night at 0° E: no correction.
    EXPECT_EQ(sun_position(utc, 10, 0, 0, on).zenith_deg, sun_position(utc, 10, 0, 0).zenith_deg);
    // Daytime at 180° E: refraction lifts the sun.
    EXPECT_LT(sun_position(utc, 10, 180, 0, on).zenith_deg,
              sun_position(utc, 10, 180, 0).zenith_deg);
}

TEST(Sun, TimeScales) {
    EXPECT_EQ(tai_minus_utc_s(parse_iso8601("1971-12-31T23:59:59Z")), 10.0);
    EXPECT_EQ(tai_minus_utc_s(parse_iso8601("1972-01-01T00:00:00Z")), 10.0);
    EXPECT_EQ(tai_minus_utc_s(parse_iso8601("1972-07-01T00:00:00Z")), 11.0);
    EXPECT_EQ(tai_minus_utc_s(parse_iso8601("2016-12-31T23:59:59Z")), 36.0);
    EXPECT_EQ(tai_minus_utc_s(parse_iso8601("2017-01-01T00:00:00Z")), 37.0);
    EXPECT_EQ(tai_minus_utc_s(parse_iso8601("2040-01-01T00:00:00Z")), 37.0);
    const DateTime now = parse_iso8601("2024-01-01T00:00:00Z");
    EXPECT_DOUBLE_EQ(delta_t_s(now), 69.184);
    AstroOptions options;
    options.delta_ut1_s = 0.1;
    EXPECT_DOUBLE_EQ(delta_t_s(now, options), 69.084);
    options.delta_t_s = 67.0;
    EXPECT_DOUBLE_EQ(delta_t_s(now, options), 67.0);
}

TEST(Sun, RejectsBadInput) {
    const DateTime utc = parse_iso8601("2020-01-01T00:00:00Z");
    EXPECT_THROW(sun_position(utc, 91, 0, 0), Error);
    EXPECT_THROW(sun_position(utc, NAN, 0, 0), Error);
    EXPECT_THROW(moon_position(utc, 0, INFINITY, 0), Error);
    AstroOptions bad;
    bad.apply_refraction = true;
    bad.pressure_mbar = -1;
    EXPECT_THROW(sun_position(utc, 0, 0, 0, bad), Error);
    bad.pressure_mbar = 1000;
    bad.temperature_c = -300;
    EXPECT_THROW(sun_position(utc, 0, 0, 0, bad), Error);
    AstroOptions nan_dt;
    nan_dt.delta_t_s = NAN;
    EXPECT_THROW(sun_position(utc, 0, 0, 0, nan_dt), Error);
}

/// Meeus, "Astronomical Algorithms" 2nd ed., example 47.a: 1992 April 12, 0h TD. Apparent
/// α = 134.688470°, δ = 13.768368°, Δ = 368409.7 km. ΔT is set to 0 so that UTC = TD.
TEST(Moon, MeeusExample47a) {
    AstroOptions options;
    options.delta_t_s = 0.0;
    const MoonPosition moon =
        moon_position(parse_iso8601("1992-04-12T00:00:00Z"), 0.0, 0.0, 0.0, options);
    EXPECT_NEAR(moon.right_ascension_deg, 134.688470, 2e-5);
    EXPECT_NEAR(moon.declination_deg, 13.768368, 2e-5);
    EXPECT_NEAR(moon.geocentric_distance_km, 368409.7, 0.1);
    // Topocentric distance is shorter when the moon is up, longer when it is down.
    EXPECT_GT(moon.distance_km, moon.geocentric_distance_km - 6379.0);
    EXPECT_LT(moon.distance_km, moon.geocentric_distance_km + 6379.0);
    EXPECT_NEAR(norm(moon.direction_enu), 1.0, 1e-15);
}

/// Meeus example 48.a: same instant, illuminated fraction k = 0.6786, phase angle
/// i = 69.0756° (waxing: first quarter was 1992-04-10).
TEST(Moon, MeeusExample48a) {
    AstroOptions options;
    options.delta_t_s = 0.0;
    const MoonPosition moon =
        moon_position(parse_iso8601("1992-04-12T00:00:00Z"), 0.0, 0.0, 0.0, options);
    EXPECT_NEAR(moon.phase_fraction, 0.6786, 1e-4);
    EXPECT_NEAR(moon.phase_angle_deg, 69.0756, 0.005);
    EXPECT_TRUE(moon.waxing);
}

TEST(Moon, FullAndNewMoon) {
    // Full moon near 2024-03-25 07:00 UTC, new moon near 2024-03-10 09:00 UTC.
    const MoonPosition full = moon_position(parse_iso8601("2024-03-25T07:00:00Z"), 0, 0, 0);
    const MoonPosition fresh = moon_position(parse_iso8601("2024-03-10T09:00:00Z"), 0, 0, 0);
    EXPECT_GT(full.phase_fraction, 0.99);
    EXPECT_LT(fresh.phase_fraction, 0.01);
}

}  // namespace sun_test
}  // namespace glint::motion
