// SPDX-License-Identifier: Apache-2.0
// Rigid transforms: point/direction mapping, composition order (right to left), inverse round
// trips and associativity on random transforms.
#include "glint/motion/rigid.h"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "glint/test/angles.h"
#include "motion_expect.h"

namespace glint::motion {
namespace rigid_test {

using glint::test::kPi;

Rigid random_rigid(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    return {normalized(Quaternion{n(rng), n(rng), n(rng), n(rng)}),
            {10 * n(rng), 10 * n(rng), 10 * n(rng)}};
}

TEST(Rigid, IdentityLeavesPointsAndDirections) {
    const Rigid id = Rigid::identity();
    expect_near(apply_point(id, {1, 2, 3}), {1, 2, 3}, 0.0);
    expect_near(apply_direction(id, {1, 2, 3}), {1, 2, 3}, 0.0);
}

TEST(Rigid, PointGetsRotationThenTranslationDirectionOnlyRotation) {
    const Rigid a{quaternion_from_axis_angle({0, 0, 1}, kPi / 2), {10, 0, 0}};
    expect_near(apply_point(a, {1, 0, 0}), {10, 1, 0}, 1e-15);
    expect_near(apply_direction(a, {1, 0, 0}), {0, 1, 0}, 1e-15);
}

TEST(Rigid, CompositionAppliesRightOperandFirst) {
    const Rigid rotate_z{quaternion_from_axis_angle({0, 0, 1}, kPi / 2), {}};
    const Rigid shift_x = rigid_translation({5, 0, 0});
    // rotate_z * shift_x: shift first, then rotate: (1,0,0) → (6,0,0) → (0,6,0).
    expect_near(apply_point(rotate_z * shift_x, {1, 0, 0}), {0, 6, 0}, 1e-14);
    // shift_x * rotate_z: rotate first, then shift: (1,0,0) → (0,1,0) → (5,1,0).
    expect_near(apply_point(shift_x * rotate_z, {1, 0, 0}), {5, 1, 0}, 1e-14);
    expect_near(apply_point(compose(shift_x, rotate_z), {1, 0, 0}), {5, 1, 0}, 1e-14);
}

TEST(Rigid, RandomCompositionMatchesSequentialApplication) {
    std::mt19937_64 rng(7);
    for (int i = 0; i < 200; ++i) {
        const Rigid a = random_rigid(rng), b = random_rigid(rng), c = random_rigid(rng);
        const Vec3 p{1.5, -2.0, 0.25};
        expect_near(apply_point(a * b, p), apply_point(a, apply_point(b, p)), 1e-12);
        expect_near(apply_point((a * b) * c, p), apply_point(a * (b * c), p), 1e-12);
        expect_near(apply_direction(a * b, p), apply_direction(a, apply_direction(b, p)), 1e-12);
    }
}

TEST(Rigid, InverseRoundTrips) {
    std::mt19937_64 rng(11);
    for (int i = 0; i < 200; ++i) {
        const Rigid a = random_rigid(rng);
        const Vec3 p{3.0, -1.0, 7.0};
        expect_near(apply_point(inverse(a), apply_point(a, p)), p, 1e-12);
        const Rigid id = a * inverse(a);
        expect_near(id.translation_m, {0, 0, 0}, 1e-12);
        EXPECT_NEAR(angle_between(id.rotation, Quaternion::identity()), 0.0, 1e-7);
    }
}

TEST(Rigid, CompositionStaysUnitQuaternion) {
    std::mt19937_64 rng(3);
    Rigid chain = Rigid::identity();
    for (int i = 0; i < 10000; ++i) chain = chain * random_rigid(rng);
    EXPECT_NEAR(norm(chain.rotation), 1.0, 1e-14);
}

}  // namespace rigid_test
}  // namespace glint::motion
