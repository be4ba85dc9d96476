// SPDX-License-Identifier: Apache-2.0
// Strict parsing of NORAD two-line element sets: every field is read from its fixed columns,
// separators and checksums are checked, and each failure names the line, columns and field.
#include "glint/motion/tle.h"
#include "glint/core/text.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string>

namespace glint::motion {

namespace {

constexpr std::size_t kLineLength = 69;
constexpr double kJulianDateOfUnixEpoch = 2440587.5;
/// days_from_civil(1949, 12, 31): the origin of the deep-space time argument.
constexpr std::int64_t kDays1950 = days_from_civil(1949, 12, 31);

bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

std::string_view trim(std::string_view text) noexcept {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    return text;
}

/// One TLE line being read, with what an error message needs to say where it is.
class LineReader {
public:
    LineReader(std::string_view text, int number, const ErrorContext& where)
        : m_text(text), m_number(number), m_where(where) {
        if (m_where.line > 0) m_where.line += number - 1;
    }

    /// The characters of columns first..last (1-based, inclusive).
    std::string_view columns(int first, int last) const {
        return m_text.substr(static_cast<std::size_t>(first - 1),
                             static_cast<std::size_t>(last - first + 1));
    }
    char column(int col) const { return m_text[static_cast<std::size_t>(col - 1)]; }

    [[noreturn]] void fail(int first, int last, std::string_view field,
                           const std::string& message) const {
        ErrorContext context = m_where;
        std::string element = "TLE line " + std::to_string(m_number);
        if (first > 0) {
            element += first == last
                           ? " column " + std::to_string(first)
                           : " columns " + std::to_string(first) + "-" + std::to_string(last);
        }
        if (!field.empty()) element += " (" + std::string(field) + ")";
        context.element = m_where.element.empty() ? element : m_where.element + ": " + element;
        throw input_error(message, context);
    }

    /// Fails unless each listed column is blank.
    void expect_blanks(std::initializer_list<int> cols) const {
        for (const int col : cols) {
            if (column(col) != ' ') {
                fail(col, col, "separator",
                     "expected a blank, found " + quote(std::string(1, column(col))));
            }
        }
    }

    /// An unsigned integer field; blank reads as 0 when `blank_ok`.
    int integer(int first, int last, std::string_view field, bool blank_ok) const {
        const std::string_view text = trim(columns(first, last));
        if (text.empty()) {
            if (blank_ok) return 0;
            fail(first, last, field, "is blank, expected digits");
        }
        int value = 0;
        for (const char c : text) {
            if (!is_digit(c)) {
                fail(first, last, field, "expected digits, found " + quote(columns(first, last)));
            }
            value = value * 10 + (c - '0');
        }
        return value;
    }

    /// A decimal number: optional sign, digits with at most one point ("-.00000084",
    /// "34.2682", "10.82419157").
    double decimal(int first, int last, std::string_view field) const {
        std::string_view text = trim(columns(first, last));
        const std::string_view raw = columns(first, last);
        bool negative = false;
        if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
            negative = text.front() == '-';
            text.remove_prefix(1);
        }
        int digits = 0;
        int points = 0;
        for (const char c : text) {
            if (is_digit(c)) {
                ++digits;
            } else if (c == '.') {
                ++points;
            } else {
                digits = -1;
                break;
            }
        }
        double value = 0.0;
        const char* end = text.data() + text.size();
        if (digits <= 0 || points > 1 || std::from_chars(text.data(), end, value).ptr != end) {
            fail(first, last, field, "expected a decimal number, found " + quote(raw));
        }
        return negative ? -value : value;
    }

    /// The "assumed decimal point" exponent format of columns 45-52 and 54-61 of line 1:
    /// sign or blank, five digits, exponent sign, one digit; " 12345-4" is 0.12345e-4.
    /// An all-blank field reads as 0.
    double exponent_field(int first, std::string_view field) const {
        const int last = first + 7;
        const std::string_view text = columns(first, last);
        if (trim(text).empty()) return 0.0;
        const char sign = text[0];
        const char exponent_sign = text[6];
        bool ok = (sign == ' ' || sign == '+' || sign == '-') &&
                  (exponent_sign == '+' || exponent_sign == '-' || exponent_sign == ' ') &&
                  is_digit(text[7]);
        double mantissa = 0.0;
        for (std::size_t i = 1; ok && i <= 5; ++i) {
            ok = is_digit(text[i]);
            mantissa = mantissa * 10.0 + (text[i] - '0');
        }
        if (!ok) {
            fail(first, last, field,
                 "expected sign, 5 digits, exponent sign and digit (\" 12345-4\"), found " +
                     quote(text));
        }
        const int exponent = (exponent_sign == '-' ? -1 : 1) * (text[7] - '0');
        const double value = mantissa * 1e-5 * std::pow(10.0, exponent);
        return sign == '-' ? -value : value;
    }

