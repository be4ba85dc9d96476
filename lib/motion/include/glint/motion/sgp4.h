// SPDX-License-Identifier: Apache-2.0
// SGP4/SDP4 orbit propagation of two-line element sets: glint's own implementation of the
// published model (F. R. Hoots and R. L. Roehrich, "Models for Propagation of NORAD Element
// Sets", Spacetrack Report No. 3, 1980) with the corrections of D. A. Vallado, P. Crawford,
// R. Hujsak and T. S. Kelso, "Revisiting Spacetrack Report #3", AIAA/AAS Astrodynamics
// Specialist Conference 2006, AIAA 2006-6753: near-Earth SGP4 with drag, and deep-space SDP4
// (periods ≥ 225 min) with lunar-solar secular and periodic terms and the 12 h and 24 h
// geopotential resonances. Operation mode is Vallado et al.'s "improved" mode 'i' (GMST by
// the IAU-82 formula, modern Lyddane handling); the old AFSPC mode 'a' is not offered.
//
// Results are in TEME, the "true equator, mean equinox" frame of the element set's epoch;
// teme.h turns them into ECEF. Verified against the verification vectors of Vallado et al.
// 2006 (SGP4-VER.TLE / tcppver.out) by tests/oracle/motion/sgp4_oracle_test.cpp. Full
// citations: docs/references.md.
#pragma once

#include <memory>
#include <string_view>

#include "glint/core/datetime.h"
#include "glint/motion/geometry.h"
#include "glint/motion/tle.h"

namespace glint::motion {

/// The Earth constants the propagator uses. Element sets are fitted with WGS-72, so use it
/// unless you know better; the verification vectors use WGS-72.
enum class GravityModel {
    wgs72_old,  ///< WGS-72 with the xke of the original Spacetrack Report #3 code
    wgs72,      ///< WGS-72 (μ = 398600.8 km³/s², Re = 6378.135 km): the default
    wgs84,      ///< WGS-84 (μ = 398600.5 km³/s², Re = 6378.137 km)
};

/// The constants of a gravity model.
struct GravityConstants {
    double mu_km3_s2 = 0.0;    ///< gravitational parameter
    double radius_km = 0.0;    ///< equatorial radius (the model's distance unit)
    double xke_per_min = 0.0;  ///< sqrt(μ / Re³) in 1/min (Re = 1 distance unit)
    double j2 = 0.0;           ///< zonal harmonics, unnormalised
    double j3 = 0.0;
    double j4 = 0.0;
};

/// The constants of `model`.
GravityConstants gravity_constants(GravityModel model) noexcept;

/// Why a propagation produced no state (the codes of the 2006 reference implementation).
enum class Sgp4Error {
    none = 0,                ///< success
    mean_elements = 1,       ///< mean eccentricity left [-0.001, 1) (drag decay)
    mean_motion = 2,         ///< mean motion fell to zero or below
    perturbed_elements = 3,  ///< eccentricity outside [0, 1] after the lunar-solar periodics
    semi_latus_rectum = 4,   ///< semi-latus rectum negative
    decayed = 6,             ///< the satellite is below the Earth's surface (decayed)
    invalid_time = 7,        ///< time not finite or more than 1e8 min from epoch (glint's own code)
    non_finite = 8,          ///< the model produced a non-finite number (glint's own code)
};

/// A short lowercase description of `error` ("satellite decayed", ...).
std::string_view describe(Sgp4Error error) noexcept;

/// The outcome of one propagation: position and velocity in TEME, or an error code. When
/// `error` is not none the vectors are zero (never NaN).
struct Sgp4State {
    Sgp4Error error = Sgp4Error::none;
    Vec3 position_km;    ///< TEME position
    Vec3 velocity_km_s;  ///< TEME velocity

    /// True when the propagation succeeded.
    bool ok() const noexcept { return error == Sgp4Error::none; }
};

/// A propagator initialised from one element set. Immutable after construction: copies are
/// cheap and propagate_* may be called from many threads at once.
class Sgp4 {
public:
    /// Initialises the model (un-Kozai the mean motion, drag and deep-space coefficients).
    /// Throws glint::Error (input) for elements the model cannot start from: eccentricity
    /// outside [0, 1), mean motion not positive, or any non-finite element.
    explicit Sgp4(const Tle& tle, GravityModel gravity = GravityModel::wgs72);

    /// Position and velocity in TEME `tsince_min` minutes after the element-set epoch (may
    /// be negative), or an error code. Never throws.
    Sgp4State propagate_minutes(double tsince_min) const noexcept;

    /// Like propagate_minutes at the UTC instant `time` (taken as UT1).
    Sgp4State propagate(const DateTime& time) const noexcept;

    /// Like propagate_minutes, but throws glint::Error (runtime), e.g. "satellite 22312
    /// decayed at t=494.2 min after epoch", instead of returning an error code.
    Sgp4State propagate_or_throw(double tsince_min) const;

    /// The element set this propagator was built from.
    const Tle& tle() const noexcept;
    /// The gravity model in use.
    GravityModel gravity() const noexcept;
    /// True for the deep-space branch (SDP4: orbital period of 225 minutes or more).
    bool deep_space() const noexcept;
    /// The un-Kozai'd ("Brouwer") mean motion at epoch in rad/min.
    double mean_motion_rad_min() const noexcept;
    /// Minutes from the element-set epoch to the UTC instant `time`.
    double minutes_since_epoch(const DateTime& time) const noexcept;

    /// Implementation data, defined in lib/motion/src.
    struct Model;

private:
    std::shared_ptr<const Model> m_model;
};

}  // namespace glint::motion
