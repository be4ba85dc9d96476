// SPDX-License-Identifier: Apache-2.0
// ISO-8601 parsing and formatting, second arithmetic and Julian dates for glint::DateTime.
#include "glint/core/datetime.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include "glint/core/text.h"

namespace glint {

namespace {

constexpr std::int64_t kSecondsPerDay = 86400;
constexpr double kJulianDateOfUnixEpoch = 2440587.5;

/// floor(a / b) for b > 0.
constexpr std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

std::string two_digits(int value) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%02d", value);
    return buffer;
}

/// Checks the fields of a calendar time; returns "" or what is wrong.
std::string civil_problem(const CivilTime& c) {
    if (c.year < 1 || c.year > 9999) {
        return "year " + std::to_string(c.year) + " is out of range, expected 0001 to 9999";
    }
    if (c.month < 1 || c.month > 12) {
        return "month " + std::to_string(c.month) + " is out of range, expected 01 to 12";
    }
    const int month_days = days_in_month(c.year, c.month);
    if (c.day < 1 || c.day > month_days) {
        return "day " + std::to_string(c.day) + " is out of range for " + std::to_string(c.year) +
               "-" + two_digits(c.month) + ", expected 01 to " + std::to_string(month_days);
    }
    if (c.hour < 0 || c.hour > 23) {
        return "hour " + std::to_string(c.hour) + " is out of range, expected 00 to 23";
    }
    if (c.minute < 0 || c.minute > 59) {
        return "minute " + std::to_string(c.minute) + " is out of range, expected 00 to 59";
    }
    if (c.second == 60) {
        return "second 60 (a leap second) is not supported, expected 00 to 59";
    }
    if (c.second < 0 || c.second > 59) {
        return "second " + std::to_string(c.second) + " is out of range, expected 00 to 59";
    }
    if (!(c.fraction_s >= 0.0 && c.fraction_s < 1.0)) {
        return "fraction of a second " + format_ten_digits(c.fraction_s) +
               " is out of range, expected [0, 1)";
    }
    return {};
}

DateTime datetime_from_valid_civil(const CivilTime& c, int utc_offset_min) noexcept {
    DateTime out;
    out.unix_s = days_from_civil(c.year, c.month, c.day) * kSecondsPerDay + c.hour * 3600 +
                 c.minute * 60 + c.second - static_cast<std::int64_t>(utc_offset_min) * 60;
    out.fraction_s = c.fraction_s;
    out.utc_offset_min = utc_offset_min;
    return out;
}

/// A cursor over the text being parsed that reports errors quoting the whole text.
class Iso8601Parser {
public:
    Iso8601Parser(std::string_view original, std::string_view trimmed, const ErrorContext& context)
        : m_original(original), m_text(trimmed), m_context(context) {}

    DateTime parse() {
        if (m_text.empty()) fail("it is empty, expected YYYY-MM-DD[Thh:mm[:ss[.fff]][zone]]");
        CivilTime civil;
        civil.year = digits(4, "year (YYYY)");
        expect('-', "after the year");
        civil.month = digits(2, "month (MM)");
        expect('-', "after the month");
        civil.day = digits(2, "day (DD)");
        int offset_min = 0;
        if (!at_end()) {
            const char separator = m_text[m_pos];
            if (separator != 'T' && separator != 't' && separator != ' ') {
                fail_here("'T' or a space between the date and the time");
            }
            ++m_pos;
            civil.hour = digits(2, "hour (hh)");
            expect(':', "after the hour");
            civil.minute = digits(2, "minute (mm)");
            if (accept(':')) {
                civil.second = digits(2, "second (ss)");
                if (accept('.') || accept(',')) civil.fraction_s = fraction();
            }
            offset_min = zone();
            if (!at_end()) fail_here("the end of the text");
        }
        const std::string problem = civil_problem(civil);
        if (!problem.empty()) fail(problem);
        return datetime_from_valid_civil(civil, offset_min);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw input_error("invalid date-time '" + std::string(m_original) + "': " + what,
                          m_context);
    }