    /// A satellite number: five digits (leading blanks allowed) or Alpha-5 (a letter other
    /// than I and O for the ten-thousands, A = 10).
    int satellite_number() const {
        const std::string_view text = columns(3, 7);
        const char first = text[0];
        if (first >= 'A' && first <= 'Z' && first != 'I' && first != 'O') {
            int value = 10 + (first - 'A');
            if (first > 'I') --value;
            if (first > 'O') --value;
            for (std::size_t i = 1; i < text.size(); ++i) {
                if (!is_digit(text[i])) {
                    fail(3, 7, "satellite number",
                         "expected 5 digits or Alpha-5, found " + quote(text));
                }
                value = value * 10 + (text[i] - '0');
            }
            return value;
        }
        return integer(3, 7, "satellite number", false);
    }

    /// Checks the checksum digit in column 69.
    void check_checksum() const {
        const char digit = column(69);
        if (!is_digit(digit)) {
            fail(69, 69, "checksum", "expected a digit, found " + quote(std::string(1, digit)));
        }
        const int expected = tle_checksum(m_text);
        if (digit - '0' != expected) {
            fail(69, 69, "checksum",
                 "checksum is " + std::string(1, digit) + ", computed " + std::to_string(expected) +
                     " from columns 1-68");
        }
    }

    /// Fails unless `value` is within [low, high] (or [low, high) when `open_high`).
    void check_range(double value, double low, double high, bool open_high, int first, int last,
                     std::string_view field) const {
        const bool in = value >= low && (open_high ? value < high : value <= high);
        if (!in) {
            char buffer[96];
            std::snprintf(buffer, sizeof buffer, "%.10g is out of range, expected %g to %g%s",
                          value, low, high, open_high ? " (exclusive)" : "");
            fail(first, last, field, buffer);
        }
    }

private:
    std::string_view m_text;
    int m_number;
    ErrorContext m_where;
};

/// `line` without a trailing CR/LF and blanks, checked to be 69 characters starting with
/// the line number.
std::string_view checked_line(std::string_view line, int number, const ErrorContext& where) {
    while (!line.empty() && (line.back() == '\r' || line.back() == '\n' || line.back() == ' ')) {
        line.remove_suffix(1);
    }
    const LineReader reader(line, number, where);
    if (line.empty() || line.front() != static_cast<char>('0' + number)) {
        reader.fail(1, 1, "line number",
                    "expected '" + std::to_string(number) + "', found " +
                        (line.empty() ? std::string("an empty line") : quote(line.substr(0, 1))));
    }
    if (line.size() != kLineLength) {
        reader.fail(0, 0, "", "has " + std::to_string(line.size()) + " characters, expected 69");
    }
    return line;
}

}  // namespace

int tle_checksum(std::string_view line) noexcept {
    int sum = 0;
    const std::size_t n = line.size() < 68 ? line.size() : 68;
    for (std::size_t i = 0; i < n; ++i) {
        if (is_digit(line[i])) sum += line[i] - '0';
        if (line[i] == '-') sum += 1;
    }
    return sum % 10;
}

