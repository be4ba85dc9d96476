// SPDX-License-Identifier: Apache-2.0
// Vec3 / Mat3 / Quaternion: algebra, the right-handed active rotation convention, quaternion ↔
// matrix in both directions (every branch of Shepperd's method), composition order and slerp.
#include "glint/motion/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "glint/test/angles.h"
#include "motion_expect.h"

namespace glint::motion {
namespace geometry_test {

using glint::test::kPi;

Quaternion random_rotation(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    return normalized(Quaternion{n(rng), n(rng), n(rng), n(rng)});
}

TEST(Vec3, Algebra) {
    constexpr Vec3 a{1, 2, 3}, b{4, -5, 6};
    static_assert(a + b == Vec3{5, -3, 9});
    static_assert(a - b == Vec3{-3, 7, -3});
    static_assert(2.0 * a == Vec3{2, 4, 6});
    static_assert(dot(a, b) == 4 - 10 + 18);
    static_assert(cross(Vec3{1, 0, 0}, Vec3{0, 1, 0}) == Vec3{0, 0, 1});
    static_assert(a[0] == 1 && a[1] == 2 && a[2] == 3);
    EXPECT_DOUBLE_EQ(norm(Vec3{3, 4, 12}), 13.0);
    expect_near(normalized(Vec3{0, 0, 5}), {0, 0, 1}, 0);
    EXPECT_EQ(normalized(Vec3{}), Vec3{});
    EXPECT_EQ(to_vec3(to_array(a)), a);
    Vec3 c = a;
    c += b;
    c -= a;
    c *= 2.0;
    EXPECT_EQ(c, (Vec3{8, -10, 12}));
    c[1] = 7.0;
    EXPECT_EQ(c.y, 7.0);
}

TEST(Mat3, ProductTransposeDeterminant) {
    const Mat3 a = Mat3::from_rows({1, 2, 3}, {4, 5, 6}, {7, 8, 10});
    EXPECT_EQ(a * Mat3::identity(), a);
    EXPECT_EQ(transpose(transpose(a)), a);
    EXPECT_EQ(transpose(a).row(0), (Vec3{1, 4, 7}));
    EXPECT_EQ(a.column(2), (Vec3{3, 6, 10}));
    EXPECT_EQ(Mat3::from_columns({1, 4, 7}, {2, 5, 8}, {3, 6, 10}), a);
    EXPECT_DOUBLE_EQ(determinant(a), -3.0);
    EXPECT_EQ((a * Vec3{1, 0, 0}), (Vec3{1, 4, 7}));
    const Mat3 b = Mat3::from_rows({0, 1, 0}, {1, 0, 0}, {0, 0, 2});
    // (a·b)·v = a·(b·v)
    const Vec3 v{0.3, -1.2, 2.5};
    expect_near((a * b) * v, a * (b * v), 1e-12);
}

TEST(Rotation, ElementaryAreActiveRightHanded) {
    const double q = kPi / 2;
    expect_near(rotation_x(q) * Vec3{0, 1, 0}, {0, 0, 1}, 1e-15);
    expect_near(rotation_y(q) * Vec3{0, 0, 1}, {1, 0, 0}, 1e-15);
    expect_near(rotation_z(q) * Vec3{1, 0, 0}, {0, 1, 0}, 1e-15);
    for (const Mat3& r : {rotation_x(0.7), rotation_y(-1.9), rotation_z(2.6)}) {
        EXPECT_NEAR(determinant(r), 1.0, 1e-15);
        expect_near(r * transpose(r), Mat3::identity(), 1e-15);
    }
}

TEST(Quaternion, AxisAngleMatchesElementaryMatrices) {
    const double angle = 0.83;
    expect_near(to_matrix(quaternion_from_axis_angle({1, 0, 0}, angle)), rotation_x(angle), 1e-15);
    expect_near(to_matrix(quaternion_from_axis_angle({0, 2, 0}, angle)), rotation_y(angle), 1e-15);
    expect_near(to_matrix(quaternion_from_axis_angle({0, 0, 9}, angle)), rotation_z(angle), 1e-15);
    EXPECT_EQ(quaternion_from_axis_angle({0, 0, 0}, 1.0), Quaternion::identity());
    EXPECT_EQ(normalized(Quaternion{0, 0, 0, 0}), Quaternion::identity());
}

TEST(Quaternion, RotateAgreesWithMatrixAndComposition) {
    std::mt19937_64 rng(42);
    for (int i = 0; i < 200; ++i) {
        const Quaternion a = random_rotation(rng), b = random_rotation(rng);
        const Vec3 v{0.3, -2.0, 1.1};
        expect_near(rotate(a, v), to_matrix(a) * v, 1e-14);
        // (a * b) applies b first, then a, for quaternions and matrices alike.
        expect_near(rotate(a * b, v), rotate(a, rotate(b, v)), 1e-14);
        expect_near(to_matrix(a * b), to_matrix(a) * to_matrix(b), 1e-14);
        expect_near(rotate(conjugate(a), rotate(a, v)), v, 1e-14);
        EXPECT_NEAR(determinant(to_matrix(a)), 1.0, 1e-14);
    }
}

TEST(Quaternion, FromMatrixRoundTripsEveryBranch) {
    std::mt19937_64 rng(7);
    for (int i = 0; i < 500; ++i) {
        const Quaternion q = random_rotation(rng);
        const Quaternion r = quaternion_from_matrix(to_matrix(q));
        expect_same_rotation(r, q, 1e-14);
        EXPECT_GE(r.w, 0.0);
    }
    // Half-turns drive the trace to −1 and select the x, y and z branches.
    for (const Vec3& axis :
         {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{1, 1, 1}, Vec3{-1, 2, 0.5}}) {
        for (const double angle : {kPi, kPi - 1e-9, 3.0, 0.0, 1e-9}) {
            const Quaternion q = quaternion_from_axis_angle(axis, angle);
            expect_same_rotation(quaternion_from_matrix(to_matrix(q)), q, 1e-13);
        }
    }
    EXPECT_EQ(quaternion_from_matrix(Mat3::identity()), Quaternion::identity());
}

TEST(Quaternion, SlerpEndpointsMidpointAndConstantSpeed) {
    const Quaternion a = Quaternion::identity();
    const Quaternion b = quaternion_from_axis_angle({0, 0, 1}, kPi / 2);
    expect_same_rotation(slerp(a, b, 0.0), a, 1e-15);
    expect_same_rotation(slerp(a, b, 1.0), b, 1e-15);
    expect_same_rotation(slerp(a, b, 0.5), quaternion_from_axis_angle({0, 0, 1}, kPi / 4), 1e-15);
    // −b is the same rotation: slerp must take the shorter arc and reach the same midpoint.
    const Quaternion minus_b{-b.w, -b.x, -b.y, -b.z};
    expect_same_rotation(slerp(a, minus_b, 0.5), quaternion_from_axis_angle({0, 0, 1}, kPi / 4),
                         1e-15);

    std::mt19937_64 rng(3);
    for (int i = 0; i < 50; ++i) {
        const Quaternion p = random_rotation(rng), q = random_rotation(rng);
        const double total = angle_between(p, q);
        for (const double t : {0.0, 0.1, 0.25, 0.5, 0.9, 1.0}) {
            const Quaternion s = slerp(p, q, t);
            EXPECT_NEAR(norm(s), 1.0, 1e-14);
            EXPECT_NEAR(angle_between(p, s), t * total, 1e-12);
            EXPECT_NEAR(angle_between(s, q), (1.0 - t) * total, 1e-12);
        }
    }
    // Nearly identical inputs.
    const Quaternion c = quaternion_from_axis_angle({1, 2, 3}, 1e-12);
    expect_same_rotation(slerp(a, c, 0.5), quaternion_from_axis_angle({1, 2, 3}, 0.5e-12), 1e-15);
}

TEST(Quaternion, AngleBetween) {
    const Quaternion a = quaternion_from_axis_angle({0, 1, 0}, 0.2);
    const Quaternion b = quaternion_from_axis_angle({0, 1, 0}, 1.4);
    EXPECT_NEAR(angle_between(a, b), 1.2, 1e-15);
    EXPECT_NEAR(angle_between(a, a), 0.0, 1e-15);
    EXPECT_NEAR(angle_between(Quaternion::identity(), quaternion_from_axis_angle({1, 0, 0}, kPi)),
                kPi, 1e-15);
}

}  // namespace geometry_test
}  // namespace glint::motion