    [[noreturn]] void fail_here(const std::string& expected) const {
        const std::string found =
            at_end() ? "the end of the text" : "'" + std::string(1, m_text[m_pos]) + "'";
        fail("found " + found + " at character " + std::to_string(m_pos + 1) + ", expected " +
             expected);
    }

    bool at_end() const noexcept { return m_pos >= m_text.size(); }

    static bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }

    bool accept(char c) noexcept {
        if (at_end() || m_text[m_pos] != c) return false;
        ++m_pos;
        return true;
    }

    void expect(char c, const char* where) {
        if (!accept(c)) fail_here(std::string("'") + c + "' " + where);
    }

    int digits(int count, const char* field) {
        int value = 0;
        for (int i = 0; i < count; ++i) {
            if (at_end() || !is_digit(m_text[m_pos])) {
                fail_here(std::to_string(count) + "-digit " + field);
            }
            value = value * 10 + (m_text[m_pos++] - '0');
        }
        return value;
    }

    double fraction() {
        const std::size_t start = m_pos;
        while (!at_end() && is_digit(m_text[m_pos])) ++m_pos;
        if (m_pos == start) fail_here("digits of the fraction of a second");
        const std::string number = "0." + std::string(m_text.substr(start, m_pos - start));
        double value = 0.0;
        std::from_chars(number.data(), number.data() + number.size(), value);
        // Many nines round to 1.0; keep the fraction below 1 (a truncation by < 1e-16 s).
        return value < 1.0 ? value : std::nextafter(1.0, 0.0);
    }

    /// The zone suffix as minutes east of UTC; none means UTC.
    int zone() {
        if (at_end()) return 0;
        if (accept('Z') || accept('z')) return 0;
        int sign = 0;
        if (accept('+')) {
            sign = 1;
        } else if (accept('-')) {
            sign = -1;
        } else {
            fail_here("a UTC offset ('Z', ±hh:mm, ±hhmm or ±hh) or the end of the text");
        }
        const int hours = digits(2, "offset hour (hh)");
        int minutes = 0;
        if (accept(':')) {
            minutes = digits(2, "offset minute (mm)");
        } else if (!at_end()) {
            minutes = digits(2, "offset minute (mm)");
        }
        if (hours > 23) {
            fail("UTC offset hour " + std::to_string(hours) +
                 " is out of range, expected 00 to 23");
        }
        if (minutes > 59) {
            fail("UTC offset minute " + std::to_string(minutes) +
                 " is out of range, expected 00 to 59");
        }
        return sign * (hours * 60 + minutes);
    }

    std::string_view m_original;
    std::string_view m_text;
    const ErrorContext& m_context;
    std::size_t m_pos = 0;
};

std::string format_with_offset(const DateTime& time, int fraction_digits, int offset_min) {
    if (fraction_digits < 0 || fraction_digits > 9) {
        throw input_error("fraction digits " + std::to_string(fraction_digits) +
                          " is out of range, expected 0 to 9");
    }
    std::int64_t scale = 1;
    for (int i = 0; i < fraction_digits; ++i) scale *= 10;
    DateTime shown = time;
    shown.unix_s += static_cast<std::int64_t>(offset_min) * 60;
    auto scaled = static_cast<std::int64_t>(std::llround(time.fraction_s * scale));
    if (scaled >= scale) {
        scaled -= scale;
        shown.unix_s += 1;
    }
    shown.fraction_s = 0.0;
    const CivilTime c = to_civil_utc(shown);
    if (c.year < 1 || c.year > 9999) {
        throw input_error("date-time in year " + std::to_string(c.year) +
                          " cannot be written as ISO-8601, expected years 0001 to 9999");
    }
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%04d-%02d-%02dT%02d:%02d:%02d", c.year, c.month, c.day,
                  c.hour, c.minute, c.second);
    std::string out = buffer;
    if (fraction_digits > 0) {
        std::snprintf(buffer, sizeof buffer, ".%0*lld", fraction_digits,
                      static_cast<long long>(scaled));
        out += buffer;
    }
    if (offset_min == 0) {
        out += 'Z';
    } else {
        const int magnitude = offset_min < 0 ? -offset_min : offset_min;
        out += offset_min < 0 ? '-' : '+';
        out += two_digits(magnitude / 60) + ":" + two_digits(magnitude % 60);
    }
    return out;
}

}  // namespace