Tle Tle::parse(std::string_view line1, std::string_view line2, ErrorContext where) {
    const LineReader l1(checked_line(line1, 1, where), 1, where);
    const LineReader l2(checked_line(line2, 2, where), 2, where);
    l1.check_checksum();
    l2.check_checksum();
    l1.expect_blanks({2, 9, 18, 33, 44, 53, 62, 64});
    l2.expect_blanks({2, 8, 17, 26, 34, 43, 52});

    Tle tle;
    tle.satellite_number = l1.satellite_number();
    const char classification = l1.column(8);
    if (classification != ' ' && classification != 'U' && classification != 'C' &&
        classification != 'S') {
        l1.fail(8, 8, "classification",
                "expected U, C, S or blank, found " + quote(std::string(1, classification)));
    }
    tle.classification = classification == ' ' ? 'U' : classification;
    tle.international_designator = std::string(trim(l1.columns(10, 17)));

    const int year2 = l1.integer(19, 20, "epoch year", false);
    if (!is_digit(l1.column(19)) || !is_digit(l1.column(20))) {
        l1.fail(19, 20, "epoch year", "expected two digits, found " + quote(l1.columns(19, 20)));
    }
    tle.epoch_year = year2 >= 57 ? 1900 + year2 : 2000 + year2;
    tle.epoch_day = l1.decimal(21, 32, "epoch day");
    const int days_in_year = is_leap_year(tle.epoch_year) ? 366 : 365;
    l1.check_range(tle.epoch_day, 1.0, days_in_year + 1.0, true, 21, 32, "epoch day");

    tle.mean_motion_dot_rev_day2 = l1.decimal(34, 43, "first derivative of mean motion");
    tle.mean_motion_ddot_rev_day3 = l1.exponent_field(45, "second derivative of mean motion");
    tle.bstar_per_earth_radii = l1.exponent_field(54, "B* drag term");
    tle.ephemeris_type = l1.integer(63, 63, "ephemeris type", true);
    tle.element_set_number = l1.integer(65, 68, "element set number", true);

    const int satellite2 = l2.satellite_number();
    if (satellite2 != tle.satellite_number) {
        l2.fail(3, 7, "satellite number",
                std::to_string(satellite2) + " differs from " +
                    std::to_string(tle.satellite_number) + " on line 1");
    }
    tle.inclination_deg = l2.decimal(9, 16, "inclination");
    l2.check_range(tle.inclination_deg, 0.0, 180.0, false, 9, 16, "inclination");
    tle.raan_deg = l2.decimal(18, 25, "right ascension of the ascending node");
    l2.check_range(tle.raan_deg, 0.0, 360.0, false, 18, 25,
                   "right ascension of the ascending node");

    // Eccentricity: seven digits after an implied "0."; blanks read as zeros.
    double eccentricity = 0.0;
    const std::string_view ecc_text = l2.columns(27, 33);
    for (const char c : ecc_text) {
        if (!is_digit(c) && c != ' ') {
            l2.fail(27, 33, "eccentricity",
                    "expected 7 digits (leading \"0.\" implied), found " + quote(ecc_text));
        }
        eccentricity = eccentricity * 10.0 + (c == ' ' ? 0 : c - '0');
    }
    tle.eccentricity = eccentricity * 1e-7;

    tle.arg_perigee_deg = l2.decimal(35, 42, "argument of perigee");
    l2.check_range(tle.arg_perigee_deg, 0.0, 360.0, false, 35, 42, "argument of perigee");
    tle.mean_anomaly_deg = l2.decimal(44, 51, "mean anomaly");
    l2.check_range(tle.mean_anomaly_deg, 0.0, 360.0, false, 44, 51, "mean anomaly");
    tle.mean_motion_rev_day = l2.decimal(53, 63, "mean motion");
    if (!(tle.mean_motion_rev_day > 0.0)) {
        l2.fail(53, 63, "mean motion", "must be positive, found " + quote(l2.columns(53, 63)));
    }
    tle.revolution_number = l2.integer(64, 68, "revolution number", true);
    return tle;
}

DateTime Tle::epoch() const noexcept {
    const double seconds = (epoch_day - 1.0) * 86400.0;
    double whole = std::floor(seconds);
    double fraction = seconds - whole;
    if (fraction >= 1.0) {
        whole += 1.0;
        fraction = 0.0;
    }
    DateTime time;
    time.unix_s = days_from_civil(epoch_year, 1, 1) * 86400 + static_cast<std::int64_t>(whole);
    time.fraction_s = fraction;
    return time;
}

double Tle::epoch_jd() const noexcept {
    return kJulianDateOfUnixEpoch + static_cast<double>(days_from_civil(epoch_year, 1, 1)) +
           (epoch_day - 1.0);
}

double Tle::epoch_days_since_1950() const noexcept {
    return static_cast<double>(days_from_civil(epoch_year, 1, 1) - kDays1950) + (epoch_day - 1.0);
}

}  // namespace glint::motion
