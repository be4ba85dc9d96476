// SPDX-License-Identifier: Apache-2.0
// Frames: geodetic → ECEF → scene ENU → ECEF → geodetic round trips below 1 mm (poles,
// antimeridian, LEO and GEO heights, below the ellipsoid), the ENU axes at (0°, 0°) and at the
// poles, known WGS84 values, agreement with GeographicLib::LocalCartesian, and input checks.
#include "glint/motion/frames.h"

#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "glint/core/error.h"
#include "motion_expect.h"

namespace glint::motion {
namespace frames_test {

constexpr double kLeoM = 700e3;
constexpr double kGeoM = 35786e3;

const std::vector<Geodetic>& test_points() {
    static const std::vector<Geodetic> points = {
        {0, 0, 0},
        {90, 0, 0},
        {-90, 0, 0},
        {90, 123, kLeoM},
        {-90, -45, -100},
        {0, 180, 0},
        {0, -180, 10},
        {12.5, 179.9999999, 250},
        {-33.9, -179.99, 5},
        {43.0, -78.0, 0},
        {39.742476, -105.1786, 1830.14},
        {89.9999, 10, kGeoM},
        {-89.9999, 170, kLeoM},
        {51.5, -0.1, kGeoM},
        {-12.3, 45.6, -430},
        {31.5, 35.5, -10000},
        {64.8, -147.7, kLeoM},
        {-77.8, 166.7, 3000},
    };
    return points;
}

/// Longitude difference wrapped into [−180, 180].
double lon_diff(double a, double b) { return std::remainder(a - b, 360.0); }

TEST(Frames, RoundTripBelowOneMillimetre) {
    const std::vector<Geodetic> origins = {{0, 0, 0},   {43, -78, 200}, {90, 0, 0},
                                           {-90, 0, 0}, {0, 180, 0},    {-45, -179.9, kLeoM}};
    double worst_m = 0.0;
    for (const Geodetic& origin : origins) {
        const SceneFrame frame(origin);
        for (const Geodetic& p : test_points()) {
            const Vec3 ecef = geodetic_to_ecef(p);
            const Vec3 enu = frame.ecef_to_enu(ecef);
            const Vec3 ecef2 = frame.enu_to_ecef(enu);
            const Geodetic g = ecef_to_geodetic(ecef2);
            const Geodetic g2 = frame.enu_to_geodetic(frame.geodetic_to_enu(p));
            // Distance between the original point and the round-tripped one, in metres.
            const double d = norm(geodetic_to_ecef(g) - ecef);
            const double d2 = norm(geodetic_to_ecef(g2) - ecef);
            worst_m = std::max({worst_m, d, d2});
            EXPECT_LT(d, 1e-3);
            EXPECT_LT(d2, 1e-3);
            EXPECT_NEAR(g.latitude_deg, p.latitude_deg, 1e-10);
            EXPECT_NEAR(g.altitude_m, p.altitude_m, 1e-3);
            if (std::abs(p.latitude_deg) < 90.0) {
                // Longitude loses digits towards the poles; compare the east-west arc.
                EXPECT_NEAR(lon_diff(g.longitude_deg, p.longitude_deg) *
                                std::cos(p.latitude_deg * std::numbers::pi / 180.0),
                            0.0, 1e-11);
            }
        }
    }
    std::ostringstream text;
    text << std::scientific << worst_m;
    RecordProperty("worst_round_trip_m", text.str());
}

TEST(Frames, EnuAxesAtZeroZero) {
    const SceneFrame frame(0, 0, 0);
    const Mat3 r = frame.enu_to_ecef_rotation();
    expect_near(r * Vec3{1, 0, 0}, {0, 1, 0}, 1e-15);  // east  = +Y_ecef
    expect_near(r * Vec3{0, 1, 0}, {0, 0, 1}, 1e-15);  // north = +Z_ecef
    expect_near(r * Vec3{0, 0, 1}, {1, 0, 0}, 1e-15);  // up    = +X_ecef
    expect_near(frame.origin_ecef(), {6378137.0, 0, 0}, 1e-9);
    expect_near(frame.enu_direction_to_ecef({0, 0, 1}), {1, 0, 0}, 1e-15);
    expect_near(frame.ecef_direction_to_enu({0, 1, 0}), {1, 0, 0}, 1e-15);
    // A point 1 km east of the origin along the tangent plane.
    expect_near(frame.ecef_to_enu({6378137.0, 1000.0, 0.0}), {1000, 0, 0}, 1e-9);
}

TEST(Frames, EnuAxesAtPolesAndAntimeridian) {
    // North pole, longitude 0: up = +Z, north points along −X (towards lon 180), east = +Y.
    const Mat3 np = SceneFrame(90, 0, 0).enu_to_ecef_rotation();
    expect_near(np.column(2), {0, 0, 1}, 1e-15);
    expect_near(np.column(1), {-1, 0, 0}, 1e-15);
    expect_near(np.column(0), {0, 1, 0}, 1e-15);
    // South pole: up = −Z, north = +X.
    const Mat3 sp = SceneFrame(-90, 0, 0).enu_to_ecef_rotation();
    expect_near(sp.column(2), {0, 0, -1}, 1e-15);
    expect_near(sp.column(1), {1, 0, 0}, 1e-15);
    // At (0, 180): up = −X, east = −Y; ±180 is the same place.
    const SceneFrame a(0, 180, 0), b(0, -180, 0);
    expect_near(a.enu_to_ecef_rotation().column(2), {-1, 0, 0}, 1e-15);
    expect_near(a.enu_to_ecef_rotation().column(0), {0, -1, 0}, 1e-15);
    expect_near(a.origin_ecef(), b.origin_ecef(), 1e-8);
    expect_near(geodetic_to_ecef({90, 0, 0}), {0, 0, 6356752.314245179}, 1e-6);
    expect_near(geodetic_to_ecef({-90, 0, 100}), {0, 0, -6356852.314245179}, 1e-6);
}

TEST(Frames, RotationIsOrthonormal) {
    for (const Geodetic& p : test_points()) {
        const Mat3 r = ecef_to_enu_rotation(p.latitude_deg, p.longitude_deg);
        EXPECT_NEAR(determinant(r), 1.0, 1e-14);
        const Mat3 i = r * transpose(r);
        for (std::size_t a = 0; a < 3; ++a) {
            for (std::size_t b = 0; b < 3; ++b) EXPECT_NEAR(i(a, b), a == b ? 1.0 : 0.0, 1e-15);
        }
    }
}

TEST(Frames, AgreesWithGeographicLibLocalCartesian) {
    const std::vector<Geodetic> origins = {
        {43, -78, 200}, {-33.9, 151.2, 0}, {89.5, 20, 0}, {0, 180, 1000}};
    for (const Geodetic& o : origins) {
        const SceneFrame frame(o);
        const GeographicLib::LocalCartesian lc(o.latitude_deg, o.longitude_deg, o.altitude_m);
        for (const Geodetic& p : test_points()) {
            Vec3 expected;
            lc.Forward(p.latitude_deg, p.longitude_deg, p.altitude_m, expected.x, expected.y,
                       expected.z);
            expect_near(frame.geodetic_to_enu(p), expected, 1e-6);
        }
    }
}

TEST(Frames, OriginAndVertical) {
    const SceneFrame frame(39.742476, -105.1786, 1830.14);
    expect_near(frame.geodetic_to_enu(39.742476, -105.1786, 1830.14), {0, 0, 0}, 1e-8);
    expect_near(frame.geodetic_to_enu(39.742476, -105.1786, 1830.14 + 500), {0, 0, 500}, 1e-8);
    const Geodetic g = frame.enu_to_geodetic({0, 0, 0});
    EXPECT_NEAR(g.latitude_deg, 39.742476, 1e-12);
    EXPECT_NEAR(g.longitude_deg, -105.1786, 1e-12);
    EXPECT_NEAR(g.altitude_m, 1830.14, 1e-8);
    // North of the origin is +Y, east is +X (small offsets, tangent plane).
    EXPECT_GT(frame.geodetic_to_enu(39.743, -105.1786, 1830.14).y, 50.0);
    EXPECT_GT(frame.geodetic_to_enu(39.742476, -105.178, 1830.14).x, 50.0);
}

TEST(Frames, DefaultOrigin) {
    const SceneFrame frame;
    EXPECT_EQ(frame.origin().latitude_deg, kDefaultSceneOrigin.latitude_deg);
    EXPECT_EQ(frame.origin().longitude_deg, kDefaultSceneOrigin.longitude_deg);
    EXPECT_EQ(frame.origin().altitude_m, kDefaultSceneOrigin.altitude_m);
}

TEST(Frames, RejectsBadInput) {
    EXPECT_THROW(SceneFrame(90.5, 0, 0), Error);
    EXPECT_THROW(SceneFrame(-91, 0, 0), Error);
    EXPECT_THROW(SceneFrame(NAN, 0, 0), Error);
    EXPECT_THROW(SceneFrame(0, INFINITY, 0), Error);
    EXPECT_THROW(geodetic_to_ecef({0, 0, NAN}), Error);
    try {
        SceneFrame(100, 0, 0);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find("latitude"), std::string::npos);
    }
}

}  // namespace frames_test
}  // namespace glint::motion
