// SPDX-License-Identifier: Apache-2.0
// Private to lib/motion: the coefficients an initialised SGP4/SDP4 propagator keeps, and the
// stages that compute them (near-Earth initialisation in sgp4_near.cpp, deep-space terms in
// sgp4_deep.cpp, propagation in sgp4.cpp). Symbol names follow Spacetrack Report #3 and the
// 2006 revision (cc1, t2cof, xlcof, ...) so the code can be read against the equations.
#pragma once

#include "glint/motion/sgp4.h"
#include "glint/motion/tle.h"

namespace glint::motion {

namespace sgp4_detail {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kTwoThirds = 2.0 / 3.0;
/// Earth rotation rate used by the resonance terms, rad/min (Spacetrack Report #3 RPTIM).
inline constexpr double kEarthRotationRadPerMin = 4.37526908801129966e-3;

/// Lunar-solar terms of the deep-space model (SDP4), set once at initialisation.
struct DeepSpaceTerms {
    // Coefficients of the solar (s*) and lunar (x*, e*) long-period periodics.
    double e3 = 0, ee2 = 0, se2 = 0, se3 = 0, sgh2 = 0, sgh3 = 0, sgh4 = 0, sh2 = 0, sh3 = 0;
    double si2 = 0, si3 = 0, sl2 = 0, sl3 = 0, sl4 = 0;
    double xgh2 = 0, xgh3 = 0, xgh4 = 0, xh2 = 0, xh3 = 0, xi2 = 0, xi3 = 0;
    double xl2 = 0, xl3 = 0, xl4 = 0;
    double zmol = 0;  ///< lunar mean anomaly at epoch, rad
    double zmos = 0;  ///< solar mean anomaly at epoch, rad
    // Secular rates from the Sun and Moon, per minute.
    double dedt = 0, didt = 0, dmdt = 0, dnodt = 0, domdt = 0;
    // Geopotential resonance: 0 none, 1 synchronous (24 h), 2 half-day (12 h).
    int irez = 0;
    double d2201 = 0, d2211 = 0, d3210 = 0, d3222 = 0, d4410 = 0, d4422 = 0;
    double d5220 = 0, d5232 = 0, d5421 = 0, d5433 = 0;
    double del1 = 0, del2 = 0, del3 = 0;
    double xfact = 0;  ///< resonance rate offset, rad/min
    double xlamo = 0;  ///< resonance angle at epoch, rad
};

}  // namespace sgp4_detail

/// Everything an initialised propagator needs; immutable once built.
struct Sgp4::Model {
    Tle tle;
    GravityModel gravity = GravityModel::wgs72;
    GravityConstants constants;
    double j3oj2 = 0;              ///< J3 / J2
    double km_per_s_per_unit = 0;  ///< velocity unit (Re·xke per minute) in km/s

    // Mean elements at epoch: rad, rad/min; bstar in 1/earth radii.
    double ecco = 0, inclo = 0, nodeo = 0, argpo = 0, mo = 0, bstar = 0;
    double no_kozai = 0;    ///< mean motion as given (Kozai), rad/min
    double no_unkozai = 0;  ///< mean motion recovered for the model (Brouwer), rad/min

    bool deep = false;   ///< SDP4 branch (period ≥ 225 min)
    bool isimp = false;  ///< simplified drag (perigee below 220 km, and all deep-space orbits)
    double gsto = 0;     ///< GMST at epoch, rad

    // Secular rates, drag and long-period coefficients (Spacetrack Report #3 names).
    double mdot = 0, argpdot = 0, nodedot = 0, nodecf = 0;
    double cc1 = 0, cc4 = 0, cc5 = 0, d2 = 0, d3 = 0, d4 = 0;
    double t2cof = 0, t3cof = 0, t4cof = 0, t5cof = 0;
    double omgcof = 0, xmcof = 0, eta = 0, delmo = 0, sinmao = 0;
    double con41 = 0, x1mth2 = 0, x7thm1 = 0, xlcof = 0, aycof = 0;

    sgp4_detail::DeepSpaceTerms ds;
};

namespace sgp4_detail {

/// Near-Earth initialisation (Spacetrack Report #3 SGP4 init with the 2006 fixes): fills
/// every field of `m` except the deep-space terms; m.tle and m.gravity must be set.
void init_near_earth(Sgp4::Model& m);

/// Deep-space initialisation (DSCOM + DSINIT): fills m.ds. Needs the near-Earth fields.
void init_deep_space(Sgp4::Model& m);

/// Mean elements in flight through one propagation step.
struct MeanElements {
    double em = 0;     ///< eccentricity
    double inclm = 0;  ///< inclination, rad
    double nodem = 0;  ///< right ascension of the ascending node, rad
    double argpm = 0;  ///< argument of perigee, rad
    double mm = 0;     ///< mean anomaly, rad
    double nm = 0;     ///< mean motion, rad/min
};

/// Deep-space secular effects and resonance integration at `t_min` (DSPACE): updates `e`.
/// Integrates the resonance from epoch each call, so the result does not depend on
/// earlier calls.
void deep_space_secular(const Sgp4::Model& m, double t_min, MeanElements& e) noexcept;

/// Lunar-solar long-period periodics at `t_min` (DPPER, mode 'i'): updates ep, inclp,
/// nodep, argpp and mp of `e` (em, inclm, ... on entry are the mean values).
void lunar_solar_periodics(const Sgp4::Model& m, double t_min, MeanElements& e) noexcept;

}  // namespace sgp4_detail

}  // namespace glint::motion
