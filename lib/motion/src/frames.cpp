// SPDX-License-Identifier: Apache-2.0
// Geodetic ↔ ECEF through GeographicLib's WGS84 Geocentric, the ECEF → ENU tangent-plane
// rotation, the scene frame built from them, and the vehicle attitude rotation.
#include "glint/motion/frames.h"

#include <GeographicLib/Geocentric.hpp>
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/units.h"

namespace glint::motion {
namespace {

void check_geodetic(const Geodetic& p) {
    if (!std::isfinite(p.latitude_deg) || !std::isfinite(p.longitude_deg) ||
        !std::isfinite(p.altitude_m)) {
        throw input_error("geodetic position has a non-finite value (latitude " +
                          std::to_string(p.latitude_deg) + ", longitude " +
                          std::to_string(p.longitude_deg) + ", altitude " +
                          std::to_string(p.altitude_m) + ")");
    }
    if (p.latitude_deg < -90.0 || p.latitude_deg > 90.0) {
        throw input_error("latitude " + std::to_string(p.latitude_deg) +
                          " is outside [-90, 90] degrees");
    }
}

}  // namespace

Mat3 vehicle_to_scene_rotation(const VehicleAttitude& attitude, EulerOrder order) noexcept {
    return euler_to_matrix(to_euler_triple(attitude), order);
}

Vec3 geodetic_to_ecef(const Geodetic& position) {
    check_geodetic(position);
    Vec3 ecef;
    GeographicLib::Geocentric::WGS84().Forward(position.latitude_deg, position.longitude_deg,
                                               position.altitude_m, ecef.x, ecef.y, ecef.z);
    return ecef;
}

Geodetic ecef_to_geodetic(const Vec3& ecef_m) noexcept {
    Geodetic g;
    GeographicLib::Geocentric::WGS84().Reverse(ecef_m.x, ecef_m.y, ecef_m.z, g.latitude_deg,
                                               g.longitude_deg, g.altitude_m);
    return g;
}

Mat3 ecef_to_enu_rotation(double latitude_deg, double longitude_deg) noexcept {
    const double phi = deg_to_rad(latitude_deg), lambda = deg_to_rad(longitude_deg);
    const double sp = std::sin(phi), cp = std::cos(phi);
    const double sl = std::sin(lambda), cl = std::cos(lambda);
    return Mat3::from_rows({-sl, cl, 0.0}, {-sp * cl, -sp * sl, cp}, {cp * cl, cp * sl, sp});
}

SceneFrame::SceneFrame() : SceneFrame(kDefaultSceneOrigin) {}

SceneFrame::SceneFrame(double latitude_deg, double longitude_deg, double altitude_m)
    : SceneFrame(Geodetic{latitude_deg, longitude_deg, altitude_m}) {}

SceneFrame::SceneFrame(const Geodetic& origin)
    : m_origin(origin),
      m_origin_ecef_m(geodetic_to_ecef(origin)),
      m_ecef_to_enu(motion::ecef_to_enu_rotation(origin.latitude_deg, origin.longitude_deg)) {}

Vec3 SceneFrame::geodetic_to_enu(const Geodetic& position) const {
    return ecef_to_enu(geodetic_to_ecef(position));
}

Geodetic SceneFrame::enu_to_geodetic(const Vec3& enu_m) const noexcept {
    return ecef_to_geodetic(enu_to_ecef(enu_m));
}

}  // namespace glint::motion