CivilTime to_civil_utc(const DateTime& time) noexcept {
    const std::int64_t days = floor_div(time.unix_s, kSecondsPerDay);
    const std::int64_t second_of_day = time.unix_s - days * kSecondsPerDay;
    // H. Hinnant's civil_from_days.
    const std::int64_t z = days + 719468;
    const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
    const std::int64_t day_of_era = z - era * 146097;  // [0, 146096]
    const std::int64_t year_of_era =
        (day_of_era - day_of_era / 1460 + day_of_era / 36524 - day_of_era / 146096) / 365;
    const std::int64_t day_of_year =
        day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);  // [0, 365]
    const std::int64_t mp = (5 * day_of_year + 2) / 153;                         // [0, 11]
    CivilTime c;
    c.day = static_cast<int>(day_of_year - (153 * mp + 2) / 5 + 1);
    c.month = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
    c.year = static_cast<int>(year_of_era + era * 400 + (c.month <= 2 ? 1 : 0));
    c.hour = static_cast<int>(second_of_day / 3600);
    c.minute = static_cast<int>(second_of_day / 60 % 60);
    c.second = static_cast<int>(second_of_day % 60);
    c.fraction_s = time.fraction_s;
    return c;
}

DateTime make_datetime_utc(const CivilTime& civil, const ErrorContext& context) {
    const std::string problem = civil_problem(civil);
    if (!problem.empty()) throw input_error("invalid date-time: " + problem, context);
    return datetime_from_valid_civil(civil, 0);
}

DateTime parse_iso8601(std::string_view text, const ErrorContext& context) {
    std::string_view trimmed = text;
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!trimmed.empty() && blank(trimmed.front())) trimmed.remove_prefix(1);
    while (!trimmed.empty() && blank(trimmed.back())) trimmed.remove_suffix(1);
    return Iso8601Parser(text, trimmed, context).parse();
}

double seconds_between(const DateTime& a, const DateTime& b) noexcept {
    return static_cast<double>(b.unix_s - a.unix_s) + (b.fraction_s - a.fraction_s);
}

DateTime add_seconds(DateTime time, double seconds) {
    if (!(std::fabs(seconds) < 1e17)) {
        throw input_error("time step of " + format_ten_digits(seconds) +
                          " s is invalid, expected a finite value below 1e17 s");
    }
    double whole = std::floor(seconds);
    double part = seconds - whole;  // [0, 1], 1 only by rounding of tiny negative steps
    if (part >= 1.0) {
        part = 0.0;
        whole += 1.0;
    }
    time.unix_s += static_cast<std::int64_t>(whole);
    time.fraction_s += part;
    if (time.fraction_s >= 1.0) {
        time.fraction_s -= 1.0;
        time.unix_s += 1;
    }
    return time;
}

std::string format_iso8601_utc(const DateTime& time, int fraction_digits) {
    return format_with_offset(time, fraction_digits, 0);
}

std::string format_iso8601_local(const DateTime& time, int fraction_digits) {
    return format_with_offset(time, fraction_digits, time.utc_offset_min);
}

double julian_date_utc(const DateTime& time) noexcept {
    const std::int64_t days = floor_div(time.unix_s, kSecondsPerDay);
    const std::int64_t second_of_day = time.unix_s - days * kSecondsPerDay;
    return kJulianDateOfUnixEpoch + static_cast<double>(days) +
           (static_cast<double>(second_of_day) + time.fraction_s) / kSecondsPerDay;
}

}  // namespace glint
