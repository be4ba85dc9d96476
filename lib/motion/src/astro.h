// SPDX-License-Identifier: Apache-2.0
// Private helpers shared by sun.cpp and moon.cpp: time scales, nutation and obliquity, sidereal
// time (all following NREL SPA, Reda & Andreas 2004, §3.1-3.8), the sun's geocentric apparent
// position, and the topocentric parallax + horizon step (SPA §3.9-3.14, exact for any
// parallax, so it serves the moon too).
#pragma once

#include "glint/core/datetime.h"
#include "glint/motion/sun.h"

namespace glint::motion::detail {

/// Julian dates and centuries of one instant (SPA §3.1).
struct AstroTime {
    double jd_ut1 = 0.0;  ///< Julian day, UT1
    double jc_ut1 = 0.0;  ///< Julian centuries of UT1 from J2000.0
    double jde = 0.0;     ///< Julian ephemeris day, TT
    double jce = 0.0;     ///< Julian ephemeris centuries from J2000.0
    double jme = 0.0;     ///< Julian ephemeris millennia from J2000.0
};

/// The time arguments of `utc` under `options`.
AstroTime astro_time(const DateTime& utc, const AstroOptions& options) noexcept;

/// Nutation in longitude and obliquity and the true obliquity of the ecliptic (SPA §3.4-3.5,
/// the 63-term IAU 1980 series).
struct Nutation {
    double delta_psi_deg = 0.0;
    double delta_epsilon_deg = 0.0;
    double true_obliquity_deg = 0.0;
};

/// Nutation at `time` (uses its Julian ephemeris century).
Nutation nutation(const AstroTime& time) noexcept;

/// Apparent sidereal time at Greenwich in degrees, [0, 360) (SPA §3.8).
double apparent_sidereal_time_deg(const AstroTime& time, const Nutation& nut) noexcept;

/// Geocentric apparent right ascension and declination, degrees (SPA §3.9-3.10), from
/// apparent ecliptic longitude and latitude and the true obliquity.
struct Equatorial {
    double right_ascension_deg = 0.0;  ///< [0, 360)
    double declination_deg = 0.0;
};
Equatorial ecliptic_to_equatorial(double longitude_deg, double latitude_deg,
                                  double obliquity_deg) noexcept;

/// The sun's geocentric apparent position (SPA §3.2-3.10).
struct SunGeocentric {
    double apparent_longitude_deg = 0.0;  ///< λ, [0, 360)
    double distance_au = 0.0;             ///< R
    Equatorial equatorial;
};
SunGeocentric sun_geocentric(const AstroTime& time, const Nutation& nut) noexcept;

/// A body seen from the observer (SPA §3.11-3.14).
struct Horizontal {
    double zenith_deg = 0.0;      ///< topocentric, refraction applied if asked
    double azimuth_deg = 0.0;     ///< clockwise from north, [0, 360)
    double hour_angle_deg = 0.0;  ///< topocentric local hour angle, [0, 360)
    double distance_ratio = 1.0;  ///< topocentric / geocentric distance
};

/// Topocentric horizontal position of a body at geocentric apparent (α, δ) with equatorial
/// horizontal parallax sin ξ = a_earth / distance, seen from (lat, lon, alt) at Greenwich
/// apparent sidereal time `sidereal_deg`. Refraction per `options`.
Horizontal equatorial_to_horizontal(const Equatorial& body, double sin_parallax,
                                    double sidereal_deg, double latitude_deg, double longitude_deg,
                                    double altitude_m, const AstroOptions& options) noexcept;

/// Throws glint::Error (input) for an observer position or options that the algorithms
/// cannot use (see sun_position).
void check_observer(double latitude_deg, double longitude_deg, double altitude_m,
                    const AstroOptions& options);

/// `angle_deg` reduced to [0, 360).
double wrap_360(double angle_deg) noexcept;

}  // namespace glint::motion::detail
