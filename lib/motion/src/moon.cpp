// SPDX-License-Identifier: Apache-2.0
// The moon's position (Meeus, "Astronomical Algorithms" 2nd ed., ch. 47: truncated ELP-2000/82
// with the tables 47.A and 47.B) and illuminated fraction (ch. 48), seen from a place on Earth
// through the shared SPA nutation, sidereal time and topocentric step (astro.cpp).
#include "glint/motion/moon.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "astro.h"
#include "glint/core/units.h"

namespace glint::motion {
namespace {

/// Meeus table 47.A: multipliers of D, M, M', F; Σl coefficient (1e-6 deg) and Σr
/// coefficient (1e-3 km).
struct LongitudeDistanceTerm {
    int d;
    int m;
    int m_prime;
    int f;
    int l;
    int r;
};

/// Meeus table 47.B: multipliers of D, M, M', F; Σb coefficient (1e-6 deg).
struct LatitudeTerm {
    int d;
    int m;
    int m_prime;
    int f;
    int b;
};

constexpr LongitudeDistanceTerm kLongitudeDistance[] = {
    {0, 0, 1, 0, 6288774, -20905355},
    {2, 0, -1, 0, 1274027, -3699111},
    {2, 0, 0, 0, 658314, -2955968},
    {0, 0, 2, 0, 213618, -569925},
    {0, 1, 0, 0, -185116, 48888},
    {0, 0, 0, 2, -114332, -3149},
    {2, 0, -2, 0, 58793, 246158},
    {2, -1, -1, 0, 57066, -152138},
    {2, 0, 1, 0, 53322, -170733},
    {2, -1, 0, 0, 45758, -204586},
    {0, 1, -1, 0, -40923, -129620},
    {1, 0, 0, 0, -34720, 108743},
    {0, 1, 1, 0, -30383, 104755},
    {2, 0, 0, -2, 15327, 10321},
    {0, 0, 1, 2, -12528, 0},
    {0, 0, 1, -2, 10980, 79661},
    {4, 0, -1, 0, 10675, -34782},
    {0, 0, 3, 0, 10034, -23210},
    {4, 0, -2, 0, 8548, -21636},
    {2, 1, -1, 0, -7888, 24208},
    {2, 1, 0, 0, -6766, 30824},
    {1, 0, -1, 0, -5163, -8379},
    {1, 1, 0, 0, 4987, -16675},
    {2, -1, 1, 0, 4036, -12831},
    {2, 0, 2, 0, 3994, -10445},
    {4, 0, 0, 0, 3861, -11650},
    {2, 0, -3, 0, 3665, 14403},
    {0, 1, -2, 0, -2689, -7003},
    {2, 0, -1, 2, -2602, 0},
    {2, -1, -2, 0, 2390, 10056},
    {1, 0, 1, 0, -2348, 6322},
    {2, -2, 0, 0, 2236, -9884},
    {0, 1, 2, 0, -2120, 5751},
    {0, 2, 0, 0, -2069, 0},
    {2, -2, -1, 0, 2048, -4950},
    {2, 0, 1, -2, -1773, 4130},
    {2, 0, 0, 2, -1595, 0},
    {4, -1, -1, 0, 1215, -3958},
    {0, 0, 2, 2, -1110, 0},
    {3, 0, -1, 0, -892, 3258},
    {2, 1, 1, 0, -810, 2616},
    {4, -1, -2, 0, 759, -1897},
    {0, 2, -1, 0, -713, -2117},
    {2, 2, -1, 0, -700, 2354},
    {2, 1, -2, 0, 691, 0},
    {2, -1, 0, -2, 596, 0},
    {4, 0, 1, 0, 549, -1423},
    {0, 0, 4, 0, 537, -1117},
    {4, -1, 0, 0, 520, -1571},
    {1, 0, -2, 0, -487, -1739},
    {2, 1, 0, -2, -399, 0},
    {0, 0, 2, -2, -381, -4421},
    {1, 1, 1, 0, 351, 0},
    {3, 0, -2, 0, -340, 0},
    {4, 0, -3, 0, 330, 0},
    {2, -1, 2, 0, 327, 0},
    {0, 2, 1, 0, -323, 1165},
    {1, 1, -1, 0, 299, 0},
    {2, 0, 3, 0, 294, 0},
    {2, 0, -1, -2, 0, 8752},
};

constexpr LatitudeTerm kLatitude[] = {
    {0, 0, 0, 1, 5128122}, {0, 0, 1, 1, 280602},  {0, 0, 1, -1, 277693}, {2, 0, 0, -1, 173237},
    {2, 0, -1, 1, 55413},  {2, 0, -1, -1, 46271}, {2, 0, 0, 1, 32573},   {0, 0, 2, 1, 17198},
    {2, 0, 1, -1, 9266},   {0, 0, 2, -1, 8822},   {2, -1, 0, -1, 8216},  {2, 0, -2, -1, 4324},
    {2, 0, 1, 1, 4200},    {2, 1, 0, -1, -3359},  {2, -1, -1, 1, 2463},  {2, -1, 0, 1, 2211},
    {2, -1, -1, -1, 2065}, {0, 1, -1, -1, -1870}, {4, 0, -1, -1, 1828},  {0, 1, 0, 1, -1794},
    {0, 0, 0, 3, -1749},   {0, 1, -1, 1, -1565},  {1, 0, 0, 1, -1491},   {0, 1, 1, 1, -1475},
    {0, 1, 1, -1, -1410},  {0, 1, 0, -1, -1344},  {1, 0, 0, -1, -1335},  {0, 0, 3, 1, 1107},
    {4, 0, 0, -1, 1021},   {4, 0, -1, 1, 833},    {0, 0, 1, -3, 777},    {4, 0, -2, 1, 671},
    {2, 0, 0, -3, 607},    {2, 0, 2, -1, 596},    {2, -1, 1, -1, 491},   {2, 0, -2, 1, -451},
    {0, 0, 3, -1, 439},    {2, 0, 2, 1, 422},     {2, 0, -3, -1, 421},   {2, 1, -1, 1, -366},
    {2, 1, 0, 1, -351},    {4, 0, 0, 1, 331},     {2, -1, 1, 1, 315},    {2, -2, 0, -1, 302},
    {0, 0, 1, 3, -283},    {2, 1, 1, -1, -229},   {1, 1, 0, -1, 223},    {1, 1, 0, 1, 223},
    {0, 1, -2, -1, -220},  {2, 1, -1, -1, -220},  {1, 0, 1, 1, -185},    {2, -1, -2, -1, 181},
    {0, 1, 2, 1, -177},    {4, 0, -2, -1, 176},   {4, -1, -1, -1, 166},  {1, 0, 1, -1, -164},
    {4, 0, 1, -1, 132},    {1, 0, -1, -1, -119},  {4, -1, 0, -1, 115},   {2, -2, 0, 1, 107},
};

constexpr double kAuKm = 149597870.7;
constexpr double kEarthRadiusKm = 6378.14;  // Meeus' equatorial radius for the parallax

double polynomial4(double t, double c0, double c1, double c2, double c3, double c4) noexcept {
    return (((c4 * t + c3) * t + c2) * t + c1) * t + c0;
}

/// Geocentric ecliptic longitude and latitude (mean equinox of date, degrees) and distance.
struct MoonGeocentric {
    double longitude_deg;
    double latitude_deg;
    double distance_km;
};

MoonGeocentric moon_geocentric(double t) noexcept {
    const double lp = detail::wrap_360(polynomial4(t, 218.3164477, 481267.88123421, -0.0015786,
                                                   1.0 / 538841.0, -1.0 / 65194000.0));
    const double d = detail::wrap_360(polynomial4(t, 297.8501921, 445267.1114034, -0.0018819,
                                                  1.0 / 545868.0, -1.0 / 113065000.0));
    const double m = detail::wrap_360(
        polynomial4(t, 357.5291092, 35999.0502909, -0.0001536, 1.0 / 24490000.0, 0.0));
    const double mp = detail::wrap_360(
        polynomial4(t, 134.9633964, 477198.8675055, 0.0087414, 1.0 / 69699.0, -1.0 / 14712000.0));
    const double f = detail::wrap_360(polynomial4(t, 93.2720950, 483202.0175233, -0.0036539,
                                                  -1.0 / 3526000.0, 1.0 / 863310000.0));
    const double a1 = deg_to_rad(119.75 + 131.849 * t);
    const double a2 = deg_to_rad(53.09 + 479264.290 * t);
    const double a3 = deg_to_rad(313.45 + 481266.484 * t);
    const double e = 1.0 - t * (0.002516 + 0.0000074 * t);
    const double e_power[3] = {1.0, e, e * e};

    double sum_l = 0.0, sum_r = 0.0, sum_b = 0.0;
    for (const LongitudeDistanceTerm& term : kLongitudeDistance) {
        const double arg = deg_to_rad(term.d * d + term.m * m + term.m_prime * mp + term.f * f);
        const double scale = e_power[std::abs(term.m)];
        sum_l += term.l * scale * std::sin(arg);
        sum_r += term.r * scale * std::cos(arg);
    }
    for (const LatitudeTerm& term : kLatitude) {
        const double arg = deg_to_rad(term.d * d + term.m * m + term.m_prime * mp + term.f * f);
        sum_b += term.b * e_power[std::abs(term.m)] * std::sin(arg);
    }
    const double lp_rad = deg_to_rad(lp), mp_rad = deg_to_rad(mp), f_rad = deg_to_rad(f);
    sum_l += 3958.0 * std::sin(a1) + 1962.0 * std::sin(lp_rad - f_rad) + 318.0 * std::sin(a2);
    sum_b += -2235.0 * std::sin(lp_rad) + 382.0 * std::sin(a3) + 175.0 * std::sin(a1 - f_rad) +
             175.0 * std::sin(a1 + f_rad) + 127.0 * std::sin(lp_rad - mp_rad) -
             115.0 * std::sin(lp_rad + mp_rad);
    return {detail::wrap_360(lp + sum_l / 1e6), sum_b / 1e6, 385000.56 + sum_r / 1000.0};
}

}  // namespace

MoonPosition moon_position(const DateTime& utc, double latitude_deg, double longitude_deg,
                           double altitude_m, const AstroOptions& options) {
    detail::check_observer(latitude_deg, longitude_deg, altitude_m, options);
    const detail::AstroTime time = detail::astro_time(utc, options);
    const detail::Nutation nut = detail::nutation(time);
    const MoonGeocentric moon = moon_geocentric(time.jce);
    const double apparent_longitude_deg = detail::wrap_360(moon.longitude_deg + nut.delta_psi_deg);
    const detail::Equatorial eq = detail::ecliptic_to_equatorial(
        apparent_longitude_deg, moon.latitude_deg, nut.true_obliquity_deg);
    const double sidereal_deg = detail::apparent_sidereal_time_deg(time, nut);
    const detail::Horizontal h =
        detail::equatorial_to_horizontal(eq, kEarthRadiusKm / moon.distance_km, sidereal_deg,
                                         latitude_deg, longitude_deg, altitude_m, options);

    MoonPosition out;
    out.zenith_deg = h.zenith_deg;
    out.azimuth_deg = h.azimuth_deg;
    out.geocentric_distance_km = moon.distance_km;
    out.distance_km = moon.distance_km * h.distance_ratio;
    out.direction_enu = direction_from_zenith_azimuth(h.zenith_deg, h.azimuth_deg);
    out.right_ascension_deg = eq.right_ascension_deg;
    out.declination_deg = eq.declination_deg;

    // Illuminated fraction (Meeus eq. 48.2, 48.3, 48.1) from the geocentric elongation ψ.
    const detail::SunGeocentric sun = detail::sun_geocentric(time, nut);
    const double d0 = deg_to_rad(sun.equatorial.declination_deg);
    const double d1 = deg_to_rad(eq.declination_deg);
    const double da = deg_to_rad(sun.equatorial.right_ascension_deg - eq.right_ascension_deg);
    const double cos_psi = std::clamp(
        std::sin(d0) * std::sin(d1) + std::cos(d0) * std::cos(d1) * std::cos(da), -1.0, 1.0);
    const double psi = std::acos(cos_psi);
    const double sun_km = sun.distance_au * kAuKm;
    const double phase_angle =
        std::atan2(sun_km * std::sin(psi), moon.distance_km - sun_km * std::cos(psi));
    out.phase_angle_deg = rad_to_deg(phase_angle);
    out.phase_fraction = 0.5 * (1.0 + std::cos(phase_angle));
    out.waxing = detail::wrap_360(apparent_longitude_deg - sun.apparent_longitude_deg) < 180.0;
    return out;
}

MoonPosition moon_position(const DateTime& utc, const SceneFrame& frame,
                           const AstroOptions& options) {
    const Geodetic& o = frame.origin();
    return moon_position(utc, o.latitude_deg, o.longitude_deg, o.altitude_m, options);
}

}  // namespace glint::motion
