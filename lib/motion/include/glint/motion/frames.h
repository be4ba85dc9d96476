// SPDX-License-Identifier: Apache-2.0
// Coordinate frames: WGS84 geodetic ↔ ECEF ↔ the scene's local East-North-Up frame (through
// GeographicLib), and the vehicle (platform) frame conventions of DIRSIG.
//
// Frames (all right-handed, metres):
//   - Geodetic: WGS84 latitude (deg, north > 0), longitude (deg, east > 0), height above
//     the ellipsoid (m). Not above the geoid/MSL: DIRSIG's "altitude" is taken as
//     ellipsoidal height, as GeographicLib::LocalCartesian does.
//   - ECEF: WGS84 Earth-centred Earth-fixed; +X through (0°, 0°), +Y through (0°, 90°E),
//     +Z through the north pole.
//   - Scene ENU: origin at the scene's geodetic origin; X east, Y north, Z up along the
//     ellipsoid normal (the tangent-plane frame of GeographicLib::LocalCartesian). Scenes
//     without a geographic origin use kDefaultSceneOrigin.
//   - Vehicle: X right wing, Y forward, Z up. With zero rotation the vehicle axes coincide
//     with the scene axes (forward = north, right wing = east). Pitch is the rotation about
//     X (nose up > 0), roll about Y (right wing down > 0), yaw about Z (counter-clockwise
//     seen from above > 0); the angle triple is (x, y, z) = (pitch, roll, yaw), composed as
//     documented in euler.h. An instrument with identity mounts looks along −Z (nadir).
//
//                   ^ +Z up
//                   |    +Y forward (nose)
//                   |   /
//                   |  /
//                   | /
//   left wing ------o------> +X right wing
//                   |
//                   v  −Z: boresight of an instrument with identity mounts (nadir)
#pragma once

#include "glint/motion/euler.h"
#include "glint/motion/geometry.h"

namespace glint::motion {

/// A WGS84 geodetic position.
struct Geodetic {
    double latitude_deg = 0.0;   ///< −90..90, north positive
    double longitude_deg = 0.0;  ///< east positive; outputs are in [−180, 180]
    double altitude_m = 0.0;     ///< height above the WGS84 ellipsoid
};

/// Scene origin assumed when a scene gives none: 43° N, 78° W, 0 m, the example location of
/// DIRSIG's own scene documentation (near Rochester, NY). A glint choice, not a documented
/// DIRSIG default; every scene that cares should state its origin.
inline constexpr Geodetic kDefaultSceneOrigin{43.0, -78.0, 0.0};

/// Vehicle-frame unit vectors (see the file comment).
inline constexpr Vec3 kVehicleRight{1.0, 0.0, 0.0};
inline constexpr Vec3 kVehicleForward{0.0, 1.0, 0.0};
inline constexpr Vec3 kVehicleUp{0.0, 0.0, 1.0};
/// Look direction, in vehicle coordinates, of an instrument with identity mounts.
inline constexpr Vec3 kInstrumentBoresight{0.0, 0.0, -1.0};

/// A vehicle attitude in radians (DIRSIG sign conventions, see the file comment).
struct VehicleAttitude {
    double roll_rad = 0.0;   ///< about vehicle Y, right wing down > 0
    double pitch_rad = 0.0;  ///< about vehicle X, nose up > 0
    double yaw_rad = 0.0;    ///< about vehicle Z, counter-clockwise from above > 0
};

/// The DIRSIG angle triple (x, y, z) = (pitch, roll, yaw) of an attitude.
constexpr Vec3 to_euler_triple(const VehicleAttitude& attitude) noexcept {
    return {attitude.pitch_rad, attitude.roll_rad, attitude.yaw_rad};
}
/// The attitude of a DIRSIG angle triple (x, y, z) = (pitch, roll, yaw).
constexpr VehicleAttitude to_vehicle_attitude(const Vec3& euler_xyz_rad) noexcept {
    return {euler_xyz_rad.y, euler_xyz_rad.x, euler_xyz_rad.z};
}
/// The rotation taking vehicle coordinates to scene ENU coordinates for `attitude` composed
/// in `order` (DIRSIG's default "xyz": pitch first, then roll, then yaw about fixed axes).
Mat3 vehicle_to_scene_rotation(const VehicleAttitude& attitude,
                               EulerOrder order = EulerOrder::xyz) noexcept;

/// WGS84 geodetic → ECEF (m), by GeographicLib::Geocentric. Throws glint::Error (input)
/// for a latitude outside [−90, 90] or a non-finite value.
Vec3 geodetic_to_ecef(const Geodetic& position);
/// ECEF (m) → WGS84 geodetic, by GeographicLib::Geocentric (exact to round-off at any
/// height; longitude in [−180, 180], 0 on the polar axis).
Geodetic ecef_to_geodetic(const Vec3& ecef_m) noexcept;
/// The rotation taking ECEF vectors to ENU vectors at (lat, lon): rows are the east, north
/// and up unit vectors expressed in ECEF.
Mat3 ecef_to_enu_rotation(double latitude_deg, double longitude_deg) noexcept;

/// The scene's East-North-Up frame about a geodetic origin. A small value type (origin,
/// its ECEF position and the ECEF→ENU rotation); the ECEF↔ENU maps are inline and cheap.
class SceneFrame {
public:
    /// The frame about kDefaultSceneOrigin.
    SceneFrame();
    /// The frame about (lat, lon, alt). Throws glint::Error (input) for a latitude outside
    /// [−90, 90] or a non-finite value.
    SceneFrame(double latitude_deg, double longitude_deg, double altitude_m);
    /// The frame about `origin` (same checks).
    explicit SceneFrame(const Geodetic& origin);

