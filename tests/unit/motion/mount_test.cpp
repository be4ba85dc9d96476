// SPDX-License-Identifier: Apache-2.0
// Mount kinematics and affine placements: static tilts and their sign, nesting order,
// affine translations, commanded interpolation, tabulated periodicity, whisk scans, tracking
// accuracy for a moving parent, rigidity checks of 4x4 matrices, and the errors.
#include "glint/motion/mount.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/error.h"
#include "glint/motion/euler.h"
#include "glint/motion/frames.h"
#include "glint/test/angles.h"
#include "glint/test/errors.h"
#include "motion_expect.h"

namespace glint::motion {
namespace mount_test {

using glint::test::kDeg;
using glint::test::kPi;

Vec3 boresight(const Rigid& r) { return apply_direction(r, kInstrumentBoresight); }

model::Mount static_mount(std::array<double, 3> rotation_rad, std::string order = "xyz") {
    model::Mount m;
    m.name = "M";
    m.type = model::MountType::static_mount;
    m.rotation_rad = rotation_rad;
    m.rotation_order = std::move(order);
    return m;
}

model::MountEntry entry(double t, std::array<double, 3> rot, std::array<double, 3> trans = {}) {
    model::MountEntry e;
    e.time_s = t;
    e.rotation_rad = rot;
    e.translation_m = trans;
    return e;
}

TEST(Mount, StaticIdentityLooksDown) {
    const Rigid r = mount_transform(static_mount({0, 0, 0}), 0.0);
    expect_near(boresight(r), {0, 0, -1}, 0.0);
    expect_near(r.translation_m, {0, 0, 0}, 0.0);
}

// Convention check: a positive rotation about X (active, right-handed: +Y towards +Z) takes
// −Z towards +Y, so a +30° X mount tilts the boresight 30° FORWARD (towards vehicle +Y,
// the direction of flight); a +30° Y rotation tilts it towards −X (left wing).
TEST(Mount, StaticThirtyDegreesAboutXTiltsForward) {
    const Vec3 b = boresight(mount_transform(static_mount({30 * kDeg, 0, 0}), 0.0));
    expect_near(b, {0, std::sin(30 * kDeg), -std::cos(30 * kDeg)}, 1e-15);
    EXPECT_NEAR(std::acos(-b.z), 30 * kDeg, 1e-12);
    EXPECT_GT(b.y, 0.0);  // forward
    const Vec3 back = boresight(mount_transform(static_mount({-30 * kDeg, 0, 0}), 0.0));
    EXPECT_LT(back.y, 0.0);  // aft
    const Vec3 left = boresight(mount_transform(static_mount({0, 30 * kDeg, 0}), 0.0));
    expect_near(left, {-std::sin(30 * kDeg), 0, -std::cos(30 * kDeg)}, 1e-15);
}

TEST(Mount, StaticUsesRotationOrder) {
    const std::array<double, 3> angles{0.3, -0.2, 1.1};
    for (const EulerOrder order : kAllEulerOrders) {
        const Rigid r = mount_transform(static_mount(angles, std::string(to_string(order))), 0.0);
        const Quaternion expected = euler_to_quaternion(to_vec3(angles), order);
        EXPECT_NEAR(angle_between(r.rotation, expected), 0.0, 1e-7) << to_string(order);
    }
}

// Outermost first: instrument_to_vehicle = A0 · M0 · A1 · M1. A yaw of 90° outside a 30°
// forward tilt turns the tilted boresight to the vehicle's left (−X); the other nesting
// (tilt outside the yaw) leaves it tilted forward.
TEST(Mount, NestedMountsComposeOutermostFirst) {
    const Rigid yaw = mount_transform(static_mount({0, 0, 90 * kDeg}), 0.0);
    const Rigid tilt = mount_transform(static_mount({30 * kDeg, 0, 0}), 0.0);
    const double s = std::sin(30 * kDeg), c = std::cos(30 * kDeg);
    expect_near(boresight(yaw * tilt), {-s, 0, -c}, 1e-15);  // yaw outermost
    expect_near(boresight(tilt * yaw), {0, s, -c}, 1e-15);   // tilt outermost
}

TEST(Mount, AffineTranslationMovesTheInstrumentOrigin) {
    model::AffineTransform a;
    a.translation_m = {1.5, -0.25, 0.1};
    const Rigid r = affine_transform(a);
    expect_near(apply_point(r, {0, 0, 0}), {1.5, -0.25, 0.1}, 0.0);
    expect_near(boresight(r), {0, 0, -1}, 0.0);
    // Placement outside a mount: the mount rotates about the attachment point, which moves
    // with the translation.
    const Rigid chain = r * mount_transform(static_mount({0, 0, kPi / 2}), 0.0);
    expect_near(apply_point(chain, {1, 0, 0}), {1.5, 0.75, 0.1}, 1e-15);
}

TEST(Mount, AffineRotationAndMatrixAgree) {
    model::AffineTransform euler;
    euler.translation_m = {2, 3, 4};
    euler.rotation_rad = {0.1, 0.2, 0.3};
    euler.rotation_order = "zyx";
    const Rigid a = affine_transform(euler);
    const Mat3 r = euler_to_matrix({0.1, 0.2, 0.3}, EulerOrder::zyx);
    model::AffineTransform matrix;
    matrix.matrix =
        std::array<double, 16>{r(0, 0), r(0, 1), r(0, 2), 2, r(1, 0), r(1, 1), r(1, 2), 3,
                               r(2, 0), r(2, 1), r(2, 2), 4, 0,       0,       0,       1};
    const Rigid b = affine_transform(matrix);
    EXPECT_NEAR(angle_between(a.rotation, b.rotation), 0.0, 1e-7);
    expect_near(a.translation_m, b.translation_m, 0.0);
    expect_near(apply_point(b, {1, 1, 1}), r * Vec3{1, 1, 1} + Vec3{2, 3, 4}, 1e-14);
}

TEST(Mount, AffineMatrixNotRigidIsAnError) {
    model::AffineTransform scaled;
    scaled.where = {"cam.platform", 12, "platform/attachment/affinetransform"};
    scaled.matrix = std::array<double, 16>{2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const std::string msg = test::error_text([&] { affine_transform(scaled); });
    EXPECT_THAT(msg, testing::HasSubstr("cam.platform:12:"));
    EXPECT_THAT(msg, testing::HasSubstr("matrix is not rigid"));

    model::AffineTransform sheared = scaled;
    sheared.matrix = std::array<double, 16>{1, 0.1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    EXPECT_THAT(test::error_text([&] { affine_transform(sheared); }),
                testing::HasSubstr("not a rotation"));

    model::AffineTransform mirror = scaled;
    mirror.matrix = std::array<double, 16>{-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    EXPECT_THAT(test::error_text([&] { affine_transform(mirror); }),
                testing::HasSubstr("reflection"));

    model::AffineTransform projective = scaled;
    projective.matrix = std::array<double, 16>{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 0, 1};
    EXPECT_THAT(test::error_text([&] { affine_transform(projective); }),
                testing::HasSubstr("last row is not 0 0 0 1"));

    model::AffineTransform bad_order;
    bad_order.rotation_order = "xxz";
    EXPECT_THAT(test::error_text([&] { affine_transform(bad_order); }),
                testing::HasSubstr("unknown rotation order \"xxz\""));
}

TEST(Mount, CommandedInterpolatesAndClamps) {
    model::Mount m;
    m.type = model::MountType::commanded;
    m.type_text = "commanded";
    m.entries = {entry(0.0, {0, -10 * kDeg, 0}), entry(1.5, {0, 0, 0}, {0.5, 0, -0.2}),
                 entry(3.0, {0, 10 * kDeg, 0})};
    ASSERT_NO_THROW(validate_mount(m));
    EXPECT_TRUE(mount_is_time_varying(m));
    const auto y_angle = [&](double t) {
        return quaternion_to_euler(mount_transform(m, t).rotation, EulerOrder::xyz).y;
    };
    EXPECT_NEAR(y_angle(-5.0), -10 * kDeg, 1e-12);  // held before the table
    EXPECT_NEAR(y_angle(0.75), -5 * kDeg, 1e-12);   // slerp about one axis is linear in angle
    EXPECT_NEAR(y_angle(1.5), 0.0, 1e-12);
    EXPECT_NEAR(y_angle(2.25), 5 * kDeg, 1e-12);
    EXPECT_NEAR(y_angle(99.0), 10 * kDeg, 1e-12);  // held after
    expect_near(mount_transform(m, 0.75).translation_m, {0.25, 0, -0.1}, 1e-15);
    expect_near(mount_transform(m, 2.25).translation_m, {0.25, 0, -0.1}, 1e-15);
    expect_near(mount_transform(m, 10.0).translation_m, {0, 0, 0}, 0.0);
}

TEST(Mount, CommandedSlerpsBetweenGeneralRotations) {
    model::Mount m;
    m.type = model::MountType::commanded;
    m.rotation_order = "zyx";
    m.entries = {entry(1.0, {0.2, 0.4, -0.5}), entry(2.0, {-0.3, 0.1, 1.0})};
    const Quaternion a = euler_to_quaternion({0.2, 0.4, -0.5}, EulerOrder::zyx);
    const Quaternion b = euler_to_quaternion({-0.3, 0.1, 1.0}, EulerOrder::zyx);
    for (const double u : {0.0, 0.3, 0.5, 1.0}) {
        EXPECT_NEAR(angle_between(mount_transform(m, 1.0 + u).rotation, slerp(a, b, u)), 0.0, 1e-7);
    }
}

TEST(Mount, TabulatedRepeatsWithPeriod) {
    // mounts.platform "Tabulated2": −20° at 0 s, +20° at 2 s about Y, period 4 s: a triangle.
    model::Mount m;
    m.type = model::MountType::tabulated;
    m.type_text = "tabulated";
    m.entries = {entry(0.0, {0, -20 * kDeg, 0}), entry(2.0, {0, 20 * kDeg, 0})};
    m.period_s = 4.0;
    ASSERT_NO_THROW(validate_mount(m));
    const auto y_angle = [&](double t) {
        return quaternion_to_euler(mount_transform(m, t).rotation, EulerOrder::xyz).y;
    };
    EXPECT_NEAR(y_angle(0.0), -20 * kDeg, 1e-12);
    EXPECT_NEAR(y_angle(1.0), 0.0, 1e-12);
    EXPECT_NEAR(y_angle(2.0), 20 * kDeg, 1e-12);
    EXPECT_NEAR(y_angle(3.0), 0.0, 1e-12);  // last → first of the next period
    for (const double t : {0.0, 0.3, 1.7, 2.5, 3.9}) {
        for (const int k : {-3, -1, 1, 2, 25}) {
            EXPECT_NEAR(y_angle(t + 4.0 * k), y_angle(t), 1e-9) << t << " + " << k << " periods";
        }
    }
}

TEST(Mount, TabulatedDefaultPeriodIsTheLastTime) {
    // The reader sets period_s to the last entry time when none is given; the table then
    // jumps back to the first entry.
    model::Mount m;
    m.type = model::MountType::tabulated;
    m.entries = {entry(0.0, {0, 0, 0}), entry(1.0, {0, 0, 0.5})};
    m.period_s = 1.0;
    const auto z_angle = [&](double t) {
        return quaternion_to_euler(mount_transform(m, t).rotation, EulerOrder::xyz).z;
    };
    EXPECT_NEAR(z_angle(0.5), 0.25, 1e-12);
    EXPECT_NEAR(z_angle(1.5), 0.25, 1e-12);
    EXPECT_NEAR(z_angle(2.0), 0.0, 1e-12);
    EXPECT_NEAR(z_angle(-0.25), 0.375, 1e-12);
    // A single entry without a period is constant.
    model::Mount one = m;
    one.entries = {entry(0.0, {0.1, 0, 0})};
    one.period_s.reset();
    EXPECT_FALSE(mount_is_time_varying(one));
    EXPECT_NEAR(quaternion_to_euler(mount_transform(one, 123.0).rotation, EulerOrder::xyz).x, 0.1,
                1e-12);
}

TEST(Mount, WhiskSinusoidPeaksAtQuarterPeriod) {
    model::WhiskScan s;
    s.axis = model::WhiskScan::Axis::across_track;
    s.min_angle_rad = -15 * kDeg;
    s.max_angle_rad = 25 * kDeg;
    s.rate_hz = 10.0;
    EXPECT_NEAR(whisk_angle_rad(s, 0.0), 5 * kDeg, 1e-15);      // centre
    EXPECT_NEAR(whisk_angle_rad(s, 0.025), 25 * kDeg, 1e-12);   // quarter period: max
    EXPECT_NEAR(whisk_angle_rad(s, 0.075), -15 * kDeg, 1e-12);  // three quarters: min
    EXPECT_NEAR(whisk_angle_rad(s, 0.125), 25 * kDeg, 1e-12);   // periodic
    s.phase_rad = kPi / 2;
    EXPECT_NEAR(whisk_angle_rad(s, 0.0), 25 * kDeg, 1e-12);  // phase 90°: starts at max

    model::Mount m;
    m.type = model::MountType::whisk;
    m.whisk = s;
    m.whisk->phase_rad = 0.0;
    ASSERT_NO_THROW(validate_mount(m));
    // Across-track = about Y: the boresight swings in the X–Z plane (positive towards −X).
    const Vec3 b = boresight(mount_transform(m, 0.025));
    expect_near(b, {-std::sin(25 * kDeg), 0, -std::cos(25 * kDeg)}, 1e-12);
    m.whisk->axis = model::WhiskScan::Axis::along_track;  // about X: forward for positive
    expect_near(boresight(mount_transform(m, 0.025)),
                {0, std::sin(25 * kDeg), -std::cos(25 * kDeg)}, 1e-12);
}

TEST(Mount, WhiskLinearIsASawtooth) {
    model::WhiskScan s;
    s.min_angle_rad = -0.2;
    s.max_angle_rad = 0.2;
    s.rate_hz = 2.0;  // period 0.5 s
    s.sinusoidal = false;
    EXPECT_NEAR(whisk_angle_rad(s, 0.0), 0.0, 1e-15);       // centre, rising
    EXPECT_NEAR(whisk_angle_rad(s, 0.0625), 0.05, 1e-12);   // 0.8 rad/s sweep
    EXPECT_NEAR(whisk_angle_rad(s, 0.2499999), 0.2, 1e-6);  // just before the fly-back
    EXPECT_NEAR(whisk_angle_rad(s, 0.25), -0.2, 1e-12);     // fly-back at half a period
    EXPECT_NEAR(whisk_angle_rad(s, 0.375), -0.1, 1e-12);
    EXPECT_NEAR(whisk_angle_rad(s, 0.5), 0.0, 1e-12);  // one period later
    // Linear in between: equal steps.
    EXPECT_NEAR(whisk_angle_rad(s, 0.1) - whisk_angle_rad(s, 0.05),
                whisk_angle_rad(s, 0.15) - whisk_angle_rad(s, 0.1), 1e-12);
}

/// A target that moves east at 20 m/s.
class MovingTarget : public TargetResolver {
public:
    std::optional<Vec3> target_position_m(std::string_view name, double t_s) const override {
        if (name != "truck_01") return std::nullopt;
        return Vec3{100.0 + 20.0 * t_s, -50.0, 0.0};
    }
};

TEST(Mount, TrackingPointsBoresightAtTheTargetFromAMovingParent) {
    model::Mount m;
    m.name = "Tracker";
    m.type = model::MountType::tracking;
    m.tracking = model::TrackingTarget{};
    m.tracking->name = "truck_01";
    m.tracking->offset_m = {0, 1.5, 2};
    ASSERT_NO_THROW(validate_mount(m));
    const MovingTarget targets;
    for (double t = 0.0; t <= 10.0; t += 0.37) {
        // A vehicle flying north at 100 m/s, 1 km up, yawing and banking with time, with the
        // mount on an attachment 0.5 m below the vehicle origin.
        const Rigid vehicle{
            euler_to_quaternion({0.05 * t, 0.2 * std::sin(t), 0.1 * t}, EulerOrder::xyz),
            {0.0, -500.0 + 100.0 * t, 1000.0}};
        const Rigid parent = vehicle * rigid_translation({0, 0, -0.5});
        MountContext context;
        context.parent_to_scene = parent;
        context.targets = &targets;
        const Rigid mount_to_scene = parent * mount_transform(m, t, context);
        const Vec3 target = *targets.target_position_m("truck_01", t) + Vec3{0, 1.5, 2};
        const Vec3 wanted = normalized(target - mount_to_scene.translation_m);
        const Vec3 got = boresight(mount_to_scene);
        EXPECT_LT(std::atan2(norm(cross(got, wanted)), dot(got, wanted)), 1e-9) << "t=" << t;
        EXPECT_NEAR(norm(got), 1.0, 1e-14);
    }
}

TEST(Mount, TrackingFixedPointAndRollConvention) {
    model::Mount m;
    m.type = model::MountType::tracking;
    m.tracking = model::TrackingTarget{};
    m.tracking->point_m = {0, 0, -1000};
    MountContext context;
    context.parent_to_scene = rigid_translation({0, 0, 0});
    // Straight down: the identity.
    EXPECT_NEAR(angle_between(mount_transform(m, 0.0, context).rotation, Quaternion::identity()),
                0.0, 1e-7);
    // Forward and down: a pure rotation about X (mount +Y stays in the Y–Z plane, forward).
    m.tracking->point_m = {0, 1000, -1000};
    const Rigid r = mount_transform(m, 0.0, context);
    EXPECT_NEAR(angle_between(r.rotation, quaternion_from_axis_angle({1, 0, 0}, kPi / 4)), 0.0,
                1e-7);
    // Looking straight forward (degenerate for the +Y rule): +Z takes its place.
    expect_near(apply_direction(rigid_rotation(tracking_rotation({0, 1, 0})), kInstrumentBoresight),
                {0, 1, 0}, 1e-15);
    expect_near(apply_direction(rigid_rotation(tracking_rotation({0, 1, 0})), {1, 0, 0}), {1, 0, 0},
                1e-15);
}

TEST(Mount, TrackingErrors) {
    model::Mount m;
    m.name = "Tracker";
    m.where = {"mounts.platform", 160, "platform/attachment/mount[Tracker]"};
    m.type = model::MountType::tracking;
    m.tracking = model::TrackingTarget{};
    m.tracking->name = "truck_01";
    MountContext context;
    context.parent_to_scene = Rigid::identity();
    EXPECT_THAT(test::error_text([&] { mount_transform(m, 0.0, context); }),
                testing::HasSubstr("mounts.platform:160: platform/attachment/mount[Tracker]: "
                                   "mount \"Tracker\": tracking a named target (\"truck_01\") "
                                   "needs the scene (its instances are the targets)"));
    const MovingTarget targets;
    context.targets = &targets;
    m.tracking->name = "car_02";
    EXPECT_THAT(test::error_text([&] { mount_transform(m, 0.0, context); }),
                testing::HasSubstr("the scene has no target named \"car_02\""));
    EXPECT_THAT(test::error_text([&] { mount_transform(m, 0.0, {}); }),
                testing::HasSubstr("needs the parent-to-scene transform"));
    m.tracking = model::TrackingTarget{};
    EXPECT_THAT(test::error_text([&] { validate_mount(m); }), testing::HasSubstr("has no target"));
}

TEST(Mount, ValidateRejectsBadTables) {
    model::Mount m;
    m.name = "Pointer";
    m.type = model::MountType::commanded;
    m.type_text = "commanded";
    EXPECT_THAT(test::error_text([&] { validate_mount(m); }), testing::HasSubstr("has no entries"));
    EXPECT_THAT(test::error_text([&] { mount_transform(m, 0.0); }),
                testing::HasSubstr("has no entries"));
    m.entries = {entry(1.0, {}), entry(1.0, {})};
    EXPECT_THAT(test::error_text([&] { validate_mount(m); }),
                testing::HasSubstr("not strictly increasing"));
    m.entries = {entry(1.0, {})};
    m.rotation_order = "abc";
    EXPECT_THAT(test::error_text([&] { validate_mount(m); }),
                testing::HasSubstr("unknown rotation order"));
    model::Mount w;
    w.type = model::MountType::whisk;
    EXPECT_THAT(test::error_text([&] { validate_mount(w); }), testing::HasSubstr("has no scan"));
    w.whisk = model::WhiskScan{};
    EXPECT_THAT(test::error_text([&] { validate_mount(w); }),
                testing::HasSubstr("rate must be > 0"));
}

}  // namespace mount_test
}  // namespace glint::motion
