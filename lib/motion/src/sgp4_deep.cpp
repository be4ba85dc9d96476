// SPDX-License-Identifier: Apache-2.0
// The deep-space part of the model (SDP4, orbital periods of 225 minutes and more): the
// lunar and solar perturbation coefficients (Spacetrack Report #3 DSCOM/DSINIT), their
// secular rates, the 12 h and 24 h geopotential resonances integrated by the report's
// Euler-Maclaurin scheme in 720-minute steps (DSPACE), and the lunar-solar long-period
// periodics with the Lyddane modification at low inclination (DPPER, 2006 mode 'i').
#include <cmath>

#include "sgp4_model.h"

namespace glint::motion::sgp4_detail {

namespace {

// Solar and lunar mean motions (rad/min) and orbit eccentricities.
constexpr double kZns = 1.19459e-5;
constexpr double kZes = 0.01675;
constexpr double kZnl = 1.5835218e-4;
constexpr double kZel = 0.05490;
// Perturbation constants of the Sun and Moon.
constexpr double kC1ss = 2.9864797e-6;
constexpr double kC1l = 4.7968065e-7;
// Sine and cosine of the obliquity, and the solar argument of perigee terms.
constexpr double kZsinis = 0.39785416;
constexpr double kZcosis = 0.91744867;
constexpr double kZcosgs = 0.1945905;
constexpr double kZsings = -0.98088458;
// Resonance constants.
constexpr double kQ22 = 1.7891679e-6;
constexpr double kQ31 = 2.1460748e-6;
constexpr double kQ33 = 2.2123015e-7;
constexpr double kRoot22 = 1.7891679e-6;
constexpr double kRoot44 = 7.3636953e-9;
constexpr double kRoot54 = 2.1765803e-9;
constexpr double kRoot32 = 3.7393792e-7;
constexpr double kRoot52 = 1.1428639e-7;
constexpr double kFasx2 = 0.13130908;
constexpr double kFasx4 = 2.8843198;
constexpr double kFasx6 = 0.37448087;
constexpr double kG22 = 5.7686396;
constexpr double kG32 = 0.95240898;
constexpr double kG44 = 1.8014998;
constexpr double kG52 = 1.0508330;
constexpr double kG54 = 4.4108898;
// Integrator step (minutes) and half its square.
constexpr double kStepMin = 720.0;
constexpr double kStep2 = 259200.0;
/// 3 degrees: below it (or within it of 180°) the node terms divided by sin i are dropped.
constexpr double kLowInclinationRad = 5.2359877e-2;

/// The terms of one perturbing body (Sun or Moon) on the satellite's orbit.
struct BodyTerms {
    double s1, s2, s3, s4, s5, s6, s7;
    double z1, z2, z3, z11, z12, z13, z21, z22, z23, z31, z32, z33;
};

/// The orbit's orientation and eccentricity, as the body terms need them.
struct OrbitGeometry {
    double sinim, cosim, sinomm, cosomm, snodm, cnodm;
    double em, emsq, betasq, rtemsq, xnoi;
};

/// Terms of a body whose orbit has argument of perigee (zcosg, zsing), inclination
/// (zcosi, zsini) and node relative to the satellite's (zcosh, zsinh); cc its strength.
BodyTerms body_terms(const OrbitGeometry& o, double zcosg, double zsing, double zcosi, double zsini,
                     double zcosh, double zsinh, double cc) noexcept {
    const double a1 = zcosg * zcosh + zsing * zcosi * zsinh;
    const double a3 = -zsing * zcosh + zcosg * zcosi * zsinh;
    const double a7 = -zcosg * zsinh + zsing * zcosi * zcosh;
    const double a8 = zsing * zsini;
    const double a9 = zsing * zsinh + zcosg * zcosi * zcosh;
    const double a10 = zcosg * zsini;
    const double a2 = o.cosim * a7 + o.sinim * a8;
    const double a4 = o.cosim * a9 + o.sinim * a10;
    const double a5 = -o.sinim * a7 + o.cosim * a8;
    const double a6 = -o.sinim * a9 + o.cosim * a10;

    const double x1 = a1 * o.cosomm + a2 * o.sinomm;
    const double x2 = a3 * o.cosomm + a4 * o.sinomm;
    const double x3 = -a1 * o.sinomm + a2 * o.cosomm;
    const double x4 = -a3 * o.sinomm + a4 * o.cosomm;
    const double x5 = a5 * o.sinomm;
    const double x6 = a6 * o.sinomm;
    const double x7 = a5 * o.cosomm;
    const double x8 = a6 * o.cosomm;

    BodyTerms b{};
    const double emsq = o.emsq;
    b.z31 = 12.0 * x1 * x1 - 3.0 * x3 * x3;
    b.z32 = 24.0 * x1 * x2 - 6.0 * x3 * x4;
    b.z33 = 12.0 * x2 * x2 - 3.0 * x4 * x4;
    b.z1 = 3.0 * (a1 * a1 + a2 * a2) + b.z31 * emsq;
    b.z2 = 6.0 * (a1 * a3 + a2 * a4) + b.z32 * emsq;
    b.z3 = 3.0 * (a3 * a3 + a4 * a4) + b.z33 * emsq;
    b.z11 = -6.0 * a1 * a5 + emsq * (-24.0 * x1 * x7 - 6.0 * x3 * x5);
    b.z12 = -6.0 * (a1 * a6 + a3 * a5) +
            emsq * (-24.0 * (x2 * x7 + x1 * x8) - 6.0 * (x3 * x6 + x4 * x5));
    b.z13 = -6.0 * a3 * a6 + emsq * (-24.0 * x2 * x8 - 6.0 * x4 * x6);
    b.z21 = 6.0 * a2 * a5 + emsq * (24.0 * x1 * x5 - 6.0 * x3 * x7);
    b.z22 =
        6.0 * (a4 * a5 + a2 * a6) + emsq * (24.0 * (x2 * x5 + x1 * x6) - 6.0 * (x4 * x7 + x3 * x8));
    b.z23 = 6.0 * a4 * a6 + emsq * (24.0 * x2 * x6 - 6.0 * x4 * x8);
    b.z1 = b.z1 + b.z1 + o.betasq * b.z31;
    b.z2 = b.z2 + b.z2 + o.betasq * b.z32;
    b.z3 = b.z3 + b.z3 + o.betasq * b.z33;
    b.s3 = cc * o.xnoi;
    b.s2 = -0.5 * b.s3 / o.rtemsq;
    b.s4 = b.s3 * o.rtemsq;
    b.s1 = -15.0 * o.em * b.s4;
    b.s5 = x1 * x3 + x2 * x4;
    b.s6 = x2 * x3 + x1 * x4;
    b.s7 = x2 * x4 - x1 * x3;
    return b;
}

/// Coefficients of the 12-hour (half-day) resonance for eccentricity `em` (irez = 2).
void init_half_day_resonance(Sgp4::Model& m, const OrbitGeometry& o, double aonv,
                             double theta) noexcept {
    DeepSpaceTerms& d = m.ds;
    const double em = o.em;
    const double emsq = o.emsq;
    const double eoc = em * emsq;
    const double cosim = o.cosim;
    const double sinim = o.sinim;
    const double cosisq = cosim * cosim;
    const double g201 = -0.306 - (em - 0.64) * 0.440;
    double g211, g310, g322, g410, g422, g520, g521, g532, g533;
    if (em <= 0.65) {
        g211 = 3.616 - 13.2470 * em + 16.2900 * emsq;
        g310 = -19.302 + 117.3900 * em - 228.4190 * emsq + 156.5910 * eoc;
        g322 = -18.9068 + 109.7927 * em - 214.6334 * emsq + 146.5816 * eoc;
        g410 = -41.122 + 242.6940 * em - 471.0940 * emsq + 313.9530 * eoc;
        g422 = -146.407 + 841.8800 * em - 1629.014 * emsq + 1083.4350 * eoc;
        g520 = -532.114 + 3017.977 * em - 5740.032 * emsq + 3708.2760 * eoc;
    } else {
        g211 = -72.099 + 331.819 * em - 508.738 * emsq + 266.724 * eoc;
        g310 = -346.844 + 1582.851 * em - 2415.925 * emsq + 1246.113 * eoc;
        g322 = -342.585 + 1554.908 * em - 2366.899 * emsq + 1215.972 * eoc;
        g410 = -1052.797 + 4758.686 * em - 7193.992 * emsq + 3651.957 * eoc;
        g422 = -3581.690 + 16178.110 * em - 24462.770 * emsq + 12422.520 * eoc;
        g520 = em > 0.715 ? -5149.66 + 29936.92 * em - 54087.36 * emsq + 31324.56 * eoc
                          : 1464.74 - 4664.75 * em + 3763.64 * emsq;
    }
    if (em < 0.7) {
        g533 = -919.22770 + 4988.6100 * em - 9064.7700 * emsq + 5542.21 * eoc;
        g521 = -822.71072 + 4568.6173 * em - 8491.4146 * emsq + 5337.524 * eoc;
        g532 = -853.66600 + 4690.2500 * em - 8624.7700 * emsq + 5341.4 * eoc;
    } else {
        g533 = -37995.780 + 161616.52 * em - 229838.20 * emsq + 109377.94 * eoc;
        g521 = -51752.104 + 218913.95 * em - 309468.16 * emsq + 146349.42 * eoc;
        g532 = -40023.880 + 170470.89 * em - 242699.48 * emsq + 115605.82 * eoc;
    }

    const double sini2 = sinim * sinim;
    const double f220 = 0.75 * (1.0 + 2.0 * cosim + cosisq);
    const double f221 = 1.5 * sini2;
    const double f321 = 1.875 * sinim * (1.0 - 2.0 * cosim - 3.0 * cosisq);
    const double f322 = -1.875 * sinim * (1.0 + 2.0 * cosim - 3.0 * cosisq);
    const double f441 = 35.0 * sini2 * f220;
    const double f442 = 39.3750 * sini2 * sini2;
    const double f522 = 9.84375 * sinim *
                        (sini2 * (1.0 - 2.0 * cosim - 5.0 * cosisq) +
                         0.33333333 * (-2.0 + 4.0 * cosim + 6.0 * cosisq));
    const double f523 = sinim * (4.92187512 * sini2 * (-2.0 - 4.0 * cosim + 10.0 * cosisq) +
                                 6.56250012 * (1.0 + 2.0 * cosim - 3.0 * cosisq));
    const double f542 =
        29.53125 * sinim * (2.0 - 8.0 * cosim + cosisq * (-12.0 + 8.0 * cosim + 10.0 * cosisq));
    const double f543 =
        29.53125 * sinim * (-2.0 - 8.0 * cosim + cosisq * (12.0 + 8.0 * cosim - 10.0 * cosisq));

    const double nm = m.no_unkozai;
    double temp1 = 3.0 * nm * nm * aonv * aonv;
    double temp = temp1 * kRoot22;
    d.d2201 = temp * f220 * g201;
    d.d2211 = temp * f221 * g211;
    temp1 *= aonv;
    temp = temp1 * kRoot32;
    d.d3210 = temp * f321 * g310;
    d.d3222 = temp * f322 * g322;
    temp1 *= aonv;
    temp = 2.0 * temp1 * kRoot44;
    d.d4410 = temp * f441 * g410;
    d.d4422 = temp * f442 * g422;
    temp1 *= aonv;
    temp = temp1 * kRoot52;
    d.d5220 = temp * f522 * g520;
    d.d5232 = temp * f523 * g532;
    temp = 2.0 * temp1 * kRoot54;
    d.d5421 = temp * f542 * g521;
    d.d5433 = temp * f543 * g533;
    d.xlamo = std::fmod(m.mo + m.nodeo + m.nodeo - theta - theta, kTwoPi);
    d.xfact =
        m.mdot + d.dmdt + 2.0 * (m.nodedot + d.dnodt - kEarthRotationRadPerMin) - m.no_unkozai;
}

/// Coefficients of the synchronous (24-hour) resonance (irez = 1).
void init_synchronous_resonance(Sgp4::Model& m, const OrbitGeometry& o, double aonv,
                                double theta) noexcept {
    DeepSpaceTerms& d = m.ds;
    const double emsq = o.emsq;
    const double cosim = o.cosim;
    const double sinim = o.sinim;
    const double g200 = 1.0 + emsq * (-2.5 + 0.8125 * emsq);
    const double g310 = 1.0 + 2.0 * emsq;
    const double g300 = 1.0 + emsq * (-6.0 + 6.60937 * emsq);
    const double f220 = 0.75 * (1.0 + cosim) * (1.0 + cosim);
    const double f311 = 0.9375 * sinim * sinim * (1.0 + 3.0 * cosim) - 0.75 * (1.0 + cosim);
    const double f330 = 1.875 * (1.0 + cosim) * (1.0 + cosim) * (1.0 + cosim);
    const double nm = m.no_unkozai;
    const double del1 = 3.0 * nm * nm * aonv * aonv;
    d.del2 = 2.0 * del1 * f220 * g200 * kQ22;
    d.del3 = 3.0 * del1 * f330 * g300 * kQ33 * aonv;
    d.del1 = del1 * f311 * g310 * kQ31 * aonv;
    d.xlamo = std::fmod(m.mo + m.nodeo + m.argpo - theta, kTwoPi);
    const double xpidot = m.argpdot + m.nodedot;
    d.xfact = m.mdot + xpidot - kEarthRotationRadPerMin + d.dmdt + d.domdt + d.dnodt - m.no_unkozai;
}

}  // namespace

void init_deep_space(Sgp4::Model& m) {
    DeepSpaceTerms& d = m.ds;
    OrbitGeometry o{};
    o.snodm = std::sin(m.nodeo);
    o.cnodm = std::cos(m.nodeo);
    o.sinomm = std::sin(m.argpo);
    o.cosomm = std::cos(m.argpo);
    o.sinim = std::sin(m.inclo);
    o.cosim = std::cos(m.inclo);
    o.em = m.ecco;
    o.emsq = o.em * o.em;
    o.betasq = 1.0 - o.emsq;
    o.rtemsq = std::sqrt(o.betasq);
    o.xnoi = 1.0 / m.no_unkozai;

    // Lunar orbit at epoch: node, inclination and the Moon's longitude terms. `day` counts
    // days from 1900 January 0.5 (JD 2415020.0).
    const double day = m.tle.epoch_days_since_1950() + 18261.5;
    const double xnodce = std::fmod(4.5236020 - 9.2422029e-4 * day, kTwoPi);
    const double stem = std::sin(xnodce);
    const double ctem = std::cos(xnodce);
    const double zcosil = 0.91375164 - 0.03568096 * ctem;
    const double zsinil = std::sqrt(1.0 - zcosil * zcosil);
    const double zsinhl = 0.089683511 * stem / zsinil;
    const double zcoshl = std::sqrt(1.0 - zsinhl * zsinhl);
    const double gam = 5.8351514 + 0.0019443680 * day;
    double zx = 0.39785416 * stem / zsinil;
    const double zy = zcoshl * ctem + 0.91744867 * zsinhl * stem;
    zx = std::atan2(zx, zy);
    zx = gam + zx - xnodce;
    const double zcosgl = std::cos(zx);
    const double zsingl = std::sin(zx);

    const BodyTerms sun =
        body_terms(o, kZcosgs, kZsings, kZcosis, kZsinis, o.cnodm, o.snodm, kC1ss);
    const BodyTerms moon =
        body_terms(o, zcosgl, zsingl, zcosil, zsinil, zcoshl * o.cnodm + zsinhl * o.snodm,
                   o.snodm * zcoshl - o.cnodm * zsinhl, kC1l);

    d.zmol = std::fmod(4.7199672 + 0.22997150 * day - gam, kTwoPi);
    d.zmos = std::fmod(6.2565837 + 0.017201977 * day, kTwoPi);

    // Long-period periodic coefficients: solar ...
    const double emsq = o.emsq;
    d.se2 = 2.0 * sun.s1 * sun.s6;
    d.se3 = 2.0 * sun.s1 * sun.s7;
    d.si2 = 2.0 * sun.s2 * sun.z12;
    d.si3 = 2.0 * sun.s2 * (sun.z13 - sun.z11);
    d.sl2 = -2.0 * sun.s3 * sun.z2;
    d.sl3 = -2.0 * sun.s3 * (sun.z3 - sun.z1);
    d.sl4 = -2.0 * sun.s3 * (-21.0 - 9.0 * emsq) * kZes;
    d.sgh2 = 2.0 * sun.s4 * sun.z32;
    d.sgh3 = 2.0 * sun.s4 * (sun.z33 - sun.z31);
    d.sgh4 = -18.0 * sun.s4 * kZes;
    d.sh2 = -2.0 * sun.s2 * sun.z22;
    d.sh3 = -2.0 * sun.s2 * (sun.z23 - sun.z21);
    // ... and lunar.
    d.ee2 = 2.0 * moon.s1 * moon.s6;
    d.e3 = 2.0 * moon.s1 * moon.s7;
    d.xi2 = 2.0 * moon.s2 * moon.z12;
    d.xi3 = 2.0 * moon.s2 * (moon.z13 - moon.z11);
    d.xl2 = -2.0 * moon.s3 * moon.z2;
    d.xl3 = -2.0 * moon.s3 * (moon.z3 - moon.z1);
    d.xl4 = -2.0 * moon.s3 * (-21.0 - 9.0 * emsq) * kZel;
    d.xgh2 = 2.0 * moon.s4 * moon.z32;
    d.xgh3 = 2.0 * moon.s4 * (moon.z33 - moon.z31);
    d.xgh4 = -18.0 * moon.s4 * kZel;
    d.xh2 = -2.0 * moon.s2 * moon.z22;
    d.xh3 = -2.0 * moon.s2 * (moon.z23 - moon.z21);

    // Secular rates from the Sun ...
    const bool near_polar_axis = m.inclo < kLowInclinationRad || m.inclo > kPi - kLowInclinationRad;
    const double ses = sun.s1 * kZns * sun.s5;
    const double sis = sun.s2 * kZns * (sun.z11 + sun.z13);
    const double sls = -kZns * sun.s3 * (sun.z1 + sun.z3 - 14.0 - 6.0 * emsq);
    const double sghs = sun.s4 * kZns * (sun.z31 + sun.z33 - 6.0);
    double shs = near_polar_axis ? 0.0 : -kZns * sun.s2 * (sun.z21 + sun.z23);
    if (o.sinim != 0.0) shs /= o.sinim;
    const double sgs = sghs - o.cosim * shs;
    // ... and the Moon.
    d.dedt = ses + moon.s1 * kZnl * moon.s5;
    d.didt = sis + moon.s2 * kZnl * (moon.z11 + moon.z13);
    d.dmdt = sls - kZnl * moon.s3 * (moon.z1 + moon.z3 - 14.0 - 6.0 * emsq);
    const double sghl = moon.s4 * kZnl * (moon.z31 + moon.z33 - 6.0);
    const double shll = near_polar_axis ? 0.0 : -kZnl * moon.s2 * (moon.z21 + moon.z23);
    d.domdt = sgs + sghl;
    d.dnodt = shs;
    if (o.sinim != 0.0) {
        d.domdt -= o.cosim / o.sinim * shll;
        d.dnodt += shll / o.sinim;
    }

    // Geopotential resonances: 24 h orbits (mean motion between 0.0034906585 and
    // 0.0052359877 rad/min) and eccentric 12 h orbits.
    const double nm = m.no_unkozai;
    d.irez = 0;
    if (nm < 0.0052359877 && nm > 0.0034906585) d.irez = 1;
    if (nm >= 8.26e-3 && nm <= 9.24e-3 && o.em >= 0.5) d.irez = 2;
    if (d.irez == 0) return;
    const double theta = std::fmod(m.gsto, kTwoPi);
    const double aonv = std::pow(nm / m.constants.xke_per_min, kTwoThirds);
    if (d.irez == 2) {
        init_half_day_resonance(m, o, aonv, theta);
    } else {
        init_synchronous_resonance(m, o, aonv, theta);
    }
}

void deep_space_secular(const Sgp4::Model& m, double t_min, MeanElements& e) noexcept {
    const DeepSpaceTerms& d = m.ds;
    const double theta = std::fmod(m.gsto + t_min * kEarthRotationRadPerMin, kTwoPi);
    e.em += d.dedt * t_min;
    e.inclm += d.didt * t_min;
    e.argpm += d.domdt * t_min;
    e.nodem += d.dnodt * t_min;
    e.mm += d.dmdt * t_min;
    if (d.irez == 0) return;

    // Integrate the resonance angle xli and mean motion xni from epoch in fixed steps of
    // 720 min towards t, then finish with a Taylor step of length ft.
    const double delt = t_min > 0.0 ? kStepMin : -kStepMin;
    double atime = 0.0;
    double xli = d.xlamo;
    double xni = m.no_unkozai;
    double xndt = 0.0, xldot = 0.0, xnddt = 0.0, ft = 0.0;
    for (;;) {
        if (d.irez != 2) {
            xndt = d.del1 * std::sin(xli - kFasx2) + d.del2 * std::sin(2.0 * (xli - kFasx4)) +
                   d.del3 * std::sin(3.0 * (xli - kFasx6));
            xldot = xni + d.xfact;
            xnddt = d.del1 * std::cos(xli - kFasx2) +
                    2.0 * d.del2 * std::cos(2.0 * (xli - kFasx4)) +
                    3.0 * d.del3 * std::cos(3.0 * (xli - kFasx6));
            xnddt *= xldot;
        } else {
            const double xomi = m.argpo + m.argpdot * atime;
            const double x2omi = xomi + xomi;
            const double x2li = xli + xli;
            xndt = d.d2201 * std::sin(x2omi + xli - kG22) + d.d2211 * std::sin(xli - kG22) +
                   d.d3210 * std::sin(xomi + xli - kG32) + d.d3222 * std::sin(-xomi + xli - kG32) +
                   d.d4410 * std::sin(x2omi + x2li - kG44) + d.d4422 * std::sin(x2li - kG44) +
                   d.d5220 * std::sin(xomi + xli - kG52) + d.d5232 * std::sin(-xomi + xli - kG52) +
                   d.d5421 * std::sin(xomi + x2li - kG54) + d.d5433 * std::sin(-xomi + x2li - kG54);
            xldot = xni + d.xfact;
            xnddt =
                d.d2201 * std::cos(x2omi + xli - kG22) + d.d2211 * std::cos(xli - kG22) +
                d.d3210 * std::cos(xomi + xli - kG32) + d.d3222 * std::cos(-xomi + xli - kG32) +
                d.d5220 * std::cos(xomi + xli - kG52) + d.d5232 * std::cos(-xomi + xli - kG52) +
                2.0 * (d.d4410 * std::cos(x2omi + x2li - kG44) + d.d4422 * std::cos(x2li - kG44) +
                       d.d5421 * std::cos(xomi + x2li - kG54) +
                       d.d5433 * std::cos(-xomi + x2li - kG54));
            xnddt *= xldot;
        }
        if (!(std::fabs(t_min - atime) >= kStepMin)) {
            ft = t_min - atime;
            break;
        }
        xli += xldot * delt + xndt * kStep2;
        xni += xndt * delt + xnddt * kStep2;
        atime += delt;
    }
    e.nm = xni + xndt * ft + xnddt * ft * ft * 0.5;
    const double xl = xli + xldot * ft + xndt * ft * ft * 0.5;
    if (d.irez != 1) {
        e.mm = xl - 2.0 * e.nodem + 2.0 * theta;
    } else {
        e.mm = xl - e.nodem - e.argpm + theta;
    }
}

void lunar_solar_periodics(const Sgp4::Model& m, double t_min, MeanElements& e) noexcept {
    const DeepSpaceTerms& d = m.ds;
    // Solar terms at the Sun's mean anomaly ...
    double zm = d.zmos + kZns * t_min;
    double zf = zm + 2.0 * kZes * std::sin(zm);
    double sinzf = std::sin(zf);
    double f2 = 0.5 * sinzf * sinzf - 0.25;
    double f3 = -0.5 * sinzf * std::cos(zf);
    const double ses = d.se2 * f2 + d.se3 * f3;
    const double sis = d.si2 * f2 + d.si3 * f3;
    const double sls = d.sl2 * f2 + d.sl3 * f3 + d.sl4 * sinzf;
    const double sghs = d.sgh2 * f2 + d.sgh3 * f3 + d.sgh4 * sinzf;
    const double shs = d.sh2 * f2 + d.sh3 * f3;
    // ... and lunar terms at the Moon's.
    zm = d.zmol + kZnl * t_min;
    zf = zm + 2.0 * kZel * std::sin(zm);
    sinzf = std::sin(zf);
    f2 = 0.5 * sinzf * sinzf - 0.25;
    f3 = -0.5 * sinzf * std::cos(zf);
    const double sel = d.ee2 * f2 + d.e3 * f3;
    const double sil = d.xi2 * f2 + d.xi3 * f3;
    const double sll = d.xl2 * f2 + d.xl3 * f3 + d.xl4 * sinzf;
    const double sghl = d.xgh2 * f2 + d.xgh3 * f3 + d.xgh4 * sinzf;
    const double shll = d.xh2 * f2 + d.xh3 * f3;

    const double pe = ses + sel;
    const double pinc = sis + sil;
    const double pl = sls + sll;
    double pgh = sghs + sghl;
    double ph = shs + shll;

    e.inclm += pinc;
    e.em += pe;
    const double sinip = std::sin(e.inclm);
    const double cosip = std::cos(e.inclm);
    if (e.inclm >= 0.2) {
        // Apply the periodics directly.
        ph /= sinip;
        pgh -= cosip * ph;
        e.argpm += pgh;
        e.nodem += ph;
        e.mm += pl;
        return;
    }
    // Low inclination: Lyddane's modification, through the non-singular variables
    // sin i sin Ω, sin i cos Ω and the mean longitude.
    const double sinop = std::sin(e.nodem);
    const double cosop = std::cos(e.nodem);
    double alfdp = sinip * sinop;
    double betdp = sinip * cosop;
    const double dalf = ph * cosop + pinc * cosip * sinop;
    const double dbet = -ph * sinop + pinc * cosip * cosop;
    alfdp += dalf;
    betdp += dbet;
    e.nodem = std::fmod(e.nodem, kTwoPi);
    double xls = e.mm + e.argpm + cosip * e.nodem;
    const double dls = pl + pgh - pinc * e.nodem * sinip;
    xls += dls;
    const double xnoh = e.nodem;
    e.nodem = std::atan2(alfdp, betdp);
    if (std::fabs(xnoh - e.nodem) > kPi) {
        e.nodem += e.nodem < xnoh ? kTwoPi : -kTwoPi;
    }
    e.mm += pl;
    e.argpm = xls - e.mm - cosip * e.nodem;
}

}  // namespace glint::motion::sgp4_detail
