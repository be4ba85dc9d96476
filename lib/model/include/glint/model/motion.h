// SPDX-License-Identifier: Apache-2.0
// Platform motion as read from a DIRSIG motion file: GenericMotion (`.ppd`, a table of
// timed positions and Euler attitudes) or FlexMotion (`.motion`, one location engine and one
// orientation engine), each with optional six-degree-of-freedom platform jitter. Plain data
// in SI units (m, s, rad; geodetic latitude/longitude in degrees, `_deg`); glint::motion
// turns it into a trajectory (glint/motion/trajectory.h). docs/motion.md ("Platform motion files
// and trajectories") has the formulas; the XML read is (GenericMotion, DIRSIG's GUI layout):
//
// clang-format off
// | element / attribute | type | unit | default |
// |---|---|---|---|
// | platformmotion@type | generic | - | generic |
// | method@type | raw | - | raw |
// | data@rotationframe | sceneenu, ecef | - | sceneenu |
// | data@rotationorder | permutation of xyz | - | xyz |
// | data@angletype | absolute (delta: error, not supported) | - | absolute |
// | data@angularunits | degrees, radians | - | degrees |
// | data@spatialunits | meters, kilometers, feet | - | meters |
// | data/entry | at least one; times strictly increasing | | required |
// | entry/datetime@type | relative (absolute: error) | - | relative |
// | entry/datetime | number | s after the tasks reference | required |
// | entry/position/location@type | scene, ecef, geodetic | - | scene |
// | location (scene, ecef)/point/x, y, z | numbers | spatialunits | required |
// | location (geodetic)/latitude, longitude, altitude | [-90, 90], number, number | deg, deg, spatialunits | required |
// | entry/orientation/eulerangles/cartesiantriple/x, y, z | numbers (pitch, roll, yaw) | angularunits | required |
//
// FlexMotion (`<motion type="flexible">`; also inline in a GLIST dynamic instance):
//
// | element / attribute | type | unit | default |
// |---|---|---|---|
// | locationengine@type | waypoints, straight, fixed, sgp4 | - | required |
// | waypoints: data@source, @datetime | internal; relative | - | internal, relative |
// | waypoints: data@frame | scene, ecef, geodetic | - | scene |
// | waypoints: data@delimiter | one character, not a digit, letter, '.', '+', '-' (blank: runs of blanks) | - | "," |
// | waypoints: data text (CDATA) | lines "t, x, y, z" (geodetic: t, lat, lon, alt); times strictly increasing | s, m (deg) | at least one line |
// | straight: heading | number (clockwise from north) | locationengine@angularunits (degrees) | 0 |
// | straight: velocity | number >= 0 | m/s | required |
// | straight: start@frame | scene, ecef, geodetic; x, y, z (or latitude, longitude, altitude) children, or "a,b,c" text | m (deg) | required |
// | fixed: location (or point)@frame | as start | m (deg) | required |
// | sgp4: data@source / tle1, tle2 | internal / the two TLE lines | - | required |
// | orientationengine@type | velocity, lookat, euler, quaternions, spin | - | required |
// | velocity: constraint@type, @frame, @vector | constant; scene, ecef; "x,y,z" non-zero | - | constant, scene, 0,0,1 |
// | lookat: point (or location)@frame, or a nested locationengine | the target | m (deg) | required |
// | lookat: up@type, @frame, @vector | constant, velocity; scene, ecef; "x,y,z" | - | constant, scene, 0,0,1 |
// | euler: data@rotationorder, @angularunits, @delimiter | permutation of xyz; degrees, radians | - | xyz, degrees, "," |
// | euler: data text | lines "t, x, y, z" (pitch, roll, yaw) | s, angularunits | at least one line |
// | quaternions: data@scalar, @delimiter | first (t, w, x, y, z), last (t, x, y, z, w) | - | first, "," |
// | spin@angularunits; axis; rate; phase | degrees, radians; "x,y,z" (scene); number; number | -, -, angularunits/s, angularunits | degrees, 0,0,1, required, 0 |
//
// Jitter (`locationjitter`, `orientationjitter`, in both file kinds):
//
// | element / attribute | type | unit | default |
// |---|---|---|---|
// | locationjitter@spatialunits / orientationjitter@angularunits | meters, kilometers, feet / radians, degrees | - | meters / radians |
// | xaxis, yaxis, zaxis | one element per degree of freedom (location: scene x, y, z; orientation: about vehicle x, y, z) | | none |
// | axis@type | correlated (psd), uncorrelated (normal, gaussian), none | - | inferred from the children |
// | axis@spatialunits / @angularunits | overrides the jitter element's | - | the jitter element's |
// | uncorrelated: mean, stddev (or sigma) | number, number >= 0 | units above | 0, required |
// | correlated: psd@frequencyunits, @magnitudeunits, @phaseunits | hertz; units above; radians, degrees | - | hertz, units above, radians |
// | correlated: psd/entry/frequency, magnitude, phase | >= 0 strictly increasing, >= 0, number | Hz, magnitudeunits²/Hz, phaseunits | required, required, drawn from the RNG |
// | correlated: psdfile (or filename) | path of a frequency/PSD table (instead of psd) | Hz, unit²/Hz | - |
// clang-format on
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "glint/model/common.h"
#include "glint/model/jitter.h"

