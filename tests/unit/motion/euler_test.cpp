// SPDX-License-Identifier: Apache-2.0
// Euler angles: every rotation order against the product of elementary matrices written out
// by hand and against a closed-form matrix, what "xyz" means for concrete vectors, quaternion
// and matrix forms agree, Euler → matrix → Euler round trips away from and at gimbal lock,
// order names, and the vehicle sign conventions (roll, pitch, yaw, nadir boresight).
#include "glint/motion/euler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "glint/motion/frames.h"
#include "glint/test/angles.h"
#include "motion_expect.h"

namespace glint::motion {
namespace euler_test {

using glint::test::kPi;

/// The rotation of order `order` built by hand: the first-applied matrix on the right.
Mat3 by_hand(const Vec3& a, EulerOrder order) {
    const Mat3 rx = rotation_x(a.x), ry = rotation_y(a.y), rz = rotation_z(a.z);
    switch (order) {
        case EulerOrder::xyz:
            return rz * ry * rx;
        case EulerOrder::xzy:
            return ry * rz * rx;
        case EulerOrder::yxz:
            return rz * rx * ry;
        case EulerOrder::yzx:
            return rx * rz * ry;
        case EulerOrder::zxy:
            return ry * rx * rz;
        case EulerOrder::zyx:
            return rx * ry * rz;
    }
    return Mat3::identity();
}

TEST(Euler, EveryOrderMatchesElementaryProducts) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(-kPi, kPi);
    for (const EulerOrder order : kAllEulerOrders) {
        for (int i = 0; i < 100; ++i) {
            const Vec3 a{angle(rng), angle(rng), angle(rng)};
            expect_near(euler_to_matrix(a, order), by_hand(a, order), 1e-14);
            expect_near(to_matrix(euler_to_quaternion(a, order)), by_hand(a, order), 1e-14);
        }
    }
}

TEST(Euler, XyzMatchesClosedForm) {
    // Rz(γ)·Ry(β)·Rx(α) written out (e.g. Craig, "Introduction to Robotics", eq. 2.64).
    const double al = 0.3, be = -0.7, ga = 1.9;
    const double ca = std::cos(al), sa = std::sin(al), cb = std::cos(be), sb = std::sin(be);
    const double cg = std::cos(ga), sg = std::sin(ga);
    const Mat3 expected = Mat3::from_rows({cg * cb, cg * sb * sa - sg * ca, cg * sb * ca + sg * sa},
                                          {sg * cb, sg * sb * sa + cg * ca, sg * sb * ca - cg * sa},
                                          {-sb, cb * sa, cb * ca});
    expect_near(euler_to_matrix({al, be, ga}, EulerOrder::xyz), expected, 1e-15);
}

TEST(Euler, OrderMeansWhichRotationIsAppliedFirst) {
    const double q = kPi / 2;
    // "xyz" with x = z = 90°: +Y → (about X) +Z → (about Z) +Z; +X → +X → +Y.
    const Mat3 xyz = euler_to_matrix({q, 0, q}, EulerOrder::xyz);
    expect_near(xyz * Vec3{0, 1, 0}, {0, 0, 1}, 1e-15);
    expect_near(xyz * Vec3{1, 0, 0}, {0, 1, 0}, 1e-15);
    // "zyx", same angles: +Y → (about Z) −X → (about X) −X; +X → +Y → +Z.
    const Mat3 zyx = euler_to_matrix({q, 0, q}, EulerOrder::zyx);
    expect_near(zyx * Vec3{0, 1, 0}, {-1, 0, 0}, 1e-15);
    expect_near(zyx * Vec3{1, 0, 0}, {0, 0, 1}, 1e-15);
    // The columns of R are the body axes in the parent frame.
    expect_near(xyz.column(1), xyz * Vec3{0, 1, 0}, 0.0);
}

TEST(Euler, RoundTripAwayFromGimbalLock) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> outer(-kPi + 1e-6, kPi - 1e-6);
    std::uniform_real_distribution<double> middle(-kPi / 2 + 0.01, kPi / 2 - 0.01);
    for (const EulerOrder order : kAllEulerOrders) {
        // The middle (second-applied) axis of each order.
        const std::size_t second = to_string(order)[1] - 'x';
        for (int i = 0; i < 500; ++i) {
            Vec3 a{outer(rng), outer(rng), outer(rng)};
            a[second] = middle(rng);
            const Vec3 back = matrix_to_euler(euler_to_matrix(a, order), order);
            expect_near(back, a, 1e-12);
            expect_near(quaternion_to_euler(euler_to_quaternion(a, order), order), a, 1e-12);
        }
    }
}

