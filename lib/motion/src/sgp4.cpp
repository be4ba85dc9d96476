// SPDX-License-Identifier: Apache-2.0
// SGP4/SDP4 propagation: secular gravity and drag, deep-space secular and resonance terms,
// lunar-solar periodics, long-period J3 terms, Kepler's equation, short-period J2 terms and
// the TEME position and velocity, with the error checks of the 2006 revision.
#include "glint/motion/sgp4.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "glint/core/error.h"
#include "sgp4_model.h"

namespace glint::motion {

namespace {

using sgp4_detail::kPi;
using sgp4_detail::kTwoPi;
using sgp4_detail::kTwoThirds;
using sgp4_detail::MeanElements;

/// Beyond this many minutes from epoch (about 190 years) a time is refused.
constexpr double kMaxTsinceMin = 1.0e8;

Sgp4State failure(Sgp4Error error) noexcept {
    Sgp4State state;
    state.error = error;
    return state;
}

bool finite(const Vec3& v) noexcept {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The propagation proper; t in minutes from epoch, known finite and in range.
Sgp4State run_model(const Sgp4::Model& m, double t) noexcept {
    const double xke = m.constants.xke_per_min;
    const double j2 = m.constants.j2;

    // Secular gravity and atmospheric drag.
    const double xmdf = m.mo + m.mdot * t;
    const double argpdf = m.argpo + m.argpdot * t;
    const double nodedf = m.nodeo + m.nodedot * t;
    const double t2 = t * t;
    MeanElements e;
    e.argpm = argpdf;
    e.mm = xmdf;
    e.nodem = nodedf + m.nodecf * t2;
    double tempa = 1.0 - m.cc1 * t;
    double tempe = m.bstar * m.cc4 * t;
    double templ = m.t2cof * t2;
    if (!m.isimp) {
        const double delomg = m.omgcof * t;
        const double delmtemp = 1.0 + m.eta * std::cos(xmdf);
        const double delm = m.xmcof * (delmtemp * delmtemp * delmtemp - m.delmo);
        const double temp = delomg + delm;
        e.mm = xmdf + temp;
        e.argpm = argpdf - temp;
        const double t3 = t2 * t;
        const double t4 = t3 * t;
        tempa = tempa - m.d2 * t2 - m.d3 * t3 - m.d4 * t4;
        tempe += m.bstar * m.cc5 * (std::sin(e.mm) - m.sinmao);
        templ += m.t3cof * t3 + t4 * (m.t4cof + t * m.t5cof);
    }
    e.nm = m.no_unkozai;
    e.em = m.ecco;
    e.inclm = m.inclo;
    if (m.deep) sgp4_detail::deep_space_secular(m, t, e);

    if (!(e.nm > 0.0)) return failure(Sgp4Error::mean_motion);
    const double am = std::pow(xke / e.nm, kTwoThirds) * tempa * tempa;
    e.nm = xke / std::pow(am, 1.5);
    e.em -= tempe;
    if (!(e.em < 1.0 && e.em >= -0.001)) return failure(Sgp4Error::mean_elements);
    if (e.em < 1.0e-6) e.em = 1.0e-6;  // avoids a division by zero below
    e.mm += m.no_unkozai * templ;
    double xlm = e.mm + e.argpm + e.nodem;
    e.nodem = std::fmod(e.nodem, kTwoPi);
    e.argpm = std::fmod(e.argpm, kTwoPi);
    xlm = std::fmod(xlm, kTwoPi);
    e.mm = std::fmod(xlm - e.argpm - e.nodem, kTwoPi);

    // Lunar-solar periodics (deep space): from here e holds the perturbed elements.
    double aycof = m.aycof;
    double xlcof = m.xlcof;
    double con41 = m.con41;
    double x1mth2 = m.x1mth2;
    double x7thm1 = m.x7thm1;
    double sinip = std::sin(e.inclm);
    double cosip = std::cos(e.inclm);
    if (m.deep) {
        sgp4_detail::lunar_solar_periodics(m, t, e);
        if (e.inclm < 0.0) {
            e.inclm = -e.inclm;
            e.nodem += kPi;
            e.argpm -= kPi;
        }
        if (e.em < 0.0 || e.em > 1.0) return failure(Sgp4Error::perturbed_elements);
        sinip = std::sin(e.inclm);
        cosip = std::cos(e.inclm);
        aycof = -0.5 * m.j3oj2 * sinip;
        const double one_plus_cosip = std::fabs(cosip + 1.0) > 1.5e-12 ? 1.0 + cosip : 1.5e-12;
        xlcof = -0.25 * m.j3oj2 * sinip * (3.0 + 5.0 * cosip) / one_plus_cosip;
        const double cosisq = cosip * cosip;
        con41 = 3.0 * cosisq - 1.0;
        x1mth2 = 1.0 - cosisq;
        x7thm1 = 7.0 * cosisq - 1.0;
    }

    // Long-period periodics (J3).
    const double ep = e.em;
    const double axnl = ep * std::cos(e.argpm);
    double temp = 1.0 / (am * (1.0 - ep * ep));
    const double aynl = ep * std::sin(e.argpm) + temp * aycof;
    const double xl = e.mm + e.argpm + e.nodem + temp * xlcof * axnl;

    // Kepler's equation for the eccentric longitude, Newton steps limited to 0.95 rad.
    const double u = std::fmod(xl - e.nodem, kTwoPi);
    double eo1 = u;
    double tem5 = 9999.9;
    double sineo1 = 0.0;
    double coseo1 = 0.0;
    for (int ktr = 1; std::fabs(tem5) >= 1.0e-12 && ktr <= 10; ++ktr) {
        sineo1 = std::sin(eo1);
        coseo1 = std::cos(eo1);
        tem5 = 1.0 - coseo1 * axnl - sineo1 * aynl;
        tem5 = (u - aynl * coseo1 + axnl * sineo1 - eo1) / tem5;
        if (std::fabs(tem5) >= 0.95) tem5 = tem5 > 0.0 ? 0.95 : -0.95;
        eo1 += tem5;
    }

    // Short-period preliminary quantities.
    const double ecose = axnl * coseo1 + aynl * sineo1;
    const double esine = axnl * sineo1 - aynl * coseo1;
    const double el2 = axnl * axnl + aynl * aynl;
    const double pl = am * (1.0 - el2);
    if (pl < 0.0) return failure(Sgp4Error::semi_latus_rectum);
    const double rl = am * (1.0 - ecose);
    const double rdotl = std::sqrt(am) * esine / rl;
    const double rvdotl = std::sqrt(pl) / rl;
    const double betal = std::sqrt(1.0 - el2);
    temp = esine / (1.0 + betal);
    const double sinu = am / rl * (sineo1 - aynl - axnl * temp);
    const double cosu = am / rl * (coseo1 - axnl + aynl * temp);
    double su = std::atan2(sinu, cosu);
    const double sin2u = (cosu + cosu) * sinu;
    const double cos2u = 1.0 - 2.0 * sinu * sinu;
    temp = 1.0 / pl;
    const double temp1 = 0.5 * j2 * temp;
    const double temp2 = temp1 * temp;

    // Short-period periodics (J2).
    const double mrt = rl * (1.0 - 1.5 * temp2 * betal * con41) + 0.5 * temp1 * x1mth2 * cos2u;
    su -= 0.25 * temp2 * x7thm1 * sin2u;
    const double xnode = e.nodem + 1.5 * temp2 * cosip * sin2u;
    const double xinc = e.inclm + 1.5 * temp2 * cosip * sinip * cos2u;
    const double mvt = rdotl - e.nm * temp1 * x1mth2 * sin2u / xke;
    const double rvdot = rvdotl + e.nm * temp1 * (x1mth2 * cos2u + 1.5 * con41) / xke;

    // Orientation vectors and the TEME state.
    const double sinsu = std::sin(su);
    const double cossu = std::cos(su);
    const double snod = std::sin(xnode);
    const double cnod = std::cos(xnode);
    const double sini = std::sin(xinc);
    const double cosi = std::cos(xinc);
    const double xmx = -snod * cosi;
    const double xmy = cnod * cosi;
    const Vec3 uv{xmx * sinsu + cnod * cossu, xmy * sinsu + snod * cossu, sini * sinsu};
    const Vec3 vv{xmx * cossu - cnod * sinsu, xmy * cossu - snod * sinsu, sini * cossu};

    if (mrt < 1.0) return failure(Sgp4Error::decayed);
    Sgp4State state;
    state.position_km = uv * (mrt * m.constants.radius_km);
    state.velocity_km_s = (uv * mvt + vv * rvdot) * m.km_per_s_per_unit;
    if (!finite(state.position_km) || !finite(state.velocity_km_s)) {
        return failure(Sgp4Error::non_finite);
    }
    return state;
}

}  // namespace

std::string_view describe(Sgp4Error error) noexcept {
    switch (error) {
        case Sgp4Error::none:
            return "no error";
        case Sgp4Error::mean_elements:
            return "mean eccentricity out of range (orbit decayed by drag)";
        case Sgp4Error::mean_motion:
            return "mean motion is not positive";
        case Sgp4Error::perturbed_elements:
            return "perturbed eccentricity out of range";
        case Sgp4Error::semi_latus_rectum:
            return "semi-latus rectum is negative";
        case Sgp4Error::decayed:
            return "satellite decayed";
        case Sgp4Error::invalid_time:
            return "time is not finite or too far from the epoch";
        case Sgp4Error::non_finite:
            return "the model produced a non-finite value";
    }
    return "unknown error";
}

Sgp4::Sgp4(const Tle& tle, GravityModel gravity) {
    auto model = std::make_shared<Model>();
    model->tle = tle;
    model->gravity = gravity;
    model->constants = gravity_constants(gravity);
    sgp4_detail::init_near_earth(*model);
    if (model->deep) sgp4_detail::init_deep_space(*model);
    m_model = std::move(model);
}

Sgp4State Sgp4::propagate_minutes(double tsince_min) const noexcept {
    if (!std::isfinite(tsince_min) || std::fabs(tsince_min) > kMaxTsinceMin) {
        return failure(Sgp4Error::invalid_time);
    }
    return run_model(*m_model, tsince_min);
}

Sgp4State Sgp4::propagate(const DateTime& time) const noexcept {
    return propagate_minutes(minutes_since_epoch(time));
}

Sgp4State Sgp4::propagate_or_throw(double tsince_min) const {
    Sgp4State state = propagate_minutes(tsince_min);
    if (!state.ok()) {
        char when[64];
        std::snprintf(when, sizeof when, "%.6g", tsince_min);
        const std::string satellite = "satellite " + std::to_string(m_model->tle.satellite_number);
        if (state.error == Sgp4Error::decayed) {
            throw runtime_error(satellite + " decayed at t=" + when + " min after epoch");
        }
        throw runtime_error(satellite + ": sgp4 error " +
                            std::to_string(static_cast<int>(state.error)) + " at t=" + when +
                            " min after epoch: " + std::string(describe(state.error)));
    }
    return state;
}

const Tle& Sgp4::tle() const noexcept { return m_model->tle; }

GravityModel Sgp4::gravity() const noexcept { return m_model->gravity; }

bool Sgp4::deep_space() const noexcept { return m_model->deep; }

double Sgp4::mean_motion_rad_min() const noexcept { return m_model->no_unkozai; }

double Sgp4::minutes_since_epoch(const DateTime& time) const noexcept {
    return seconds_between(m_model->tle.epoch(), time) / 60.0;
}

}  // namespace glint::motion
