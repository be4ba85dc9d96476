// SPDX-License-Identifier: Apache-2.0
// Where the sun is: topocentric zenith and azimuth, Earth–Sun distance and the unit vector to
// the sun in the scene's ENU frame, from a UTC instant and a geodetic position, by NREL's
// Solar Position Algorithm (I. Reda and A. Andreas, "Solar position algorithm for solar
// radiation applications", Solar Energy 76(5), 2004, 577-589; corrected 2007/2008), stated
// to ±0.0003° for years −2000..6000.
//
// Time scales: DateTime is UTC. UT1 = UTC + delta_ut1_s (default 0: |UT1 − UTC| < 0.9 s, at
// most 0.004° of solar hour angle). TT − UT1 (ΔT) defaults to 32.184 s + (TAI − UTC) from
// the IERS leap-second table (10 s before 1972, 37 s from 2017 on, no future leap seconds
// assumed) − delta_ut1_s, i.e. 69.184 s today. A ΔT error of 60 s moves the sun by about
// 0.0007°, the moon by about 0.01°.
//
// Refraction is off by default (geometric, "airless" positions, as astropy's AltAz with
// pressure 0); AstroOptions::apply_refraction adds SPA's Bennett-type correction for the
// given pressure and temperature when the body is above −0.83° elevation.
#pragma once

#include <optional>

#include "glint/core/datetime.h"
#include "glint/motion/frames.h"
#include "glint/motion/geometry.h"

namespace glint::motion {

/// Options shared by sun_position and moon_position.
struct AstroOptions {
    bool apply_refraction = false;   ///< add atmospheric refraction to the elevation
    double pressure_mbar = 1013.25;  ///< mean local pressure, used only with refraction
    double temperature_c = 15.0;     ///< mean local temperature, used only with refraction
    double delta_ut1_s = 0.0;        ///< UT1 − UTC in seconds (|value| < 0.9 s)
    /// TT − UT1 in seconds; unset: 32.184 + (TAI − UTC from the leap-second table) −
    /// delta_ut1_s.
    std::optional<double> delta_t_s;
};

/// The sun seen from a place on Earth.
struct SunPosition {
    double zenith_deg = 0.0;   ///< topocentric zenith angle (0 overhead, > 90 below the horizon)
    double azimuth_deg = 0.0;  ///< topocentric azimuth, clockwise from north, [0, 360)
    double distance_au = 0.0;  ///< Earth–Sun distance (geocentric radius vector) in AU
    Vec3 direction_enu;        ///< unit vector towards the sun in local East-North-Up
    double right_ascension_deg = 0.0;  ///< geocentric apparent right ascension, [0, 360)
    double declination_deg = 0.0;      ///< geocentric apparent declination
    double hour_angle_deg = 0.0;       ///< topocentric local hour angle, [0, 360)
};

/// TAI − UTC in seconds at `utc` from the IERS leap-second table (10 before 1972-01-01,
/// 37 from 2017-01-01 on).
double tai_minus_utc_s(const DateTime& utc) noexcept;
/// TT − UT1 (ΔT) in seconds used for `utc` under `options` (see the file comment).
double delta_t_s(const DateTime& utc, const AstroOptions& options = {}) noexcept;

/// The sun's position at `utc` seen from (lat, lon, alt above the ellipsoid), by NREL SPA.
/// Throws glint::Error (input) for a latitude outside [−90, 90], a non-finite input or,
/// with refraction, a pressure outside 0..5000 mbar or temperature outside −273..6000 °C.
SunPosition sun_position(const DateTime& utc, double latitude_deg, double longitude_deg,
                         double altitude_m, const AstroOptions& options = {});
/// The sun's position at `utc` seen from the origin of `frame`; direction_enu is in that
/// frame.
SunPosition sun_position(const DateTime& utc, const SceneFrame& frame,
                         const AstroOptions& options = {});

/// The unit vector in ENU of the direction (zenith, azimuth clockwise from north), degrees.
Vec3 direction_from_zenith_azimuth(double zenith_deg, double azimuth_deg) noexcept;

}  // namespace glint::motion
