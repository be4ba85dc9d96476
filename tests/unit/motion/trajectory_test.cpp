// SPDX-License-Identifier: Apache-2.0
// Tests of the trajectories built in code against closed-form answers: straight lines,
// geodetic and ECEF waypoints through SceneFrame, the waypoint clamp's one warning,
// velocity-aligned and look-at frames, Euler and quaternion tables, spin, and the models the
// trajectory refuses. tests/integration/motion/trajectory_files_test.cpp runs DIRSIG's motion
// files (GenericMotion, TLEs) through the reader.
#include "glint/motion/trajectory.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "glint/motion/euler.h"
#include "glint/test/angles.h"
#include "motion_expect.h"

namespace glint::motion {
namespace trajectory_test {

using ::testing::HasSubstr;

using glint::test::kDeg;

/// A FlexMotion with the given engines.
model::FlexMotion flex(model::LocationEngine location, model::OrientationEngine orientation) {
    model::FlexMotion f;
    f.location = std::move(location);
    f.orientation = std::move(orientation);
    return f;
}

model::LocationEngine straight(double heading_deg, double speed_m_s, const Vec3& start) {
    model::LocationEngine e;
    e.type = model::LocationEngineType::straight;
    e.heading_rad = heading_deg * kDeg;
    e.speed_m_s = speed_m_s;
    e.location.xyz_m = to_array(start);
    return e;
}

model::LocationEngine fixed_at(const Vec3& p) {
    model::LocationEngine e;
    e.type = model::LocationEngineType::fixed;
    e.location.xyz_m = to_array(p);
    return e;
}

model::LocationEngine waypoints(const std::vector<std::array<double, 4>>& rows,
                                model::LocationFrame frame = model::LocationFrame::scene) {
    model::LocationEngine e;
    e.type = model::LocationEngineType::waypoints;
    e.waypoint_frame = frame;
    e.where = {"w.motion", 3, "motion/locationengine"};
    for (const auto& r : rows) e.waypoints.push_back({r[0], {r[1], r[2], r[3], 0.0}, 0});
    return e;
}

model::OrientationEngine velocity_aligned(const Vec3& up = {0, 0, 1}) {
    model::OrientationEngine o;
    o.type = model::OrientationEngineType::velocity;
    o.up.vector = to_array(up);
    return o;
}

const SceneFrame kScene(43.0, -78.0, 150.0);
const DateTime kReference = parse_iso8601("2020-06-21T12:00:00Z");

// ---- location engines -----------------------------------------------------------------------

TEST(Trajectory, StraightLinePositionAndVelocity) {
    const auto east = make_trajectory(
        flex(straight(90, 100, {-400, 400, 50000}), velocity_aligned()), kScene, kReference);
    expect_near(east->pose_at(0).position_m, {-400, 400, 50000}, 1e-9);
    expect_near(east->pose_at(10).position_m, {600, 400, 50000}, 1e-9);
    expect_near(east->pose_at(-2.5).position_m, {-650, 400, 50000}, 1e-9);
    expect_near(east->velocity_m_s(3), {100, 0, 0}, 1e-12);
    EXPECT_FALSE(east->span());
    // Velocity-aligned: nose east, right wing south, top up.
    const Quaternion q = east->pose_at(1).orientation;
    expect_near(rotate(q, kVehicleForward), {1, 0, 0}, 1e-12);
    expect_near(rotate(q, kVehicleRight), {0, -1, 0}, 1e-12);
    expect_near(rotate(q, kVehicleUp), {0, 0, 1}, 1e-12);

    // Heading clockwise from north: 0 = north, 30° = (sin 30°, cos 30°).
    const auto north =
        make_trajectory(flex(straight(0, 10, {}), velocity_aligned()), kScene, kReference);
    expect_near(north->pose_at(2).position_m, {0, 20, 0}, 1e-12);
    EXPECT_NEAR(angle_between(north->pose_at(2).orientation, Quaternion::identity()), 0, 1e-12);
    const auto thirty =
        make_trajectory(flex(straight(30, 2, {}), velocity_aligned()), kScene, kReference);
    expect_near(thirty->pose_at(1).position_m, {1, std::sqrt(3.0), 0}, 1e-12);
}

TEST(Trajectory, GeodeticAndEcefWaypointsGoThroughTheSceneFrame) {
    const std::vector<Geodetic> points = {{43.01, -78.02, 1000}, {43.02, -77.99, 1500}};
    const auto geodetic = make_trajectory(
        flex(
            waypoints({{0, points[0].latitude_deg, points[0].longitude_deg, points[0].altitude_m},
                       {10, points[1].latitude_deg, points[1].longitude_deg, points[1].altitude_m}},
                      model::LocationFrame::geodetic),
            velocity_aligned()),
        kScene, kReference);
    const Vec3 a = kScene.geodetic_to_enu(points[0]);
    const Vec3 b = kScene.geodetic_to_enu(points[1]);
    expect_near(geodetic->pose_at(0).position_m, a, 1e-6);
    expect_near(geodetic->pose_at(10).position_m, b, 1e-6);
    expect_near(geodetic->pose_at(5).position_m, 0.5 * (a + b), 1e-6);  // linear in scene ENU

    const Vec3 ea = kScene.enu_to_ecef({100, 200, 300});
    const Vec3 eb = kScene.enu_to_ecef({-100, 0, 700});
    const auto ecef = make_trajectory(
        flex(waypoints({{0, ea.x, ea.y, ea.z}, {4, eb.x, eb.y, eb.z}}, model::LocationFrame::ecef),
             velocity_aligned()),
        kScene, kReference);
    expect_near(ecef->pose_at(0).position_m, {100, 200, 300}, 1e-6);
    expect_near(ecef->pose_at(2).position_m, {0, 100, 500}, 1e-6);
    expect_near(ecef->velocity_m_s(1), {-50, -50, 100}, 1e-6);
}

// ---- GenericMotion --------------------------------------------------------------------------

TEST(Trajectory, WaypointClampWarnsOnceAndNamesTheTable) {
    Warnings warnings;
    const auto t =
        make_trajectory(flex(waypoints({{0, 0, 0, 0}, {10, 100, 0, 0}}), velocity_aligned()),
                        kScene, kReference, warnings.log());
    expect_near(t->pose_at(-3).position_m, {0, 0, 0}, 0);
    expect_near(t->pose_at(12).position_m, {100, 0, 0}, 0);
    // Outside the span the velocity (and so the velocity-aligned frame) is the end's.
    expect_near(t->velocity_m_s(12), {10, 0, 0}, 1e-12);
    expect_near(rotate(t->pose_at(12).orientation, kVehicleForward), {1, 0, 0}, 1e-12);
    ASSERT_EQ(warnings.items.size(), 1u);
    EXPECT_EQ(warnings.items[0],
              "w.motion:3: motion/locationengine: time -3 s is outside the waypoint times (0 s "
              "to 10 s); the pose is held at the nearest end (warned once per motion)");
}

// ---- orientation engines --------------------------------------------------------------------

TEST(Trajectory, VelocityFrameFollowsTheVelocityWithUpTowardsTheConstraint) {
    const Vec3 up = normalized(Vec3{0.2, -0.1, 1.0});
    const auto t =
        make_trajectory(flex(waypoints({{0, 0, 0, 0}, {1, 3, 4, 5}, {2, 3, 4, 5}, {3, 3, 10, 5}}),
                             velocity_aligned(up)),
                        kScene, kReference);
    const Quaternion q = t->pose_at(0.5).orientation;
    const Vec3 x = rotate(q, kVehicleRight);
    const Vec3 y = rotate(q, kVehicleForward);
    const Vec3 z = rotate(q, kVehicleUp);
    const Vec3 v = normalized(Vec3{3, 4, 5});
    expect_near(y, v, 1e-12);
    expect_near(z, normalized(up - dot(up, v) * v), 1e-12);  // up as close to the constraint
    expect_near(cross(x, y), z, 1e-12);                      // right-handed
    // A pause (t in [1, 2]) keeps the direction of the nearest motion (the previous segment).
    expect_near(rotate(t->pose_at(1.5).orientation, kVehicleForward), v, 1e-12);
    expect_near(rotate(t->pose_at(2.5).orientation, kVehicleForward), {0, 1, 0}, 1e-12);
    // A fixed platform has no velocity: nose north, level.
    const auto still =
        make_trajectory(flex(fixed_at({1, 2, 3}), velocity_aligned()), kScene, kReference);
    EXPECT_NEAR(angle_between(still->pose_at(7).orientation, Quaternion::identity()), 0, 1e-12);
    expect_near(still->pose_at(7).position_m, {1, 2, 3}, 0);
    // Straight up with up = +Z: the right wing points east (as if pitched up from level
    // flight to the north), so the top faces south.
    const auto climb = make_trajectory(
        flex(waypoints({{0, 0, 0, 0}, {1, 0, 0, 10}}), velocity_aligned()), kScene, kReference);
    const Quaternion c = climb->pose_at(0.5).orientation;
    expect_near(rotate(c, kVehicleForward), {0, 0, 1}, 1e-12);
    expect_near(rotate(c, kVehicleRight), {1, 0, 0}, 1e-12);
    expect_near(rotate(c, kVehicleUp), {0, -1, 0}, 1e-12);
}

TEST(Trajectory, LookAtPutsTheBoresightOnTheTarget) {
    model::OrientationEngine look;
    look.type = model::OrientationEngineType::lookat;
    look.target = fixed_at({100, 200, 0});
    const Vec3 up{0, 0, 1};
    const auto t =
        make_trajectory(flex(straight(45, 50, {-1000, -300, 3000}), look), kScene, kReference);
    for (const double time : {0.0, 7.0, 30.0}) {
        const Pose p = t->pose_at(time);
        const Vec3 to_target = normalized(Vec3{100, 200, 0} - p.position_m);
        expect_near(rotate(p.orientation, kInstrumentBoresight), to_target, 1e-12);
        const Vec3 y = rotate(p.orientation, kVehicleForward);
        const Vec3 z = rotate(p.orientation, kVehicleUp);
        expect_near(y, normalized(up - dot(up, z) * z), 1e-12);  // +Y towards the up hint
        expect_near(cross(rotate(p.orientation, kVehicleRight), y), z, 1e-12);
    }
    // Straight down with up = +Z: north stands in, giving the identity (nadir, nose north).
    const auto nadir = make_trajectory(flex(fixed_at({100, 200, 500}), look), kScene, kReference);
    EXPECT_NEAR(angle_between(nadir->pose_at(0).orientation, Quaternion::identity()), 0, 1e-12);
    // A moving target given as a nested engine; up along the platform velocity.
    look.target = straight(180, 10, {0, 0, 0});
    look.up.type = model::DirectionType::velocity;
    const auto chase =
        make_trajectory(flex(straight(90, 20, {0, 100, 1000}), look), kScene, kReference);
    const Pose p = chase->pose_at(4);
    expect_near(rotate(p.orientation, kInstrumentBoresight),
                normalized(Vec3{0, -40, 0} - Vec3{80, 100, 1000}), 1e-12);
    EXPECT_GT(dot(rotate(p.orientation, kVehicleForward), Vec3{1, 0, 0}), 0.0);
}

model::OrientationEngine euler_table(const std::vector<std::array<double, 4>>& rows_deg,
                                     const std::string& order) {
    model::OrientationEngine o;
    o.type = model::OrientationEngineType::euler;
    o.rotation_order = order;
    o.where = {"e.motion", 4, "motion/orientationengine"};
    for (const auto& r : rows_deg) {
        o.table.push_back({r[0], {r[1] * kDeg, r[2] * kDeg, r[3] * kDeg, 0.0}, 0});
    }
    return o;
}

TEST(Trajectory, EulerTableInterpolatesWithItsRotationOrder) {
    const auto t = make_trajectory(
        flex(fixed_at({}), euler_table({{0, 0, 0, 0}, {4, 0, 0, 90}, {8, 0, 0, 90}}, "zyx")),
        kScene, kReference);
    EXPECT_NEAR(
        angle_between(t->pose_at(2).orientation, quaternion_from_axis_angle({0, 0, 1}, 45 * kDeg)),
        0, 1e-12);
    EXPECT_NEAR(
        angle_between(t->pose_at(6).orientation, quaternion_from_axis_angle({0, 0, 1}, 90 * kDeg)),
        0, 1e-12);
    ASSERT_TRUE(t->span());
    EXPECT_EQ(t->span()->end_s, 8.0);
    // x = z = 90°: "xyz" sends body +Y to +Z, "zyx" sends it to −X (docs/motion.md, §3).
    const auto xyz = make_trajectory(flex(fixed_at({}), euler_table({{0, 90, 0, 90}}, "xyz")),
                                     kScene, kReference);
    const auto zyx = make_trajectory(flex(fixed_at({}), euler_table({{0, 90, 0, 90}}, "zyx")),
                                     kScene, kReference);
    expect_near(rotate(xyz->pose_at(0).orientation, {0, 1, 0}), {0, 0, 1}, 1e-12);
    expect_near(rotate(zyx->pose_at(0).orientation, {0, 1, 0}), {-1, 0, 0}, 1e-12);
    // The FlexMotion span is the intersection of the engines' spans.
    const auto both = make_trajectory(flex(waypoints({{0, 0, 0, 0}, {20, 1, 0, 0}}),
                                           euler_table({{5, 0, 0, 0}, {30, 0, 0, 1}}, "xyz")),
                                      kScene, kReference);
    ASSERT_TRUE(both->span());
    EXPECT_EQ(both->span()->begin_s, 5.0);
    EXPECT_EQ(both->span()->end_s, 20.0);
}

TEST(Trajectory, QuaternionTableSlerpsAndSpinTurnsAtItsRate) {
    model::OrientationEngine q;
    q.type = model::OrientationEngineType::quaternions;
    const double h = std::sqrt(0.5);
    q.table = {{0, {2, 0, 0, 0}, 0}, {2, {h, 0, 0, h}, 0}};  // not normalised: fine
    const auto t = make_trajectory(flex(fixed_at({}), q), kScene, kReference);
    EXPECT_NEAR(
        angle_between(t->pose_at(1).orientation, quaternion_from_axis_angle({0, 0, 1}, 45 * kDeg)),
        0, 1e-12);
    EXPECT_NEAR(angle_between(t->pose_at(0).orientation, Quaternion::identity()), 0, 1e-12);

    model::OrientationEngine spin;
    spin.type = model::OrientationEngineType::spin;
    spin.spin_axis = {1, 1, 0};
    spin.spin_rate_rad_s = 10 * kDeg;
    spin.spin_phase_rad = 5 * kDeg;
    const auto s = make_trajectory(flex(fixed_at({}), spin), kScene, kReference);
    EXPECT_NEAR(
        angle_between(s->pose_at(2).orientation, quaternion_from_axis_angle({1, 1, 0}, 25 * kDeg)),
        0, 1e-12);
    EXPECT_NEAR(angle_between(s->pose_at(-0.5).orientation, Quaternion::identity()), 0, 1e-12);
}

// ---- refused inputs -------------------------------------------------------------------------

TEST(TrajectoryErrors, UnusableModels) {
    model::PlatformMotion empty;
    empty.file = "a.ppd";
    const Error none = thrown([&] { make_trajectory(empty, kScene, kReference); });
    EXPECT_EQ(none.message(), "no motion was read (neither GenericMotion nor FlexMotion)");
    EXPECT_EQ(none.context().file, "a.ppd");

    model::GenericMotion generic;
    generic.where = {"b.ppd", 1, "platformmotion"};
    const Error no_entries = thrown([&] { make_trajectory(generic, kScene); });
    EXPECT_EQ(no_entries.message(), "the motion has no entries, expected at least one");
    EXPECT_EQ(no_entries.context().file, "b.ppd");

    generic.entries.resize(2);
    generic.entries[0].time_s = 1;
    generic.entries[1].time_s = 1;
    generic.entries[1].where = {"b.ppd", 9, "platformmotion/data/entry"};
    const Error duplicate = thrown([&] { make_trajectory(generic, kScene); });
    EXPECT_THAT(duplicate.message(), HasSubstr("expected strictly increasing times"));
    EXPECT_EQ(duplicate.context().line, 9);

    model::GenericMotionEntry bad_latitude;
    bad_latitude.location.frame = model::LocationFrame::geodetic;
    bad_latitude.location.latitude_deg = 95;
    bad_latitude.location.where = {"c.ppd", 7, "platformmotion/data/entry/position/location"};
    generic.entries = {bad_latitude};
    const Error latitude = thrown([&] { make_trajectory(generic, kScene); });
    EXPECT_EQ(latitude.category(), ErrorCategory::input);
    EXPECT_EQ(latitude.context().line, 7);

    model::OrientationEngine look;
    look.type = model::OrientationEngineType::lookat;
    look.where = {"d.motion", 3, "motion/orientationengine"};
    const Error no_target =
        thrown([&] { make_trajectory(flex(fixed_at({}), look), kScene, kReference); });
    EXPECT_EQ(no_target.message(), "the look-at engine has no target");

    const Error bad_order = thrown([&] {
        make_trajectory(flex(fixed_at({}), euler_table({{0, 0, 0, 0}}, "xzx")), kScene, kReference);
    });
    EXPECT_THAT(bad_order.message(), HasSubstr("rotationorder \"xzx\""));

    const Error empty_table = thrown(
        [&] { make_trajectory(flex(waypoints({}), velocity_aligned()), kScene, kReference); });
    EXPECT_EQ(empty_table.message(), "the waypoint table is empty, expected at least one row");
    EXPECT_EQ(empty_table.context().line, 3);
}

}  // namespace trajectory_test
}  // namespace glint::motion
