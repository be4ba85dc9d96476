// SPDX-License-Identifier: Apache-2.0
// Tests of ISO-8601 parsing and formatting, offsets, fractional seconds, leap years,
// second arithmetic, Julian dates and the civil-date conversions of glint/core/datetime.h.
#include "glint/core/datetime.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "glint/core/error.h"

namespace glint {
namespace datetime_test {

TEST(DateTime, EpochAndSimpleUtc) {
    const DateTime epoch = parse_iso8601("1970-01-01T00:00:00Z");
    EXPECT_EQ(epoch.unix_s, 0);
    EXPECT_EQ(epoch.fraction_s, 0.0);
    // date -u -d 2009-07-27T19:29:32Z +%s  → 1248722972
    const DateTime t = parse_iso8601("2009-07-27T19:29:32Z");
    EXPECT_EQ(t.unix_s, 1248722972);
    EXPECT_EQ(t.utc_offset_min, 0);
}

TEST(DateTime, OffsetsDenoteTheSameInstant) {
    const DateTime utc = parse_iso8601("2009-07-27T19:29:32Z");
    const DateTime pdt = parse_iso8601("2009-07-27T11:29:32.0000-08:00");
    EXPECT_EQ(pdt, utc);
    EXPECT_EQ(pdt.utc_offset_min, -480);
    EXPECT_EQ(parse_iso8601("2009-07-27T11:29:32-0800"), utc);
    EXPECT_EQ(parse_iso8601("2009-07-27T11:29:32-08"), utc);
    EXPECT_EQ(parse_iso8601("2009-07-28T01:00:32+05:31"), utc);
    EXPECT_EQ(parse_iso8601("2009-07-28T01:00:32+05:31").utc_offset_min, 331);
    EXPECT_EQ(parse_iso8601("2009-07-27 19:29:32"), utc);  // space, no zone = UTC
    EXPECT_EQ(parse_iso8601("2009-07-27t19:29:32z"), utc);
    EXPECT_EQ(parse_iso8601("  2009-07-27T19:29:32Z\n"), utc);
    EXPECT_EQ(parse_iso8601("2009-07-27T19:29Z").unix_s, utc.unix_s - 32);
    EXPECT_EQ(format_iso8601_utc(pdt), "2009-07-27T19:29:32.000000Z");
    EXPECT_EQ(format_iso8601_local(pdt), "2009-07-27T11:29:32.000000-08:00");
    EXPECT_EQ(format_iso8601_local(parse_iso8601("2009-07-28T01:00:32+05:31"), 0),
              "2009-07-28T01:00:32+05:31");
}

TEST(DateTime, OffsetCrossesDayAndYear) {
    EXPECT_EQ(format_iso8601_utc(parse_iso8601("2000-01-01T01:00:00+02:00"), 0),
              "1999-12-31T23:00:00Z");
    EXPECT_EQ(format_iso8601_utc(parse_iso8601("1999-12-31T23:30:00-01:00"), 0),
              "2000-01-01T00:30:00Z");
}

TEST(DateTime, FractionalSeconds) {
    const DateTime t = parse_iso8601("2009-07-27T19:29:32.25Z");
    EXPECT_EQ(t.unix_s, 1248722972);
    EXPECT_EQ(t.fraction_s, 0.25);
    EXPECT_EQ(parse_iso8601("2009-07-27T19:29:32,5").fraction_s, 0.5);
    EXPECT_NEAR(parse_iso8601("2009-07-27T19:29:32.123456789012345678Z").fraction_s,
                0.123456789012345678, 1e-16);
    const DateTime nines = parse_iso8601("2009-07-27T19:29:32.99999999999999999999Z");
    EXPECT_LT(nines.fraction_s, 1.0);
    EXPECT_EQ(nines.unix_s, 1248722972);
    EXPECT_EQ(format_iso8601_utc(nines, 3), "2009-07-27T19:29:33.000Z");  // rounds, carries
    EXPECT_EQ(format_iso8601_utc(t, 3), "2009-07-27T19:29:32.250Z");
    EXPECT_EQ(format_iso8601_utc(t, 0), "2009-07-27T19:29:32Z");
    EXPECT_EQ(format_iso8601_utc(t, 9), "2009-07-27T19:29:32.250000000Z");
}

TEST(DateTime, LeapYears) {
    EXPECT_NO_THROW(parse_iso8601("2024-02-29T00:00:00Z"));
    EXPECT_NO_THROW(parse_iso8601("2000-02-29"));
    EXPECT_THROW(parse_iso8601("2023-02-29"), Error);
    EXPECT_THROW(parse_iso8601("1900-02-29"), Error);
    EXPECT_EQ(seconds_between(parse_iso8601("2024-02-28"), parse_iso8601("2024-03-01")),
              2.0 * 86400.0);
    EXPECT_EQ(seconds_between(parse_iso8601("2023-02-28"), parse_iso8601("2023-03-01")), 86400.0);
    EXPECT_TRUE(is_leap_year(2000));
    EXPECT_FALSE(is_leap_year(2100));
    EXPECT_EQ(days_in_month(2024, 2), 29);
    EXPECT_EQ(days_in_month(2023, 2), 28);
}

TEST(DateTime, DateOnlyIsMidnightUtc) {
    const DateTime d = parse_iso8601("2009-07-27");
    EXPECT_EQ(format_iso8601_utc(d), "2009-07-27T00:00:00.000000Z");
}

TEST(DateTime, JulianDate) {
    EXPECT_EQ(julian_date_utc(parse_iso8601("2000-01-01T12:00:00Z")), 2451545.0);
    EXPECT_EQ(julian_date_utc(parse_iso8601("1970-01-01T00:00:00Z")), 2440587.5);
    // 1858-11-17T00:00Z is MJD 0 = JD 2400000.5 (before the Unix epoch: floor division).
    EXPECT_EQ(julian_date_utc(parse_iso8601("1858-11-17")), 2400000.5);
    EXPECT_NEAR(julian_date_utc(parse_iso8601("2000-01-01T18:00:00.5Z")),
                2451545.25 + 0.5 / 86400.0, 1e-9);
}

TEST(DateTime, CivilRoundTripOverAllYears) {
    // days_from_civil and civil_from_days are inverse for every day of 0001-9999 (sampled
    // every 7 days, which visits every day-of-month and month).
    const std::int64_t first = days_from_civil(1, 1, 1);
    const std::int64_t last = days_from_civil(9999, 12, 31);
    EXPECT_EQ(days_from_civil(1970, 1, 1), 0);
    EXPECT_EQ(days_from_civil(2000, 3, 1), 11017);
    for (std::int64_t day = first; day <= last; day += 7) {
        const CivilTime c = to_civil_utc(DateTime{day * 86400, 0.0, 0});
        ASSERT_EQ(days_from_civil(c.year, c.month, c.day), day);
        ASSERT_GE(c.day, 1);
        ASSERT_LE(c.day, days_in_month(c.year, c.month));
    }
}

TEST(DateTime, FormatParseRoundTrip) {
    for (const char* text : {"0001-01-01T00:00:00.000000Z", "1969-12-31T23:59:59.500000Z",
                             "2009-07-27T19:29:32.123456Z", "2024-02-29T12:34:56.000001Z",
                             "9999-12-31T23:59:59.999999Z"}) {
        EXPECT_EQ(format_iso8601_utc(parse_iso8601(text)), text);
    }
    const DateTime before_epoch = parse_iso8601("1969-12-31T23:59:59.5Z");
    EXPECT_EQ(before_epoch.unix_s, -1);
    EXPECT_EQ(before_epoch.fraction_s, 0.5);
}

TEST(DateTime, MakeUtc) {
    CivilTime c;
    c.year = 2009;
    c.month = 7;
    c.day = 27;
    c.hour = 19;
    c.minute = 29;
    c.second = 32;
    EXPECT_EQ(make_datetime_utc(c), parse_iso8601("2009-07-27T19:29:32Z"));
    c.month = 13;
    EXPECT_THROW(make_datetime_utc(c), Error);
}

TEST(DateTime, Arithmetic) {
    const DateTime a = parse_iso8601("2009-07-27T19:29:32.75Z");
    const DateTime b = add_seconds(a, 0.5);
    EXPECT_EQ(format_iso8601_utc(b, 2), "2009-07-27T19:29:33.25Z");
    EXPECT_EQ(seconds_between(a, b), 0.5);
    EXPECT_EQ(seconds_between(b, a), -0.5);
    const DateTime c = add_seconds(a, -86400.25);
    EXPECT_EQ(format_iso8601_utc(c, 2), "2009-07-26T19:29:32.50Z");
    EXPECT_EQ(add_seconds(a, -1e-20), a);  // rounding of a tiny negative step
    EXPECT_LT(a, b);
    EXPECT_GT(a, c);
    const DateTime local = parse_iso8601("2009-07-27T11:29:32-08:00");
    EXPECT_EQ(add_seconds(local, 60.0).utc_offset_min, -480);
    EXPECT_THROW(add_seconds(a, NAN), Error);
    EXPECT_THROW(add_seconds(a, 1e300), Error);
    EXPECT_THROW(format_iso8601_utc(a, 10), Error);
    EXPECT_THROW(format_iso8601_utc(add_seconds(parse_iso8601("9999-12-31T23:59:59Z"), 1.0)),
                 Error);
}

struct BadCase {
    const char* text;
    const char* fragment;  // expected in the message
};

TEST(DateTime, MalformedInputsAreRejectedWithAMessage) {
    const std::vector<BadCase> cases = {
        {"", "it is empty"},
        {"   ", "it is empty"},
        {"2009", "'-' after the year"},
        {"09-07-27", "4-digit year"},
        {"2009-7-27", "2-digit month"},
        {"2009/07/27", "'-' after the year"},
        {"2009-07-2", "2-digit day"},
        {"2009-13-01", "month 13 is out of range, expected 01 to 12"},
        {"2009-00-01", "month 0 is out of range"},
        {"2009-04-31", "day 31 is out of range for 2009-04, expected 01 to 30"},
        {"2009-07-00", "day 0 is out of range"},
        {"0000-01-01", "year 0 is out of range, expected 0001 to 9999"},
        {"2009-07-27X19:29:32", "'T' or a space"},
        {"2009-07-27Z", "'T' or a space"},
        {"2009-07-27T", "2-digit hour"},
        {"2009-07-27T24:00:00", "hour 24 is out of range, expected 00 to 23"},
        {"2009-07-27T19:60:00", "minute 60 is out of range"},
        {"2009-07-27T19:29:61", "second 61 is out of range"},
        {"2009-07-27T23:59:60Z", "leap second"},
        {"2009-07-27T19", "':' after the hour"},
        {"2009-07-27T19:2", "2-digit minute"},
        {"2009-07-27T19:29:3", "2-digit second"},
        {"2009-07-27T19:29:32.", "digits of the fraction"},
        {"2009-07-27T19:29:32.5.5", "UTC offset"},
        {"2009-07-27T19:29:32 Z", "UTC offset"},
        {"2009-07-27T19:29:32+8", "2-digit offset hour"},
        {"2009-07-27T19:29:32+08:0", "2-digit offset minute"},
        {"2009-07-27T19:29:32+0800x", "the end of the text"},
        {"2009-07-27T19:29:32+24:00", "UTC offset hour 24"},
        {"2009-07-27T19:29:32+08:60", "UTC offset minute 60"},
        {"2009-07-27T19:29:32Zjunk", "the end of the text"},
        {"2009-07-27T19:29:32-08:00:00", "the end of the text"},
        {"2009-07-27T1a:29:32", "2-digit hour"},
    };
    for (const BadCase& c : cases) {
        try {
            parse_iso8601(c.text, ErrorContext{"capture.tasks", 7, "<starttime>"});
            ADD_FAILURE() << "'" << c.text << "' was accepted";
        } catch (const Error& e) {
            const std::string what = e.what();
            EXPECT_EQ(e.category(), ErrorCategory::input) << what;
            EXPECT_NE(what.find(c.fragment), std::string::npos) << "'" << c.text << "': " << what;
            EXPECT_NE(what.find("'" + std::string(c.text) + "'"), std::string::npos) << what;
            EXPECT_EQ(what.rfind("capture.tasks:7: <starttime>: invalid date-time", 0), 0u) << what;
        }
    }
}

}  // namespace datetime_test
}  // namespace glint
