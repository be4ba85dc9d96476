// SPDX-License-Identifier: Apache-2.0
// SGP4 initialisation: gravity constants, recovery of the Brouwer mean motion from the Kozai
// mean motion of the element set, secular rates from J2/J4, and the drag coefficients of
// Spacetrack Report #3 (with the 2006 revision's perigee and divide-by-zero fixes).
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/motion/teme.h"
#include "sgp4_model.h"

namespace glint::motion {

namespace {

using sgp4_detail::kPi;
using sgp4_detail::kTwoPi;
using sgp4_detail::kTwoThirds;

constexpr double kDegToRad = kPi / 180.0;
constexpr double kMinutesPerDay = 1440.0;
constexpr double kJdOf1950Origin = 2433281.5;  // 1949-12-31 00:00

GravityConstants make_constants(double mu_km3_s2, double radius_km, double j2, double j3,
                                double j4) noexcept {
    GravityConstants c;
    c.mu_km3_s2 = mu_km3_s2;
    c.radius_km = radius_km;
    c.xke_per_min = 60.0 / std::sqrt(radius_km * radius_km * radius_km / mu_km3_s2);
    c.j2 = j2;
    c.j3 = j3;
    c.j4 = j4;
    return c;
}

}  // namespace

GravityConstants gravity_constants(GravityModel model) noexcept {
    switch (model) {
        case GravityModel::wgs72_old: {
            GravityConstants c =
                make_constants(398600.79964, 6378.135, 0.001082616, -0.00000253881, -0.00000165597);
            c.xke_per_min = 0.0743669161;  // the value printed in Spacetrack Report #3
            return c;
        }
        case GravityModel::wgs84:
            return make_constants(398600.5, 6378.137, 0.00108262998905, -0.00000253215306,
                                  -0.00000161098761);
        case GravityModel::wgs72:
            break;
    }
    return make_constants(398600.8, 6378.135, 0.001082616, -0.00000253881, -0.00000165597);
}

namespace sgp4_detail {

void init_near_earth(Sgp4::Model& m) {
    const Tle& tle = m.tle;
    const GravityConstants& g = m.constants;
    const double xke = g.xke_per_min;
    const double j2 = g.j2;
    const double j4 = g.j4;
    m.j3oj2 = g.j3 / g.j2;
    m.km_per_s_per_unit = g.radius_km * xke / 60.0;

    m.ecco = tle.eccentricity;
    m.inclo = tle.inclination_deg * kDegToRad;
    m.nodeo = tle.raan_deg * kDegToRad;
    m.argpo = tle.arg_perigee_deg * kDegToRad;
    m.mo = tle.mean_anomaly_deg * kDegToRad;
    m.bstar = tle.bstar_per_earth_radii;
    m.no_kozai = tle.mean_motion_rev_day * kTwoPi / kMinutesPerDay;

    const ErrorContext where{"", 0, "satellite " + std::to_string(tle.satellite_number)};
    for (const double v :
         {m.ecco, m.inclo, m.nodeo, m.argpo, m.mo, m.bstar, m.no_kozai, tle.epoch_day}) {
        if (!std::isfinite(v)) throw input_error("element set has a non-finite value", where);
    }
    if (!(m.ecco >= 0.0 && m.ecco < 1.0)) {
        throw input_error("eccentricity " + std::to_string(m.ecco) + " is outside [0, 1)", where);
    }
    if (!(m.no_kozai > 0.0)) throw input_error("mean motion must be positive", where);

    // Recover the original mean motion (Brouwer) and semi-major axis from the Kozai value.
    const double eccsq = m.ecco * m.ecco;
    const double omeosq = 1.0 - eccsq;
    const double rteosq = std::sqrt(omeosq);
    const double cosio = std::cos(m.inclo);
    const double cosio2 = cosio * cosio;
    const double ak = std::pow(xke / m.no_kozai, kTwoThirds);
    const double d1 = 0.75 * j2 * (3.0 * cosio2 - 1.0) / (rteosq * omeosq);
    double del = d1 / (ak * ak);
    const double adel = ak * (1.0 - del * del - del * (1.0 / 3.0 + 134.0 * del * del / 81.0));
    del = d1 / (adel * adel);
    m.no_unkozai = m.no_kozai / (1.0 + del);

    const double ao = std::pow(xke / m.no_unkozai, kTwoThirds);
    const double sinio = std::sin(m.inclo);
    const double po = ao * omeosq;
    const double con42 = 1.0 - 5.0 * cosio2;
    m.con41 = -con42 - cosio2 - cosio2;
    const double posq = po * po;
    const double rp = ao * (1.0 - m.ecco);
    m.gsto = gmst_rad(kJdOf1950Origin + tle.epoch_days_since_1950());

    // Atmosphere: s and q0 - s of the density function, altered for perigees below 156 km.
    const double re = g.radius_km;
    const double ss = 78.0 / re + 1.0;
    const double qzms2t = std::pow((120.0 - 78.0) / re, 4.0);
    m.isimp = rp < 220.0 / re + 1.0;
    double sfour = ss;
    double qzms24 = qzms2t;
    const double perige_km = (rp - 1.0) * re;
    if (perige_km < 156.0) {
        sfour = perige_km < 98.0 ? 20.0 : perige_km - 78.0;
        qzms24 = std::pow((120.0 - sfour) / re, 4.0);
        sfour = sfour / re + 1.0;
    }
    const double pinvsq = 1.0 / posq;
    const double tsi = 1.0 / (ao - sfour);
    m.eta = ao * m.ecco * tsi;
    const double etasq = m.eta * m.eta;
    const double eeta = m.ecco * m.eta;
    const double psisq = std::fabs(1.0 - etasq);
    const double coef = qzms24 * std::pow(tsi, 4.0);
    const double coef1 = coef / std::pow(psisq, 3.5);
    const double cc2 = coef1 * m.no_unkozai *
                       (ao * (1.0 + 1.5 * etasq + eeta * (4.0 + etasq)) +
                        0.375 * j2 * tsi / psisq * m.con41 * (8.0 + 3.0 * etasq * (8.0 + etasq)));
    m.cc1 = m.bstar * cc2;
    double cc3 = 0.0;
    if (m.ecco > 1.0e-4) cc3 = -2.0 * coef * tsi * m.j3oj2 * m.no_unkozai * sinio / m.ecco;
    m.x1mth2 = 1.0 - cosio2;
    m.cc4 =
        2.0 * m.no_unkozai * coef1 * ao * omeosq *
        (m.eta * (2.0 + 0.5 * etasq) + m.ecco * (0.5 + 2.0 * etasq) -
         j2 * tsi / (ao * psisq) *
             (-3.0 * m.con41 * (1.0 - 2.0 * eeta + etasq * (1.5 - 0.5 * eeta)) +
              0.75 * m.x1mth2 * (2.0 * etasq - eeta * (1.0 + etasq)) * std::cos(2.0 * m.argpo)));
    m.cc5 = 2.0 * coef1 * ao * omeosq * (1.0 + 2.75 * (etasq + eeta) + eeta * etasq);

    // Secular rates of mean anomaly, perigee and node from J2 and J4.
    const double cosio4 = cosio2 * cosio2;
    const double temp1 = 1.5 * j2 * pinvsq * m.no_unkozai;
    const double temp2 = 0.5 * temp1 * j2 * pinvsq;
    const double temp3 = -0.46875 * j4 * pinvsq * pinvsq * m.no_unkozai;
    m.mdot = m.no_unkozai + 0.5 * temp1 * rteosq * m.con41 +
             0.0625 * temp2 * rteosq * (13.0 - 78.0 * cosio2 + 137.0 * cosio4);
    m.argpdot = -0.5 * temp1 * con42 + 0.0625 * temp2 * (7.0 - 114.0 * cosio2 + 395.0 * cosio4) +
                temp3 * (3.0 - 36.0 * cosio2 + 49.0 * cosio4);
    const double xhdot1 = -temp1 * cosio;
    m.nodedot =
        xhdot1 + (0.5 * temp2 * (4.0 - 19.0 * cosio2) + 2.0 * temp3 * (3.0 - 7.0 * cosio2)) * cosio;
    m.omgcof = m.bstar * cc3 * std::cos(m.argpo);
    m.xmcof = m.ecco > 1.0e-4 ? -kTwoThirds * coef * m.bstar / eeta : 0.0;
    m.nodecf = 3.5 * omeosq * xhdot1 * m.cc1;
    m.t2cof = 1.5 * m.cc1;
    // Long-period coefficients; 1.5e-12 replaces 1 + cos i for inclinations of 180 degrees.
    const double one_plus_cosio = std::fabs(cosio + 1.0) > 1.5e-12 ? 1.0 + cosio : 1.5e-12;
    m.xlcof = -0.25 * m.j3oj2 * sinio * (3.0 + 5.0 * cosio) / one_plus_cosio;
    m.aycof = -0.5 * m.j3oj2 * sinio;
    const double delmotemp = 1.0 + m.eta * std::cos(m.mo);
    m.delmo = delmotemp * delmotemp * delmotemp;
    m.sinmao = std::sin(m.mo);
    m.x7thm1 = 7.0 * cosio2 - 1.0;

    m.deep = kTwoPi / m.no_unkozai >= 225.0;
    if (m.deep) {
        m.isimp = true;
        return;
    }
    if (!m.isimp) {
        // Higher-order drag terms, kept only for perigees of 220 km and above.
        const double cc1sq = m.cc1 * m.cc1;
        m.d2 = 4.0 * ao * tsi * cc1sq;
        const double temp = m.d2 * tsi * m.cc1 / 3.0;
        m.d3 = (17.0 * ao + sfour) * temp;
        m.d4 = 0.5 * temp * ao * tsi * (221.0 * ao + 31.0 * sfour) * m.cc1;
        m.t3cof = m.d2 + 2.0 * cc1sq;
        m.t4cof = 0.25 * (3.0 * m.d3 + m.cc1 * (12.0 * m.d2 + 10.0 * cc1sq));
        m.t5cof = 0.2 * (3.0 * m.d4 + 12.0 * m.cc1 * m.d3 + 6.0 * m.d2 * m.d2 +
                         15.0 * cc1sq * (2.0 * m.d2 + cc1sq));
    }
}

}  // namespace sgp4_detail

}  // namespace glint::motion