TEST(Euler, GimbalLockReproducesTheRotation) {
    for (const EulerOrder order : kAllEulerOrders) {
        const std::size_t second = to_string(order)[1] - 'x';
        const std::size_t first = to_string(order)[0] - 'x';
        for (const double lock : {kPi / 2, -kPi / 2}) {
            Vec3 a{0.4, -1.1, 2.2};
            a[second] = lock;
            const Mat3 m = euler_to_matrix(a, order);
            const Vec3 back = matrix_to_euler(m, order);
            EXPECT_EQ(back[first], 0.0) << to_string(order);
            EXPECT_NEAR(back[second], lock, 1e-7) << to_string(order);
            expect_near(euler_to_matrix(back, order), m, 1e-12);
        }
    }
}

TEST(Euler, ParseAndNameOrders) {
    for (const EulerOrder order : kAllEulerOrders) {
        EXPECT_EQ(parse_euler_order(to_string(order)), order);
    }
    EXPECT_EQ(parse_euler_order(" ZYX "), EulerOrder::zyx);
    EXPECT_EQ(parse_euler_order("Xzy"), EulerOrder::xzy);
    EXPECT_FALSE(parse_euler_order("zxz"));
    EXPECT_FALSE(parse_euler_order("xy"));
    EXPECT_FALSE(parse_euler_order("xyzz"));
    EXPECT_FALSE(parse_euler_order(""));
}

TEST(Euler, DegreesRadians) {
    expect_near(euler_deg_to_rad({180, -90, 45}), {kPi, -kPi / 2, kPi / 4}, 1e-15);
    expect_near(euler_rad_to_deg({kPi, -kPi / 2, kPi / 4}), {180, -90, 45}, 1e-12);
}

TEST(VehicleFrame, SignConventions) {
    const double a = 0.3;
    // Roll about Y, positive = right wing down.
    const Mat3 roll = vehicle_to_scene_rotation({a, 0, 0});
    EXPECT_LT((roll * kVehicleRight).z, 0.0);
    expect_near(roll * kVehicleForward, kVehicleForward, 1e-15);
    // Pitch about X, positive = nose up.
    const Mat3 pitch = vehicle_to_scene_rotation({0, a, 0});
    EXPECT_GT((pitch * kVehicleForward).z, 0.0);
    expect_near(pitch * kVehicleRight, kVehicleRight, 1e-15);
    // Yaw about Z, positive = counter-clockwise from above: the nose swings from north to west.
    const Mat3 yaw = vehicle_to_scene_rotation({0, 0, kPi / 2});
    expect_near(yaw * kVehicleForward, {-1, 0, 0}, 1e-15);
    expect_near(yaw * kVehicleUp, kVehicleUp, 1e-15);
    // Identity mounts and attitude look straight down.
    expect_near(vehicle_to_scene_rotation({}) * kInstrumentBoresight, {0, 0, -1}, 0.0);
    // Triple order (x, y, z) = (pitch, roll, yaw).
    const VehicleAttitude att{0.1, 0.2, 0.3};
    expect_near(to_euler_triple(att), {0.2, 0.1, 0.3}, 0.0);
    const VehicleAttitude back = to_vehicle_attitude(to_euler_triple(att));
    EXPECT_EQ(back.roll_rad, 0.1);
    EXPECT_EQ(back.pitch_rad, 0.2);
    EXPECT_EQ(back.yaw_rad, 0.3);
    expect_near(vehicle_to_scene_rotation(att, EulerOrder::zyx),
                euler_to_matrix({0.2, 0.1, 0.3}, EulerOrder::zyx), 0.0);
}

}  // namespace euler_test
}  // namespace glint::motion
