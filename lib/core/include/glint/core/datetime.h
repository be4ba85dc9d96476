// SPDX-License-Identifier: Apache-2.0
// UTC date-times: parsing and formatting ISO-8601 text, arithmetic in seconds, Julian dates,
// and Howard Hinnant's days-from-civil conversions. Leap seconds are ignored throughout
// (every day has 86400 s, as in POSIX time); time scales other than UTC are not modelled.
#pragma once

#include <compare>
#include <cstdint>
#include <string>
#include <string_view>

#include "glint/core/error.h"

namespace glint {

/// An instant in UTC: whole seconds since 1970-01-01T00:00:00Z (POSIX time, no leap seconds)
/// plus a fraction of a second, and the UTC offset the instant was written with (kept only
/// for display). Comparisons (==, <, ...) compare the instant and ignore the offset, so
/// 11:29:32-08:00 == 19:29:32Z.
struct DateTime {
    std::int64_t unix_s = 0;  ///< whole seconds since the epoch (floor for times before it)
    double fraction_s = 0.0;  ///< fraction of a second in [0, 1)
    int utc_offset_min = 0;   ///< offset of the original text from UTC in minutes (east > 0)

    /// True when both denote the same instant (the display offsets may differ).
    friend bool operator==(const DateTime& a, const DateTime& b) noexcept {
        return a.unix_s == b.unix_s && a.fraction_s == b.fraction_s;
    }
    /// Orders by instant.
    friend std::partial_ordering operator<=>(const DateTime& a, const DateTime& b) noexcept {
        if (a.unix_s != b.unix_s) return a.unix_s <=> b.unix_s;
        return a.fraction_s <=> b.fraction_s;
    }
};

/// A broken-down calendar date and time of day (proleptic Gregorian calendar).
struct CivilTime {
    int year = 1970;          ///< e.g. 2009
    int month = 1;            ///< 1-12
    int day = 1;              ///< 1-31
    int hour = 0;             ///< 0-23
    int minute = 0;           ///< 0-59
    int second = 0;           ///< 0-59
    double fraction_s = 0.0;  ///< [0, 1)
};

/// Days from 1970-01-01 to the given proleptic Gregorian date (negative before it), by
/// H. Hinnant's days_from_civil algorithm. Valid for any year representable in an int;
/// month and day are not checked (make_datetime_utc checks them).
constexpr std::int64_t days_from_civil(int year, int month, int day) noexcept {
    const std::int64_t y = static_cast<std::int64_t>(year) - (month <= 2 ? 1 : 0);
    const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
    const std::int64_t year_of_era = y - era * 400;  // [0, 399]
    const std::int64_t day_of_year =
        (153 * (month > 2 ? month - 3 : month + 9) + 2) / 5 + day - 1;  // [0, 365]
    const std::int64_t day_of_era =
        year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;  // [0, 146096]
    return era * 146097 + day_of_era - 719468;
}

/// True for years divisible by 4, except centuries not divisible by 400.
constexpr bool is_leap_year(int year) noexcept {
    return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

/// The number of days in `month` (1-12) of `year`; 0 for a month out of range.
constexpr int days_in_month(int year, int month) noexcept {
    constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month < 1 || month > 12) return 0;
    return month == 2 && is_leap_year(year) ? 29 : kDays[month - 1];
}

/// The calendar date and time of day in UTC of `time` (H. Hinnant's civil_from_days).
CivilTime to_civil_utc(const DateTime& time) noexcept;

/// The instant of a UTC calendar date and time. Throws glint::Error (input, with `context`)
/// unless year is 1-9999, month 1-12, day within the month, hour 0-23, minute 0-59,
/// second 0-59 and fraction_s in [0, 1).
DateTime make_datetime_utc(const CivilTime& civil, const ErrorContext& context = {});

/// Parses an ISO-8601 date-time:
///   YYYY-MM-DD                       (midnight UTC)
///   YYYY-MM-DDThh:mm[:ss[.f...]][zone]  with 'T', 't' or one space between date and time,
///   fractional seconds of any length after '.' or ',', and zone one of 'Z', 'z', ±hh:mm,
///   ±hhmm, ±hh. No zone means UTC (not local time: results must not depend on the machine).
/// Surrounding blanks are ignored. Years are 0001-9999; second 60 (a leap second) is
/// rejected because leap seconds are not modelled. Throws glint::Error (input, with
/// `context`) quoting the text and saying what was expected where.
DateTime parse_iso8601(std::string_view text, const ErrorContext& context = {});

/// b − a in seconds.
double seconds_between(const DateTime& a, const DateTime& b) noexcept;

/// `time` moved by `seconds` (may be negative), keeping its display offset. Throws
/// glint::Error (input) unless |seconds| is finite and below 1e17.
DateTime add_seconds(DateTime time, double seconds);

/// "YYYY-MM-DDThh:mm:ss.ffffffZ" in UTC with `fraction_digits` (0-9; 0 omits the point)
/// digits, the fraction rounded to nearest (carrying into the seconds). Throws glint::Error
/// (input) for fraction_digits outside 0-9 or a date outside years 0001-9999.
std::string format_iso8601_utc(const DateTime& time, int fraction_digits = 6);

/// Like format_iso8601_utc, but in the time's own UTC offset with a "±hh:mm" suffix ("Z" for
/// offset 0), e.g. "2009-07-27T11:29:32.000000-08:00".
std::string format_iso8601_local(const DateTime& time, int fraction_digits = 6);

/// The Julian date of `time` treated as UTC (JD 2440587.5 at the Unix epoch; J2000.0,
/// 2000-01-01T12:00:00Z, is 2451545.0). About 40 µs resolution in a double near 2.45e6.
double julian_date_utc(const DateTime& time) noexcept;

}  // namespace glint
