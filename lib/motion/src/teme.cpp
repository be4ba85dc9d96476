// SPDX-License-Identifier: Apache-2.0
// Greenwich mean sidereal time (IAU-82) and the TEME ↔ pseudo-Earth-fixed rotation used with
// SGP4 output.
#include "glint/motion/teme.h"

#include <cmath>
#include <numbers>

namespace glint::motion {

namespace {

constexpr double kTwoPi_rad = 2.0 * std::numbers::pi;
constexpr double kJ2000 = 2451545.0;
constexpr double kDaysPerCentury = 36525.0;
constexpr double kSecondsPerDay = 86400.0;
/// GMST polynomial coefficients in seconds of time, T in Julian centuries of UT1.
constexpr double kGmst0_s = 67310.54841;
constexpr double kGmst1_s = 876600.0 * 3600.0 + 8640184.812866;
constexpr double kGmst2_s = 0.093104;
constexpr double kGmst3_s = -6.2e-6;

}  // namespace

double gmst_rad(double jd_ut1) noexcept {
    const double t = (jd_ut1 - kJ2000) / kDaysPerCentury;
    const double gmst_s = kGmst3_s * t * t * t + kGmst2_s * t * t + kGmst1_s * t + kGmst0_s;
    // 86400 s of time are 2π rad: 1 s = 2π / 86400 rad = (π / 180) / 240 rad.
    double angle = std::fmod(gmst_s * (std::numbers::pi / 180.0) / 240.0, kTwoPi_rad);
    if (angle < 0.0) angle += kTwoPi_rad;
    return angle;
}

double gmst_rate_rad_s(double jd_ut1) noexcept {
    const double t = (jd_ut1 - kJ2000) / kDaysPerCentury;
    const double seconds_per_century = (3.0 * kGmst3_s * t + 2.0 * kGmst2_s) * t + kGmst1_s;
    return seconds_per_century / (kDaysPerCentury * kSecondsPerDay) * kTwoPi_rad / kSecondsPerDay;
}

PositionVelocity teme_to_ecef(const Vec3& position_km, const Vec3& velocity_km_s,
                              double jd_ut1) noexcept {
    const double theta = gmst_rad(jd_ut1);
    const double w = gmst_rate_rad_s(jd_ut1);
    const double c = std::cos(theta), s = std::sin(theta);
    PositionVelocity out;
    out.position_km = {c * position_km.x + s * position_km.y,
                       -s * position_km.x + c * position_km.y, position_km.z};
    // v_ecef = Rz(−θ) v_teme − ω × r_ecef with ω = (0, 0, w).
    out.velocity_km_s = {c * velocity_km_s.x + s * velocity_km_s.y + w * out.position_km.y,
                         -s * velocity_km_s.x + c * velocity_km_s.y - w * out.position_km.x,
                         velocity_km_s.z};
    return out;
}

PositionVelocity ecef_to_teme(const Vec3& position_km, const Vec3& velocity_km_s,
                              double jd_ut1) noexcept {
    const double theta = gmst_rad(jd_ut1);
    const double w = gmst_rate_rad_s(jd_ut1);
    const double c = std::cos(theta), s = std::sin(theta);
    // Inertial velocity expressed in Earth-fixed axes: v_ecef + ω × r_ecef.
    const Vec3 v{velocity_km_s.x - w * position_km.y, velocity_km_s.y + w * position_km.x,
                 velocity_km_s.z};
    PositionVelocity out;
    out.position_km = {c * position_km.x - s * position_km.y, s * position_km.x + c * position_km.y,
                       position_km.z};
    out.velocity_km_s = {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
    return out;
}

}  // namespace glint::motion
