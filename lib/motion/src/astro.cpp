// SPDX-License-Identifier: Apache-2.0
// Shared astronomy for sun.cpp and moon.cpp, after NREL SPA (Reda & Andreas 2004): the
// leap-second table and ΔT, Julian dates, the 63-term nutation series, obliquity, sidereal
// time, ecliptic → equatorial, and the exact topocentric parallax + horizon step.
#include "astro.h"

#include <cmath>
#include <cstdint>
#include <string>

#include "glint/core/error.h"
#include "glint/core/units.h"

namespace glint::motion {
namespace {

/// One row of the IERS leap-second table: from this UTC date on, TAI − UTC = offset.
struct LeapSecond {
    int year;
    int month;
    double tai_minus_utc_s;
};

constexpr LeapSecond kLeapSeconds[] = {
    {1972, 1, 10}, {1972, 7, 11}, {1973, 1, 12}, {1974, 1, 13}, {1975, 1, 14}, {1976, 1, 15},
    {1977, 1, 16}, {1978, 1, 17}, {1979, 1, 18}, {1980, 1, 19}, {1981, 7, 20}, {1982, 7, 21},
    {1983, 7, 22}, {1985, 7, 23}, {1988, 1, 24}, {1990, 1, 25}, {1991, 1, 26}, {1992, 7, 27},
    {1993, 7, 28}, {1994, 7, 29}, {1996, 1, 30}, {1997, 7, 31}, {1999, 1, 32}, {2006, 1, 33},
    {2009, 1, 34}, {2012, 7, 35}, {2015, 7, 36}, {2017, 1, 37},
};

/// A nutation term (SPA Table A4.3): multipliers of D, M, M', F, Ω and the coefficients
/// a, b (Δψ, 0.0001″) and c, d (Δε, 0.0001″).
struct NutationTerm {
    int y[5];
    double a;
    double b;
    double c;
    double d;
};

constexpr NutationTerm kNutationTerms[] = {
    {{0, 0, 0, 0, 1}, -171996.0, -174.2, 92025.0, 8.9},
    {{-2, 0, 0, 2, 2}, -13187.0, -1.6, 5736.0, -3.1},
    {{0, 0, 0, 2, 2}, -2274.0, -0.2, 977.0, -0.5},
    {{0, 0, 0, 0, 2}, 2062.0, 0.2, -895.0, 0.5},
    {{0, 1, 0, 0, 0}, 1426.0, -3.4, 54.0, -0.1},
    {{0, 0, 1, 0, 0}, 712.0, 0.1, -7.0, 0.0},
    {{-2, 1, 0, 2, 2}, -517.0, 1.2, 224.0, -0.6},
    {{0, 0, 0, 2, 1}, -386.0, -0.4, 200.0, 0.0},
    {{0, 0, 1, 2, 2}, -301.0, 0.0, 129.0, -0.1},
    {{-2, -1, 0, 2, 2}, 217.0, -0.5, -95.0, 0.3},
    {{-2, 0, 1, 0, 0}, -158.0, 0.0, 0.0, 0.0},
    {{-2, 0, 0, 2, 1}, 129.0, 0.1, -70.0, 0.0},
    {{0, 0, -1, 2, 2}, 123.0, 0.0, -53.0, 0.0},
    {{2, 0, 0, 0, 0}, 63.0, 0.0, 0.0, 0.0},
    {{0, 0, 1, 0, 1}, 63.0, 0.1, -33.0, 0.0},
    {{2, 0, -1, 2, 2}, -59.0, 0.0, 26.0, 0.0},
    {{0, 0, -1, 0, 1}, -58.0, -0.1, 32.0, 0.0},
    {{0, 0, 1, 2, 1}, -51.0, 0.0, 27.0, 0.0},
    {{-2, 0, 2, 0, 0}, 48.0, 0.0, 0.0, 0.0},
    {{0, 0, -2, 2, 1}, 46.0, 0.0, -24.0, 0.0},
    {{2, 0, 0, 2, 2}, -38.0, 0.0, 16.0, 0.0},
    {{0, 0, 2, 2, 2}, -31.0, 0.0, 13.0, 0.0},
    {{0, 0, 2, 0, 0}, 29.0, 0.0, 0.0, 0.0},
    {{-2, 0, 1, 2, 2}, 29.0, 0.0, -12.0, 0.0},
    {{0, 0, 0, 2, 0}, 26.0, 0.0, 0.0, 0.0},
    {{-2, 0, 0, 2, 0}, -22.0, 0.0, 0.0, 0.0},
    {{0, 0, -1, 2, 1}, 21.0, 0.0, -10.0, 0.0},
    {{0, 2, 0, 0, 0}, 17.0, -0.1, 0.0, 0.0},
    {{2, 0, -1, 0, 1}, 16.0, 0.0, -8.0, 0.0},
    {{-2, 2, 0, 2, 2}, -16.0, 0.1, 7.0, 0.0},
    {{0, 1, 0, 0, 1}, -15.0, 0.0, 9.0, 0.0},
    {{-2, 0, 1, 0, 1}, -13.0, 0.0, 7.0, 0.0},
    {{0, -1, 0, 0, 1}, -12.0, 0.0, 6.0, 0.0},
    {{0, 0, 2, -2, 0}, 11.0, 0.0, 0.0, 0.0},
    {{2, 0, -1, 2, 1}, -10.0, 0.0, 5.0, 0.0},
    {{2, 0, 1, 2, 2}, -8.0, 0.0, 3.0, 0.0},
    {{0, 1, 0, 2, 2}, 7.0, 0.0, -3.0, 0.0},
    {{-2, 1, 1, 0, 0}, -7.0, 0.0, 0.0, 0.0},
    {{0, -1, 0, 2, 2}, -7.0, 0.0, 3.0, 0.0},
    {{2, 0, 0, 2, 1}, -7.0, 0.0, 3.0, 0.0},
    {{2, 0, 1, 0, 0}, 6.0, 0.0, 0.0, 0.0},
    {{-2, 0, 2, 2, 2}, 6.0, 0.0, -3.0, 0.0},
    {{-2, 0, 1, 2, 1}, 6.0, 0.0, -3.0, 0.0},
    {{2, 0, -2, 0, 1}, -6.0, 0.0, 3.0, 0.0},
    {{2, 0, 0, 0, 1}, -6.0, 0.0, 3.0, 0.0},
    {{0, -1, 1, 0, 0}, 5.0, 0.0, 0.0, 0.0},
    {{-2, -1, 0, 2, 1}, -5.0, 0.0, 3.0, 0.0},
    {{-2, 0, 0, 0, 1}, -5.0, 0.0, 3.0, 0.0},
    {{0, 0, 2, 2, 1}, -5.0, 0.0, 3.0, 0.0},
    {{-2, 0, 2, 0, 1}, 4.0, 0.0, 0.0, 0.0},
    {{-2, 1, 0, 2, 1}, 4.0, 0.0, 0.0, 0.0},
    {{0, 0, 1, -2, 0}, 4.0, 0.0, 0.0, 0.0},
    {{-1, 0, 1, 0, 0}, -4.0, 0.0, 0.0, 0.0},
    {{-2, 1, 0, 0, 0}, -4.0, 0.0, 0.0, 0.0},
    {{1, 0, 0, 0, 0}, -4.0, 0.0, 0.0, 0.0},
    {{0, 0, 1, 2, 0}, 3.0, 0.0, 0.0, 0.0},
    {{0, 0, -2, 2, 2}, -3.0, 0.0, 0.0, 0.0},
    {{-1, -1, 1, 0, 0}, -3.0, 0.0, 0.0, 0.0},
    {{0, 1, 1, 0, 0}, -3.0, 0.0, 0.0, 0.0},
    {{0, -1, 1, 2, 2}, -3.0, 0.0, 0.0, 0.0},
    {{2, -1, -1, 2, 2}, -3.0, 0.0, 0.0, 0.0},
    {{0, 0, 3, 2, 2}, -3.0, 0.0, 0.0, 0.0},
    {{2, -1, 0, 2, 2}, -3.0, 0.0, 0.0, 0.0},
};

double polynomial(double x, double c0, double c1, double c2, double c3) noexcept {
    return ((c3 * x + c2) * x + c1) * x + c0;
}

}  // namespace

double tai_minus_utc_s(const DateTime& utc) noexcept {
    double offset = 10.0;  // before 1972 UTC was not a leap-second scale; use the 1972 value
    for (const LeapSecond& leap : kLeapSeconds) {
        const std::int64_t start_s = days_from_civil(leap.year, leap.month, 1) * 86400;
        if (utc.unix_s >= start_s) offset = leap.tai_minus_utc_s;
    }
    return offset;
}

double delta_t_s(const DateTime& utc, const AstroOptions& options) noexcept {
    if (options.delta_t_s) return *options.delta_t_s;
    return 32.184 + tai_minus_utc_s(utc) - options.delta_ut1_s;
}

namespace detail {

double wrap_360(double angle_deg) noexcept {
    double r = std::fmod(angle_deg, 360.0);
    if (r < 0.0) r += 360.0;
    return r >= 360.0 ? 0.0 : r;
}

AstroTime astro_time(const DateTime& utc, const AstroOptions& options) noexcept {
    AstroTime t;
    t.jd_ut1 = julian_date_utc(utc) + options.delta_ut1_s / 86400.0;
    t.jde = t.jd_ut1 + delta_t_s(utc, options) / 86400.0;
    t.jc_ut1 = (t.jd_ut1 - 2451545.0) / 36525.0;
    t.jce = (t.jde - 2451545.0) / 36525.0;
    t.jme = t.jce / 10.0;
    return t;
}

Nutation nutation(const AstroTime& time) noexcept {
    const double jce = time.jce;
    // Fundamental arguments in degrees (SPA eq. 15-19).
    const double x[5] = {
        polynomial(jce, 297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0),
        polynomial(jce, 357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0),
        polynomial(jce, 134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0),
        polynomial(jce, 93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0),
        polynomial(jce, 125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0),
    };
    double sum_psi = 0.0, sum_eps = 0.0;
    for (const NutationTerm& term : kNutationTerms) {
        double arg = 0.0;
        for (int j = 0; j < 5; ++j) arg += x[j] * term.y[j];
        arg = deg_to_rad(arg);
        sum_psi += (term.a + term.b * jce) * std::sin(arg);
        sum_eps += (term.c + term.d * jce) * std::cos(arg);
    }
    Nutation n;
    n.delta_psi_deg = sum_psi / 36000000.0;
    n.delta_epsilon_deg = sum_eps / 36000000.0;
    // Mean obliquity (Laskar 1986, SPA eq. 24), U = JME / 10, in arc seconds.
    const double u = time.jme / 10.0;
    constexpr double kObliquity[] = {84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                     -39.05,    7.12,     27.87, 5.79,    2.45};
    double eps0 = 0.0;
    for (int i = 10; i >= 0; --i) eps0 = eps0 * u + kObliquity[i];
    n.true_obliquity_deg = eps0 / 3600.0 + n.delta_epsilon_deg;
    return n;
}

double apparent_sidereal_time_deg(const AstroTime& time, const Nutation& nut) noexcept {
    const double jc = time.jc_ut1;
    const double mean_deg = 280.46061837 + 360.98564736629 * (time.jd_ut1 - 2451545.0) +
                            jc * jc * (0.000387933 - jc / 38710000.0);
    return wrap_360(mean_deg + nut.delta_psi_deg * std::cos(deg_to_rad(nut.true_obliquity_deg)));
}

Equatorial ecliptic_to_equatorial(double longitude_deg, double latitude_deg,
                                  double obliquity_deg) noexcept {
    const double lambda = deg_to_rad(longitude_deg);
    const double beta = deg_to_rad(latitude_deg);
    const double eps = deg_to_rad(obliquity_deg);
    Equatorial e;
    e.right_ascension_deg = wrap_360(rad_to_deg(std::atan2(
        std::sin(lambda) * std::cos(eps) - std::tan(beta) * std::sin(eps), std::cos(lambda))));
    e.declination_deg = rad_to_deg(std::asin(std::sin(beta) * std::cos(eps) +
                                             std::cos(beta) * std::sin(eps) * std::sin(lambda)));
    return e;
}

Horizontal equatorial_to_horizontal(const Equatorial& body, double sin_parallax,
                                    double sidereal_deg, double latitude_deg, double longitude_deg,
                                    double altitude_m, const AstroOptions& options) noexcept {
    const double phi = deg_to_rad(latitude_deg);
    const double delta = deg_to_rad(body.declination_deg);
    const double h = deg_to_rad(wrap_360(sidereal_deg + longitude_deg - body.right_ascension_deg));
    // Observer's geocentric position in equatorial Earth radii (SPA eq. 38-40):
    // x = ρ cos φ', y = ρ sin φ'.
    constexpr double kAxisRatio = 0.99664719;  // b / a of the SPA ellipsoid
    constexpr double kEquatorialRadiusM = 6378140.0;
    const double u = std::atan(kAxisRatio * std::tan(phi));
    const double x = std::cos(u) + altitude_m / kEquatorialRadiusM * std::cos(phi);
    const double y = kAxisRatio * std::sin(u) + altitude_m / kEquatorialRadiusM * std::sin(phi);
    // Parallax in right ascension and topocentric declination (SPA eq. 41-45, exact).
    const double denom = std::cos(delta) - x * sin_parallax * std::cos(h);
    const double delta_alpha = std::atan2(-x * sin_parallax * std::sin(h), denom);
    const double delta_topo =
        std::atan2((std::sin(delta) - y * sin_parallax) * std::cos(delta_alpha), denom);
    const double h_topo = h - delta_alpha;
    // Topocentric elevation, refraction, zenith and azimuth (SPA eq. 41-47).
    const double e0_deg =
        rad_to_deg(std::asin(std::sin(phi) * std::sin(delta_topo) +
                             std::cos(phi) * std::cos(delta_topo) * std::cos(h_topo)));
    double refraction_deg = 0.0;
    constexpr double kSunRadiusDeg = 0.26667;
    constexpr double kHorizonRefractionDeg = 0.5667;
    if (options.apply_refraction && e0_deg >= -(kSunRadiusDeg + kHorizonRefractionDeg)) {
        refraction_deg = (options.pressure_mbar / 1010.0) *
                         (283.0 / (273.0 + options.temperature_c)) * 1.02 /
                         (60.0 * std::tan(deg_to_rad(e0_deg + 10.3 / (e0_deg + 5.11))));
    }
    Horizontal out;
    out.zenith_deg = 90.0 - (e0_deg + refraction_deg);
    const double gamma = std::atan2(
        std::sin(h_topo), std::cos(h_topo) * std::sin(phi) - std::tan(delta_topo) * std::cos(phi));
    out.azimuth_deg = wrap_360(rad_to_deg(gamma) + 180.0);
    out.hour_angle_deg = wrap_360(rad_to_deg(h_topo));
    // Topocentric distance: body at r = 1 / sin ξ Earth radii, hour angle h, declination δ;
    // observer at (x, 0, y) in the same (meridian, west, pole) frame.
    if (sin_parallax > 0.0) {
        const double r = 1.0 / sin_parallax;
        const double bx = r * std::cos(delta) * std::cos(h) - x;
        const double by = r * std::cos(delta) * std::sin(h);
        const double bz = r * std::sin(delta) - y;
        out.distance_ratio = std::sqrt(bx * bx + by * by + bz * bz) / r;
    }
    return out;
}

void check_observer(double latitude_deg, double longitude_deg, double altitude_m,
                    const AstroOptions& options) {
    if (!std::isfinite(latitude_deg) || !std::isfinite(longitude_deg) ||
        !std::isfinite(altitude_m)) {
        throw input_error("observer position has a non-finite value");
    }
    if (latitude_deg < -90.0 || latitude_deg > 90.0) {
        throw input_error("observer latitude " + std::to_string(latitude_deg) +
                          " is outside [-90, 90] degrees");
    }
    if (!std::isfinite(options.delta_ut1_s) ||
        (options.delta_t_s && !std::isfinite(*options.delta_t_s))) {
        throw input_error("time-scale offsets (delta_ut1_s, delta_t_s) must be finite");
    }
    if (options.apply_refraction) {
        if (!(options.pressure_mbar >= 0.0 && options.pressure_mbar <= 5000.0)) {
            throw input_error("refraction pressure " + std::to_string(options.pressure_mbar) +
                              " mbar is outside 0..5000");
        }
        if (!(options.temperature_c > -273.0 && options.temperature_c <= 6000.0)) {
            throw input_error("refraction temperature " + std::to_string(options.temperature_c) +
                              " degC is outside -273..6000");
        }
    }
}

}  // namespace detail
}  // namespace glint::motion