    /// The geodetic origin as given (longitude not wrapped).
    const Geodetic& origin() const noexcept { return m_origin; }
    /// The origin in ECEF (m).
    const Vec3& origin_ecef() const noexcept { return m_origin_ecef_m; }
    /// Rotation ECEF → ENU (rows: east, north, up in ECEF).
    const Mat3& ecef_to_enu_rotation() const noexcept { return m_ecef_to_enu; }
    /// Rotation ENU → ECEF (columns: east, north, up in ECEF).
    Mat3 enu_to_ecef_rotation() const noexcept { return transpose(m_ecef_to_enu); }

    /// ECEF point (m) → scene ENU point (m).
    Vec3 ecef_to_enu(const Vec3& ecef_m) const noexcept {
        return m_ecef_to_enu * (ecef_m - m_origin_ecef_m);
    }
    /// Scene ENU point (m) → ECEF point (m).
    Vec3 enu_to_ecef(const Vec3& enu_m) const noexcept {
        return transpose(m_ecef_to_enu) * enu_m + m_origin_ecef_m;
    }
    /// ECEF direction → ENU direction (rotation only).
    Vec3 ecef_direction_to_enu(const Vec3& ecef) const noexcept { return m_ecef_to_enu * ecef; }
    /// ENU direction → ECEF direction (rotation only).
    Vec3 enu_direction_to_ecef(const Vec3& enu) const noexcept {
        return transpose(m_ecef_to_enu) * enu;
    }
    /// Geodetic point → scene ENU point (m). Throws like geodetic_to_ecef.
    Vec3 geodetic_to_enu(const Geodetic& position) const;
    /// Geodetic point (lat deg, lon deg, alt m) → scene ENU point (m).
    Vec3 geodetic_to_enu(double latitude_deg, double longitude_deg, double altitude_m) const {
        return geodetic_to_enu(Geodetic{latitude_deg, longitude_deg, altitude_m});
    }
    /// Scene ENU point (m) → geodetic point.
    Geodetic enu_to_geodetic(const Vec3& enu_m) const noexcept;

private:
    Geodetic m_origin;
    Vec3 m_origin_ecef_m;
    Mat3 m_ecef_to_enu;
};

}  // namespace glint::motion
