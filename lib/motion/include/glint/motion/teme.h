// SPDX-License-Identifier: Apache-2.0
// From TEME (the "true equator, mean equinox" frame SGP4 works in) to Earth-fixed
// coordinates: a rotation about Z by the Greenwich mean sidereal time of the IAU-82 formula
// (as in Vallado's gstime), the convention of the 2006 SGP4 revision. Polar motion (< 15 m
// at the surface) and the equation-of-the-equinoxes kinematic terms are ignored, and UT1 is
// taken as UTC by callers that have no UT1 (|UT1 − UTC| < 0.9 s rotates the Earth by up to
// 66 µrad: ≤ 0.42 km at the surface, ≤ 0.45 km at LEO height, ≤ 2.8 km at GEO). The "ECEF"
// here is the pseudo-Earth-fixed frame, which differs from ITRF/WGS-84 by polar motion only.
#pragma once

#include "glint/motion/geometry.h"

namespace glint::motion {

/// Greenwich mean sidereal time in radians, [0, 2π), at the Julian date `jd_ut1` (UT1), by
/// the IAU-82 polynomial: GMST = 67310.54841 s + (876600 h + 8640184.812866 s) T
/// + 0.093104 s T² − 6.2e-6 s T³, T in Julian centuries of UT1 from J2000.0.
double gmst_rad(double jd_ut1) noexcept;

/// The Earth's rotation rate implied by gmst_rad at `jd_ut1`, in rad/s.
double gmst_rate_rad_s(double jd_ut1) noexcept;

/// A position and velocity pair.
struct PositionVelocity {
    Vec3 position_km;
    Vec3 velocity_km_s;
};

/// TEME position (km) and velocity (km/s) to Earth-fixed (pseudo-Earth-fixed, polar motion
/// ignored) at the Julian date `jd_ut1`: r = Rz(−GMST) r_teme, v = Rz(−GMST) v_teme − ω × r.
PositionVelocity teme_to_ecef(const Vec3& position_km, const Vec3& velocity_km_s,
                              double jd_ut1) noexcept;

/// The inverse of teme_to_ecef.
PositionVelocity ecef_to_teme(const Vec3& position_km, const Vec3& velocity_km_s,
                              double jd_ut1) noexcept;

}  // namespace glint::motion
