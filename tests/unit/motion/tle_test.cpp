// SPDX-License-Identifier: Apache-2.0
// Two-line element parsing: every field of a known element set, the exponent and sign
// formats, the two-digit year window, checksums, column and separator errors, line-number and
// satellite-number mismatches, and the file:line an error carries.
#include "glint/motion/tle.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace glint::motion {
namespace tle_test {

using ::testing::HasSubstr;

// Satellite 00005 of the 2006 verification set (SGP4-VER.TLE).
constexpr const char* kLine1 =
    "1 00005U 58002B   00179.78495062  .00000023  00000-0  28098-4 0  4753";
constexpr const char* kLine2 =
    "2 00005  34.2682 348.7242 1859667 331.7664  19.3264 10.82419157413667";

/// `line` with columns first..(first + text.size() - 1) replaced by `text` and the checksum
/// recomputed, so that the test reaches the field check rather than the checksum.
std::string patched(std::string line, int first_column, const std::string& text) {
    line.replace(static_cast<std::size_t>(first_column - 1), text.size(), text);
    line[68] = static_cast<char>('0' + tle_checksum(line));
    return line;
}

/// The message of the glint::Error that parsing throws ("" if none).
std::string parse_error(const std::string& line1, const std::string& line2,
                        const ErrorContext& where = {}) {
    try {
        Tle::parse(line1, line2, where);
    } catch (const Error& error) {
        EXPECT_EQ(error.category(), ErrorCategory::input);
        return error.what();
    }
    return "";
}

TEST(Tle, ParsesEveryField) {
    const Tle tle = Tle::parse(kLine1, kLine2);
    EXPECT_EQ(tle.satellite_number, 5);
    EXPECT_EQ(tle.classification, 'U');
    EXPECT_EQ(tle.international_designator, "58002B");
    EXPECT_EQ(tle.epoch_year, 2000);
    EXPECT_DOUBLE_EQ(tle.epoch_day, 179.78495062);
    EXPECT_DOUBLE_EQ(tle.mean_motion_dot_rev_day2, 0.00000023);
    EXPECT_DOUBLE_EQ(tle.mean_motion_ddot_rev_day3, 0.0);
    EXPECT_DOUBLE_EQ(tle.bstar_per_earth_radii, 0.28098e-4);
    EXPECT_EQ(tle.ephemeris_type, 0);
    EXPECT_EQ(tle.element_set_number, 475);
    EXPECT_DOUBLE_EQ(tle.inclination_deg, 34.2682);
    EXPECT_DOUBLE_EQ(tle.raan_deg, 348.7242);
    EXPECT_DOUBLE_EQ(tle.eccentricity, 0.1859667);
    EXPECT_DOUBLE_EQ(tle.arg_perigee_deg, 331.7664);
    EXPECT_DOUBLE_EQ(tle.mean_anomaly_deg, 19.3264);
    EXPECT_DOUBLE_EQ(tle.mean_motion_rev_day, 10.82419157);
    EXPECT_EQ(tle.revolution_number, 41366);
}

TEST(Tle, EpochAsDateTimeAndJulianDate) {
    const Tle tle = Tle::parse(kLine1, kLine2);
    // Day 179.78495062 of 2000 (a leap year) is 27 June, 18:50:19.733568.
    EXPECT_EQ(format_iso8601_utc(tle.epoch(), 6), "2000-06-27T18:50:19.733568Z");
    EXPECT_NEAR(tle.epoch_jd(), 2451723.28495062, 1e-8);
    EXPECT_NEAR(tle.epoch_days_since_1950(), 2451723.28495062 - 2433281.5, 1e-9);
    EXPECT_NEAR(julian_date_utc(tle.epoch()), tle.epoch_jd(), 1e-8);
}

TEST(Tle, TwoDigitYearWindow) {
    EXPECT_EQ(Tle::parse(patched(kLine1, 19, "57"), kLine2).epoch_year, 1957);
    EXPECT_EQ(Tle::parse(patched(kLine1, 19, "99"), kLine2).epoch_year, 1999);
    EXPECT_EQ(Tle::parse(patched(kLine1, 19, "00"), kLine2).epoch_year, 2000);
    EXPECT_EQ(Tle::parse(patched(kLine1, 19, "56"), kLine2).epoch_year, 2056);
    const Tle tle = Tle::parse(patched(kLine1, 19, "57001.50000000"), kLine2);
    EXPECT_EQ(format_iso8601_utc(tle.epoch(), 0), "1957-01-01T12:00:00Z");
}

TEST(Tle, ExponentAndSignFormats) {
    // " 12345-4" is 0.12345e-4; negative mantissas and '+' exponents as in SGP4-VER.TLE.
    Tle tle = Tle::parse(patched(kLine1, 45, " 12345-4"), kLine2);
    EXPECT_DOUBLE_EQ(tle.mean_motion_ddot_rev_day3, 0.12345e-4);
    tle = Tle::parse(patched(kLine1, 45, "-30915-6"), kLine2);
    EXPECT_DOUBLE_EQ(tle.mean_motion_ddot_rev_day3, -0.30915e-6);
    tle = Tle::parse(patched(kLine1, 54, "-13525-3"), kLine2);
    EXPECT_DOUBLE_EQ(tle.bstar_per_earth_radii, -0.13525e-3);
    tle = Tle::parse(patched(kLine1, 54, " 00000+0"), kLine2);
    EXPECT_DOUBLE_EQ(tle.bstar_per_earth_radii, 0.0);
    tle = Tle::parse(patched(kLine1, 54, " 14311-1"), kLine2);
    EXPECT_DOUBLE_EQ(tle.bstar_per_earth_radii, 0.14311e-1);
    tle = Tle::parse(patched(kLine1, 54, " 50000+1"), kLine2);
    EXPECT_DOUBLE_EQ(tle.bstar_per_earth_radii, 5.0);
    tle = Tle::parse(patched(kLine1, 34, "-.00000084"), kLine2);
    EXPECT_DOUBLE_EQ(tle.mean_motion_dot_rev_day2, -0.00000084);
}

TEST(Tle, BlankOptionalFieldsAndOldElementSets) {
    // The original Spacetrack Report #3 test case: no designator, ephemeris type blank.
    const Tle tle =
        Tle::parse("1 88888U          80275.98708465  .00073094  13844-3  66816-4 0    87",
                   "2 88888  72.8435 115.9689 0086731  52.6988 110.5714 16.05824518  1058");
    EXPECT_EQ(tle.satellite_number, 88888);
    EXPECT_EQ(tle.international_designator, "");
    EXPECT_EQ(tle.epoch_year, 1980);
    EXPECT_EQ(tle.element_set_number, 8);
    EXPECT_EQ(tle.revolution_number, 105);
    const Tle blank_type =
        Tle::parse("1 11801U          80230.29629788  .01431103  00000-0  14311-1      13",
                   "2 11801  46.7916 230.4354 7318036  47.4722  10.4117  2.28537848    13");
    EXPECT_EQ(blank_type.ephemeris_type, 0);
    EXPECT_EQ(blank_type.element_set_number, 1);
}

TEST(Tle, AcceptsCrLfAndTrailingBlanksAndAlpha5) {
    EXPECT_NO_THROW(Tle::parse(std::string(kLine1) + "\r\n", std::string(kLine2) + "   "));
    const Tle tle = Tle::parse(patched(kLine1, 3, "A0005"), patched(kLine2, 3, "A0005"));
    EXPECT_EQ(tle.satellite_number, 100005);
    EXPECT_EQ(Tle::parse(patched(kLine1, 3, "Z9999"), patched(kLine2, 3, "Z9999")).satellite_number,
              339999);
}

TEST(Tle, ChecksumMismatchNamesColumn69) {
    std::string bad = kLine1;
    bad[68] = '4';
    EXPECT_THAT(parse_error(bad, kLine2),
                HasSubstr("TLE line 1 column 69 (checksum): checksum is 4, computed 3"));
    std::string bad2 = kLine2;
    bad2[68] = '0';
    EXPECT_THAT(parse_error(kLine1, bad2), HasSubstr("TLE line 2 column 69 (checksum)"));
}

TEST(Tle, ErrorsCarryFileAndLine) {
    std::string bad2 = kLine2;
    bad2[68] = '0';
    try {
        Tle::parse(kLine1, bad2, ErrorContext{"sats.tle", 10, ""});
        FAIL() << "no error";
    } catch (const Error& error) {
        EXPECT_EQ(error.context().file, "sats.tle");
        EXPECT_EQ(error.context().line, 11);
        EXPECT_THAT(error.what(), HasSubstr("sats.tle:11: TLE line 2 column 69"));
    }
    std::string bad1 = kLine1;
    bad1[68] = '0';
    EXPECT_THAT(parse_error(bad1, kLine2, ErrorContext{"sats.tle", 10, ""}),
                HasSubstr("sats.tle:10: TLE line 1"));
    EXPECT_THAT(parse_error(bad1, kLine2, ErrorContext{"platform.xml", 0, "<tle>"}),
                HasSubstr("platform.xml: <tle>: TLE line 1 column 69 (checksum)"));
}

TEST(Tle, ColumnErrorsNameTheField) {
    EXPECT_THAT(parse_error(kLine1, patched(kLine2, 27, "18x9667")),
                HasSubstr("TLE line 2 columns 27-33 (eccentricity): expected 7 digits"));
    EXPECT_THAT(parse_error(kLine1, patched(kLine2, 9, " 34.26a2")),
                HasSubstr("TLE line 2 columns 9-16 (inclination): expected a decimal number"));
    EXPECT_THAT(parse_error(patched(kLine1, 54, " 28098x4"), kLine2),
                HasSubstr("TLE line 1 columns 54-61 (B* drag term)"));
    EXPECT_THAT(parse_error(kLine1, patched(kLine2, 9, "190.0000")),
                HasSubstr("(inclination): 190 is out of range, expected 0 to 180"));
    EXPECT_THAT(parse_error(kLine1, patched(kLine2, 53, " 0.00000000")),
                HasSubstr("(mean motion): must be positive"));
    // A shifted field leaves a digit in a separator column.
    EXPECT_THAT(parse_error(kLine1, patched(kLine2, 17, "1348.724")),
                HasSubstr("TLE line 2 column 17 (separator): expected a blank"));
    EXPECT_THAT(parse_error(patched(kLine1, 8, "X"), kLine2),
                HasSubstr("column 8 (classification)"));
}

TEST(Tle, BadEpochIsRejected) {
    EXPECT_THAT(parse_error(patched(kLine1, 19, "00000.50000000"), kLine2),
                HasSubstr("columns 21-32 (epoch day): 0.5 is out of range"));
    // Day 366 exists in 2004, not in 2005.
    EXPECT_NO_THROW(Tle::parse(patched(kLine1, 19, "04366.50000000"), kLine2));
    EXPECT_THAT(parse_error(patched(kLine1, 19, "05366.50000000"), kLine2),
                HasSubstr("(epoch day): 366.5 is out of range"));
    EXPECT_THAT(parse_error(patched(kLine1, 19, "0517a.78495062"), kLine2),
                HasSubstr("(epoch day): expected a decimal number"));
    EXPECT_THAT(parse_error(patched(kLine1, 19, " 0"), kLine2), HasSubstr("(epoch year)"));
}

TEST(Tle, LineNumberAndSatelliteMismatches) {
    EXPECT_THAT(parse_error(kLine2, kLine1),
                HasSubstr("TLE line 1 column 1 (line number): expected '1', found \"2\""));
    EXPECT_THAT(parse_error(kLine1, kLine1), HasSubstr("TLE line 2 column 1 (line number)"));
    EXPECT_THAT(parse_error(kLine1, patched(kLine2, 3, "00006")),
                HasSubstr("TLE line 2 columns 3-7 (satellite number): 6 differs from 5 on line 1"));
    EXPECT_THAT(parse_error(kLine1, ""), HasSubstr("found an empty line"));
}

TEST(Tle, LineLengthIsChecked) {
    EXPECT_THAT(parse_error(std::string(kLine1).substr(0, 60), kLine2),
                HasSubstr("TLE line 1: has 60 characters, expected 69"));
    EXPECT_THAT(parse_error(kLine1, std::string(kLine2) + "  0.0 4320.0 360.0"),
                HasSubstr("TLE line 2: has 87 characters, expected 69"));
}

TEST(Tle, ChecksumCountsDigitsAndMinusSigns) {
    EXPECT_EQ(tle_checksum(kLine1), 3);
    EXPECT_EQ(tle_checksum(kLine2), 7);
    EXPECT_EQ(tle_checksum("1 -- 9"), (1 + 1 + 1 + 9) % 10);
}

}  // namespace tle_test
}  // namespace glint::motion
