// SPDX-License-Identifier: Apache-2.0
// NORAD two-line element sets (TLEs): the fixed-column text format of Spacetrack Report #3,
// parsed strictly (line numbers, column separators, digits, checksums, value ranges) into the
// mean elements that SGP4/SDP4 propagates. The epoch is UTC as far as glint is concerned
// (the TLE epoch is nominally UT1; the difference, < 0.9 s, is ignored like leap seconds).
//
// Columns (1-based) read from line 1:
// | columns | field                                   | unit / format                     |
// |---------|-----------------------------------------|-----------------------------------|
// | 1       | line number                             | '1'                               |
// | 3-7     | satellite number                        | 5 digits or Alpha-5 (A0000-Z9999) |
// | 8       | classification                          | U, C, S or blank                  |
// | 10-17   | international designator                | YYNNNPPP, may be blank            |
// | 19-20   | epoch year                              | 57-99 → 19xx, 00-56 → 20xx        |
// | 21-32   | epoch day of year with fraction         | DDD.DDDDDDDD, 1 = 1 January 0 h   |
// | 34-43   | first derivative of mean motion / 2     | rev/day², e.g. " .00000023"       |
// | 45-52   | second derivative of mean motion / 6    | rev/day³, " 12345-4" = 0.12345e-4 |
// | 54-61   | B* drag term                            | 1/earth radii, same format        |
// | 63      | ephemeris type                          | digit or blank (0)                |
// | 65-68   | element set number                      | up to 4 digits, may be blank      |
// | 69      | checksum                                | digits + 1 per '-', modulo 10     |
// Columns read from line 2:
// | columns | field                                   | unit / format                     |
// |---------|-----------------------------------------|-----------------------------------|
// | 1       | line number                             | '2'                               |
// | 3-7     | satellite number (must match line 1)    |                                   |
// | 9-16    | inclination                             | degrees, 0-180                    |
// | 18-25   | right ascension of the ascending node   | degrees, 0-360                    |
// | 27-33   | eccentricity                            | 7 digits, leading "0." implied    |
// | 35-42   | argument of perigee                     | degrees, 0-360                    |
// | 44-51   | mean anomaly                            | degrees, 0-360                    |
// | 53-63   | mean motion (Kozai)                     | revolutions per day, > 0          |
// | 64-68   | revolution number at epoch              | up to 5 digits, may be blank      |
// | 69      | checksum                                |                                   |
#pragma once

#include <string>
#include <string_view>

#include "glint/core/datetime.h"
#include "glint/core/error.h"

namespace glint::motion {

/// One two-line element set as written, plus its epoch. Angles stay in degrees and mean
/// motion in revolutions per day here; Sgp4 converts them.
struct Tle {
    int satellite_number = 0;                ///< NORAD catalogue number (Alpha-5 decoded)
    char classification = 'U';               ///< 'U', 'C', 'S' (blank reads as 'U')
    std::string international_designator;    ///< e.g. "58002B", blanks trimmed; may be empty
    int epoch_year = 2000;                   ///< four-digit year of the epoch
    double epoch_day = 1.0;                  ///< day of the year with fraction, 1.0 = 1 Jan 00:00
    double mean_motion_dot_rev_day2 = 0.0;   ///< first derivative of mean motion / 2
    double mean_motion_ddot_rev_day3 = 0.0;  ///< second derivative of mean motion / 6
    double bstar_per_earth_radii = 0.0;      ///< B* drag term (1/earth radii)
    int ephemeris_type = 0;                  ///< 0 for SGP4 element sets
    int element_set_number = 0;              ///< element set number
    double inclination_deg = 0.0;            ///< inclination
    double raan_deg = 0.0;                   ///< right ascension of the ascending node
    double eccentricity = 0.0;               ///< eccentricity, [0, 1)
    double arg_perigee_deg = 0.0;            ///< argument of perigee
    double mean_anomaly_deg = 0.0;           ///< mean anomaly
    double mean_motion_rev_day = 0.0;        ///< mean motion (Kozai), revolutions per day
    int revolution_number = 0;               ///< revolution number at epoch

    /// Parses a two-line element set. Each line must be exactly 69 characters (a trailing
    /// '\r' and trailing blanks are ignored). Throws glint::Error (input) naming the line,
    /// columns and field, e.g. "TLE line 2 column 69: checksum is 3, expected 4"; when `where`
    /// names a file, the error carries it and the line number (where.line is the line of
    /// TLE line 1 in that file, line 2 is reported at where.line + 1); where.element, if
    /// any, prefixes the column description.
    static Tle parse(std::string_view line1, std::string_view line2, ErrorContext where = {});

    /// The epoch as a UTC instant (UT1 taken as UTC).
    DateTime epoch() const noexcept;
    /// The epoch as a Julian date (UT1 ≈ UTC), e.g. 2451723.28495062 for 00179.78495062.
    double epoch_jd() const noexcept;
    /// The epoch in days since 1949-12-31 00:00 (JD 2433281.5), the time origin of the
    /// deep-space lunar-solar terms, computed without the rounding of a full Julian date.
    double epoch_days_since_1950() const noexcept;
};

/// The TLE checksum of `line` (69 or more characters): the sum of the digits of columns
/// 1-68 plus 1 for each '-', modulo 10.
int tle_checksum(std::string_view line) noexcept;

}  // namespace glint::motion
