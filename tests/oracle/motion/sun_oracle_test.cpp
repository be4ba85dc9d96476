// SPDX-License-Identifier: Apache-2.0
// astropy as an oracle for glint's sun and moon: for dates 1990-2040 and places in both
// hemispheres (polar day and night, the tropics with the sun overhead, the antimeridian, high
// ground and aircraft height) astropy's AltAz frame without refraction (pressure 0, offline
// IERS tables) gives the sun's zenith and azimuth, which must agree within 0.01°, and for the
// moon (get_body) within 0.3° with the illuminated fraction within 0.02. Where astropy's
// bundled IERS table knows UT1 − UTC, glint is run again with it and must then agree within
// 0.001° (SPA's own claim is 0.0003°): the default UT1 = UTC costs up to 0.004°.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "glint/core/datetime.h"
#include "glint/motion/moon.h"
#include "glint/motion/sun.h"
#include "glint/test/oracle.h"
#include "glint/test/temp_dir.h"

namespace glint::motion {
namespace sun_oracle_test {

using nlohmann::json;

/// Reads cases [{utc, lat, lon, alt, moon}] from argv[1]; prints astropy's answers as JSON.
constexpr const char* kAstropyScript = R"(
import json, math, sys, warnings
warnings.simplefilter("ignore")
from astropy.utils import iers
iers.conf.auto_download = False
iers.conf.auto_max_age = None
try:
    iers.conf.iers_degraded_accuracy = "warn"  # dates after the bundled IERS table
except Exception:
    pass
import astropy.units as u
from astropy.time import Time
from astropy.coordinates import AltAz, EarthLocation, get_body, get_sun

out = []
for c in json.load(open(sys.argv[1])):
    t = Time(c["utc"], scale="utc")
    loc = EarthLocation.from_geodetic(c["lon"] * u.deg, c["lat"] * u.deg, c["alt"] * u.m)
    frame = AltAz(obstime=t, location=loc, pressure=0 * u.hPa)
    sun = get_sun(t)
    s = sun.transform_to(frame)
    dut1, status = iers.earth_orientation_table.get().ut1_utc(t, return_status=True)
    r = {"sun_zenith": 90.0 - s.alt.deg, "sun_azimuth": s.az.deg,
         "sun_distance_au": sun.distance.to(u.au).value,
         "dut1": float(dut1.to(u.s).value) if status == 0 else None}
    if c["moon"]:
        moon = get_body("moon", t)
        m = moon.transform_to(frame)
        psi = sun.separation(moon).rad
        R = sun.distance.to(u.km).value
        D = moon.distance.to(u.km).value
        i = math.atan2(R * math.sin(psi), D - R * math.cos(psi))
        r.update({"moon_zenith": 90.0 - m.alt.deg, "moon_azimuth": m.az.deg,
                  "moon_distance_km": m.distance.to(u.km).value,
                  "moon_phase": (1.0 + math.cos(i)) / 2.0})
    out.append(r)
print(json.dumps(out))
)";

struct Case {
    const char* utc;
    double lat_deg;
    double lon_deg;
    double alt_m;
    bool moon;
    const char* what;
};

// clang-format off
const Case kCases[] = {
    {"1990-01-15T17:00:00Z",  38.90,  -77.04,    10, true,  "Washington winter noon"},
    {"1990-07-04T16:00:00Z",  38.90,  -77.04,    10, false, "Washington summer noon"},
    {"1995-02-10T03:00:00Z", -33.87,  151.21,    20, true,  "Sydney afternoon"},
    {"1999-08-11T11:00:00Z",  48.85,    2.35,    35, true,  "Paris, eclipse day"},
    {"2000-01-01T12:00:00Z",   0.00,    0.00,     0, false, "J2000 at (0, 0)"},
    {"2000-03-20T06:05:00Z",   0.00,    0.00,     0, false, "equinox sunrise at (0, 0)"},
    {"2003-10-17T19:30:30Z",  39.742476, -105.1786, 1830.14, true, "SPA example site"},
    {"2005-06-21T00:00:00Z",  78.22,   15.65,    10, false, "Svalbard midnight sun (polar day)"},
    {"2008-12-21T12:00:00Z",  78.22,   15.65,    10, true,  "Svalbard noon (polar night)"},
    {"2010-03-01T03:00:00Z",  35.68,  139.69,    40, true,  "Tokyo noon"},
    {"2012-11-05T06:30:00Z",  28.61,   77.21,   216, false, "Delhi midday"},
    {"2015-12-21T12:00:00Z", -77.85,  166.67,    24, true,  "McMurdo (polar day, south)"},
    {"2016-07-01T12:00:00Z",  45.00,    5.00, 10000, false, "aircraft at 10 km"},
    {"2018-06-21T12:00:00Z", -75.10,  123.35,  3233, false, "Concordia (polar night, south)"},
    {"2020-02-29T23:59:59Z",  64.15,  -21.94,    30, true,  "Reykjavik night"},
    {"2024-06-20T12:01:40Z",  23.44,    0.00,     0, false, "sun overhead on the tropic"},
    {"2025-09-15T14:00:00Z", -23.55,  -46.63,   760, false, "Sao Paulo morning"},
    {"2028-08-08T08:08:08Z",  55.75,   37.62,   150, true,  "Moscow"},
    {"2030-06-01T12:00:00Z",  89.50,    0.00,     0, false, "near the north pole in June"},
    {"2033-04-01T21:00:00Z",  19.82, -155.47,  4205, true,  "Mauna Kea summit"},
    {"2037-05-05T00:00:00Z", -17.71,  178.07,    20, false, "Fiji, near the antimeridian"},
    {"2039-10-10T22:00:00Z",  51.88, -179.90,    10, true,  "Aleutians, west of the antimeridian"},
    {"2040-12-25T18:00:00Z", -34.60,  -58.38,    25, true,  "Buenos Aires summer evening"},
    {"2040-12-31T23:59:00Z",  -1.00,  -90.00,     0, false, "Galapagos sunset"},
};
// clang-format on

/// `value` in scientific notation (std::to_string would print 1e-7 as 0.000000).
std::string sci(double value) {
    std::ostringstream text;
    text << std::scientific << value;
    return text.str();
}

/// |a − b| as angles in degrees, in [0, 180].
double angle_diff_deg(double a, double b) { return std::abs(std::remainder(a - b, 360.0)); }

TEST(SunOracle, AgreesWithAstropy) {
    if (!test::python_has("astropy.coordinates")) {
        GTEST_SKIP() << GLINT_ORACLE_PYTHON
                     << " cannot import astropy (install python3-astropy for the oracle)";
    }
    test::TempDir dir;
    json cases = json::array();
    for (const Case& c : kCases) {
        cases.push_back({{"utc", c.utc},
                         {"lat", c.lat_deg},
                         {"lon", c.lon_deg},
                         {"alt", c.alt_m},
                         {"moon", c.moon}});
    }
    std::ofstream(dir / "cases.json") << cases.dump();
    const test::CommandResult result = test::run_command(
        test::python_command(dir, kAstropyScript, {(dir / "cases.json").string()}));
    ASSERT_EQ(result.exit_status, 0) << result.err;
    const json answers = json::parse(result.out);
    ASSERT_EQ(answers.size(), std::size(kCases));

    double worst_sun_zenith = 0, worst_sun_azimuth = 0, worst_sun_distance = 0;
    double worst_moon_zenith = 0, worst_moon_azimuth = 0, worst_moon_phase = 0;
    double worst_moon_distance = 0, worst_ut1_zenith = 0, worst_ut1_azimuth = 0;
    int with_dut1 = 0, polar_day = 0, polar_night = 0, south = 0, moons = 0;
    for (std::size_t i = 0; i < std::size(kCases); ++i) {
        const Case& c = kCases[i];
        const json& a = answers[i];
        SCOPED_TRACE(std::string(c.utc) + " " + c.what);
        const DateTime utc = parse_iso8601(c.utc);
        const SunPosition sun = sun_position(utc, c.lat_deg, c.lon_deg, c.alt_m);
        const double dz = std::abs(sun.zenith_deg - a["sun_zenith"].get<double>());
        EXPECT_LT(dz, 0.01) << "sun zenith " << sun.zenith_deg;
        worst_sun_zenith = std::max(worst_sun_zenith, dz);
        if (sun.zenith_deg > 0.1) {
            const double da = angle_diff_deg(sun.azimuth_deg, a["sun_azimuth"].get<double>());
            EXPECT_LT(da, 0.01) << "sun azimuth " << sun.azimuth_deg;
            worst_sun_azimuth = std::max(worst_sun_azimuth, da);
        }
        if (!a["dut1"].is_null()) {
            AstroOptions with_ut1;
            with_ut1.delta_ut1_s = a["dut1"].get<double>();
            const SunPosition s1 = sun_position(utc, c.lat_deg, c.lon_deg, c.alt_m, with_ut1);
            const double dz1 = std::abs(s1.zenith_deg - a["sun_zenith"].get<double>());
            EXPECT_LT(dz1, 0.001) << "sun zenith with UT1 " << s1.zenith_deg;
            worst_ut1_zenith = std::max(worst_ut1_zenith, dz1);
            if (s1.zenith_deg > 0.1) {
                const double da1 = angle_diff_deg(s1.azimuth_deg, a["sun_azimuth"].get<double>());
                EXPECT_LT(da1, 0.001) << "sun azimuth with UT1 " << s1.azimuth_deg;
                worst_ut1_azimuth = std::max(worst_ut1_azimuth, da1);
            }
            ++with_dut1;
        }
        const double dr = std::abs(sun.distance_au - a["sun_distance_au"].get<double>());
        EXPECT_LT(dr, 2e-5) << "sun distance " << sun.distance_au;
        worst_sun_distance = std::max(worst_sun_distance, dr);
        if (std::abs(c.lat_deg) > 66.6) (sun.zenith_deg < 90 ? polar_day : polar_night)++;
        if (c.lat_deg < 0) ++south;

        if (!c.moon) continue;
        ++moons;
        const MoonPosition moon = moon_position(utc, c.lat_deg, c.lon_deg, c.alt_m);
        const double mz = std::abs(moon.zenith_deg - a["moon_zenith"].get<double>());
        EXPECT_LT(mz, 0.3) << "moon zenith " << moon.zenith_deg;
        worst_moon_zenith = std::max(worst_moon_zenith, mz);
        if (moon.zenith_deg > 0.1) {
            const double ma = angle_diff_deg(moon.azimuth_deg, a["moon_azimuth"].get<double>());
            EXPECT_LT(ma, 0.3) << "moon azimuth " << moon.azimuth_deg;
            worst_moon_azimuth = std::max(worst_moon_azimuth, ma);
        }
        const double mp = std::abs(moon.phase_fraction - a["moon_phase"].get<double>());
        EXPECT_LT(mp, 0.02) << "moon phase " << moon.phase_fraction;
        worst_moon_phase = std::max(worst_moon_phase, mp);
        const double md = std::abs(moon.distance_km - a["moon_distance_km"].get<double>());
        EXPECT_LT(md, 100.0) << "moon distance " << moon.distance_km;
        worst_moon_distance = std::max(worst_moon_distance, md);
    }
    // The case list must keep covering what the brief asks for.
    EXPECT_GE(std::size(kCases), 20u);
    EXPECT_GE(polar_day, 2);
    EXPECT_GE(polar_night, 2);
    EXPECT_GE(south, 5);
    EXPECT_GE(moons, 10);
    EXPECT_GE(with_dut1, 10);

    std::cout << "worst |glint - astropy|: sun zenith " << worst_sun_zenith << " deg, azimuth "
              << worst_sun_azimuth << " deg, distance " << worst_sun_distance
              << " AU; with astropy's UT1-UTC (" << with_dut1 << " cases): zenith "
              << worst_ut1_zenith << " deg, azimuth " << worst_ut1_azimuth << " deg; moon zenith "
              << worst_moon_zenith << " deg, azimuth " << worst_moon_azimuth << " deg, distance "
              << worst_moon_distance << " km, phase fraction " << worst_moon_phase << "\n";
    RecordProperty("worst_sun_zenith_deg", sci(worst_sun_zenith));
    RecordProperty("worst_sun_azimuth_deg", sci(worst_sun_azimuth));
    RecordProperty("worst_sun_zenith_with_ut1_deg", sci(worst_ut1_zenith));
    RecordProperty("worst_sun_azimuth_with_ut1_deg", sci(worst_ut1_azimuth));
    RecordProperty("worst_moon_zenith_deg", sci(worst_moon_zenith));
    RecordProperty("worst_moon_azimuth_deg", sci(worst_moon_azimuth));
    RecordProperty("worst_moon_phase", sci(worst_moon_phase));
}

}  // namespace sun_oracle_test
}  // namespace glint::motion
