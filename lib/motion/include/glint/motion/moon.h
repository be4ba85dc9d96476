// SPDX-License-Identifier: Apache-2.0
// Where the moon is and how much of it is lit: topocentric zenith and azimuth, distance and
// illuminated fraction from a UTC instant and a geodetic position. Geocentric position from
// the truncated ELP-2000/82 series of J. Meeus, "Astronomical Algorithms" (2nd ed., 1998),
// ch. 47 (about 10″ in longitude, 4″ in latitude), apparent place with the nutation of
// NREL SPA, topocentric parallax and horizon as in sun.h (exact parallax, which is up to
// about 1° for the moon), illuminated fraction from Meeus ch. 48 (phase angle from the
// geocentric elongation). Time scales and refraction as documented in sun.h.
#pragma once

#include "glint/core/datetime.h"
#include "glint/motion/frames.h"
#include "glint/motion/geometry.h"
#include "glint/motion/sun.h"

namespace glint::motion {

/// The moon seen from a place on Earth.
struct MoonPosition {
    double zenith_deg = 0.0;              ///< topocentric zenith angle (refraction only if asked)
    double azimuth_deg = 0.0;             ///< topocentric azimuth, clockwise from north, [0, 360)
    double distance_km = 0.0;             ///< observer–moon (centre) distance
    double geocentric_distance_km = 0.0;  ///< Earth centre–moon centre distance
    Vec3 direction_enu;                   ///< unit vector towards the moon in local ENU
    double phase_angle_deg = 0.0;         ///< Sun–Moon–Earth angle: 0 full moon, 180 new moon
    double phase_fraction = 0.0;          ///< illuminated fraction of the disc, (1 + cos i) / 2
    bool waxing = false;                  ///< true from new moon to full moon
    double right_ascension_deg = 0.0;     ///< geocentric apparent right ascension, [0, 360)
    double declination_deg = 0.0;         ///< geocentric apparent declination
};

/// The moon's position and phase at `utc` seen from (lat, lon, alt above the ellipsoid).
/// Throws glint::Error (input) as sun_position does.
MoonPosition moon_position(const DateTime& utc, double latitude_deg, double longitude_deg,
                           double altitude_m, const AstroOptions& options = {});
/// The moon seen from the origin of `frame`; direction_enu is in that frame.
MoonPosition moon_position(const DateTime& utc, const SceneFrame& frame,
                           const AstroOptions& options = {});

}  // namespace glint::motion