namespace glint::model {

/// The frame a location is written in.
enum class LocationFrame {
    scene,     ///< scene ENU, metres
    ecef,      ///< WGS84 Earth-centred Earth-fixed, metres
    geodetic,  ///< WGS84 latitude, longitude (degrees), height above the ellipsoid (m)
};

/// A location as written: scene ENU or ECEF x, y, z in metres, or geodetic.
struct Location {
    LocationFrame frame = LocationFrame::scene;
    std::array<double, 3> xyz_m{};  ///< scene ENU or ECEF (frame scene, ecef)
    double latitude_deg = 0.0;      ///< frame geodetic
    double longitude_deg = 0.0;     ///< frame geodetic
    double altitude_m = 0.0;        ///< frame geodetic: height above the WGS84 ellipsoid
    ErrorContext where;
};

// ---- GenericMotion (.ppd) -------------------------------------------------------------------

/// The frame GenericMotion Euler angles are given relative to.
enum class RotationFrame {
    scene_enu,  ///< `sceneenu`: the vehicle→scene rotation directly
    ecef,       ///< `ecef`: the vehicle→ECEF rotation (then ECEF→scene ENU)
};

/// One `<entry>` of a `.ppd`.
struct GenericMotionEntry {
    double time_s = 0.0;  ///< seconds after the tasks reference time
    Location location;
    std::array<double, 3> euler_rad{};  ///< (x, y, z) = (pitch, roll, yaw), radians
    ErrorContext where;
};

/// A GenericMotion `.ppd`: entries with strictly increasing times.
struct GenericMotion {
    RotationFrame rotation_frame = RotationFrame::scene_enu;
    /// Permutation of "xyz", lower case (glint/motion/euler.h).
    std::string rotation_order = "xyz";
    std::vector<GenericMotionEntry> entries;
    PlatformJitter jitter;
    ErrorContext where;
};

// ---- FlexMotion (.motion) -------------------------------------------------------------------

/// One row of a FlexMotion data table (waypoints, Euler angles, quaternions).
struct MotionTableRow {
    double time_s = 0.0;             ///< seconds after the tasks reference time
    std::array<double, 4> values{};  ///< see the engine for the meaning of each value
    int line = 0;                    ///< file line of the row (0: unknown)
};

enum class LocationEngineType { waypoints, straight, fixed, sgp4 };

/// `<locationengine>`: where the platform is. Only the fields of `type` are meaningful.
struct LocationEngine {
    LocationEngineType type = LocationEngineType::fixed;

    /// waypoints: frame of the rows; rows hold (x, y, z) m, or (lat deg, lon deg, alt m)
    /// for geodetic, in values[0..2]; times strictly increasing.
    LocationFrame waypoint_frame = LocationFrame::scene;
    std::vector<MotionTableRow> waypoints;

    /// straight: direction of travel, clockwise from north (scene +Y) towards east (+X).
    double heading_rad = 0.0;
    /// straight: speed along the heading.
    double speed_m_s = 0.0;
    /// straight: the start (position at t = 0); fixed: the location.
    Location location;

    /// sgp4: the two lines of the element set as written (parsed by glint::motion::Tle).
    std::string tle1;
    std::string tle2;
    ErrorContext tle_where;  ///< where <tle1> is (Tle::parse reports line 2 at line + 1)

    ErrorContext where;  ///< the <locationengine> (or <data>) element
};

/// How a direction hint (velocity constraint, lookat up) is given.
enum class DirectionType {
    constant,  ///< a fixed vector in `frame`
    velocity,  ///< the platform's velocity direction (lookat up only)
};

/// `<constraint>` of a velocity engine, `<up>` of a lookat engine.
struct DirectionHint {
    DirectionType type = DirectionType::constant;
    LocationFrame frame = LocationFrame::scene;   ///< scene or ecef (a direction)
    std::array<double, 3> vector{0.0, 0.0, 1.0};  ///< not zero; need not be unit length
    ErrorContext where;
};

enum class OrientationEngineType { velocity, lookat, euler, quaternions, spin };

/// `<orientationengine>`: how the platform is turned. Only the fields of `type` are meaningful.
struct OrientationEngine {
    OrientationEngineType type = OrientationEngineType::velocity;

    /// velocity: the up constraint; lookat: the up hint (vehicle +Y is turned towards it).
    DirectionHint up;
    /// lookat: the target (a `fixed` engine for a `<point>`, or any nested location engine).
    std::optional<LocationEngine> target;

    /// euler: rotation order (permutation of "xyz", lower case); rows hold (x, y, z) =
    /// (pitch, roll, yaw) in rad in values[0..2]. quaternions: rows hold (w, x, y, z) of the
    /// vehicle→scene rotation (not normalised; never zero). Times strictly increasing.
    std::string rotation_order = "xyz";
    std::vector<MotionTableRow> table;

    /// spin: rotation about `spin_axis` (scene frame, not zero) by phase + rate · t.
    std::array<double, 3> spin_axis{0.0, 0.0, 1.0};
    double spin_rate_rad_s = 0.0;
    double spin_phase_rad = 0.0;

    ErrorContext where;
};

/// A FlexMotion description: one location engine and one orientation engine.
struct FlexMotion {
    LocationEngine location;
    OrientationEngine orientation;
    PlatformJitter jitter;
    ErrorContext where;
};

/// A platform motion file: exactly one of `generic` and `flexible` is set after a read
/// without errors.
struct PlatformMotion {
    std::string file;  ///< as named to the reader
    std::optional<GenericMotion> generic;
    std::optional<FlexMotion> flexible;
};

}  // namespace glint::model
