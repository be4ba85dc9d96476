// SPDX-License-Identifier: Apache-2.0
// Trajectories of DIRSIG's motion files as the reader makes them (tests/data/motion/):
// waypoints, GenericMotion (.ppd) interpolation and clamping with one warning, a geographic
// .ppd through the scene frame, SGP4 from a TLE file against its own pipeline, and the TLE
// errors reported at their line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "glint/dirsig/motion_reader.h"
#include "glint/motion/euler.h"
#include "glint/motion/sgp4.h"
#include "glint/motion/teme.h"
#include "glint/motion/tle.h"
#include "glint/motion/trajectory.h"
#include "glint/test/angles.h"
#include "glint/test/temp_dir.h"
#include "motion_expect.h"

namespace glint::motion {
namespace trajectory_files_test {

using glint::test::TempDir;
using ::testing::HasSubstr;

using glint::test::kDeg;
const std::filesystem::path kData = std::filesystem::path(GLINT_TEST_DATA_DIR) / "motion";

model::PlatformMotion read(const std::filesystem::path& file) {
    Diagnostics diagnostics;
    model::PlatformMotion motion = dirsig::read_motion(file, dirsig::ReadOptions{}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.items().at(0).text();
    return motion;
}

const SceneFrame kScene(43.0, -78.0, 150.0);
const DateTime kReference = parse_iso8601("2020-06-21T12:00:00Z");

TEST(Trajectory, WaypointsInterpolateLinearly) {
    const auto t = make_trajectory(read(kData / "waypoints.motion"), kScene, kReference);
    expect_near(t->pose_at(0).position_m, {-500, 0, 2000}, 1e-12);
    expect_near(t->pose_at(5).position_m, {0, 0, 2000}, 1e-12);
    expect_near(t->pose_at(15).position_m, {500, 500, 2250}, 1e-12);
    expect_near(t->pose_at(20).position_m, {500, 1000, 2500}, 1e-12);
    expect_near(t->velocity_m_s(5), {100, 0, 0}, 1e-12);
    expect_near(t->velocity_m_s(10), {0, 100, 50}, 1e-12);  // the segment starting at 10 s
    expect_near(t->velocity_m_s(20), {0, 100, 50}, 1e-12);  // the last segment at the end
    ASSERT_TRUE(t->span());
    EXPECT_EQ(t->span()->begin_s, 0.0);
    EXPECT_EQ(t->span()->end_s, 20.0);
}

TEST(Trajectory, Sgp4MatchesItsPipelineAtIssAltitude) {
    const model::PlatformMotion motion = read(kData / "iss.motion");
    const Tle tle = Tle::parse(motion.flexible->location.tle1, motion.flexible->location.tle2);
    const Sgp4 sat(tle);
    const DateTime reference = add_seconds(tle.epoch(), 600.0);
    const SceneFrame scene(40.0, -100.0, 0.0);
    const auto t = make_trajectory(motion, scene, reference);
    for (const double dt : {0.0, 30.0, 95.5, 600.0}) {
        const DateTime when = add_seconds(reference, dt);
        const Sgp4State s = sat.propagate(when);
        ASSERT_TRUE(s.ok());
        const PositionVelocity ecef =
            teme_to_ecef(s.position_km, s.velocity_km_s, julian_date_utc(when));
        const Vec3 expected = scene.ecef_to_enu(ecef.position_km * 1000.0);
        const Pose pose = t->pose_at(dt);
        expect_near(pose.position_m, expected, 0.05);  // DateTime rounding only
        expect_near(t->velocity_m_s(dt), scene.ecef_direction_to_enu(ecef.velocity_km_s * 1000.0),
                    1e-3);
        const double altitude_km = scene.enu_to_geodetic(pose.position_m).altitude_m / 1000.0;
        EXPECT_GT(altitude_km, 300.0);
        EXPECT_LT(altitude_km, 450.0);
        // The finite difference of positions agrees with the velocity.
        const Vec3 fd = (t->pose_at(dt + 0.5).position_m - t->pose_at(dt - 0.5).position_m);
        expect_near(fd, t->velocity_m_s(dt), 0.5);
        // Look-at: the boresight hits the scene origin.
        const Vec3 boresight = rotate(pose.orientation, kInstrumentBoresight);
        expect_near(boresight, normalized(-pose.position_m), 1e-9);
        // Up type velocity: +Y lies in the plane of the boresight and the velocity, ahead.
        const Vec3 forward = rotate(pose.orientation, kVehicleForward);
        EXPECT_NEAR(dot(forward, cross(boresight, normalized(t->velocity_m_s(dt)))), 0.0, 1e-9);
        EXPECT_GT(dot(forward, t->velocity_m_s(dt)), 0.0);
    }
    EXPECT_FALSE(t->span());
}

TEST(Trajectory, GenericMidpointIsLinearInPositionAndSlerpInOrientation) {
    Warnings warnings;
    const auto t = make_trajectory(read(kData / "gui.ppd"), kScene, kReference, warnings.log());
    const Pose mid = t->pose_at(5);
    expect_near(mid.position_m, {100, 400, 5100}, 1e-9);
    EXPECT_NEAR(angle_between(mid.orientation, quaternion_from_axis_angle({0, 0, 1}, 45 * kDeg)),
                0.0, 1e-12);
    const Pose quarter = t->pose_at(2.5);
    EXPECT_NEAR(
        angle_between(quarter.orientation, quaternion_from_axis_angle({0, 0, 1}, 22.5 * kDeg)), 0.0,
        1e-12);
    expect_near(t->velocity_m_s(5), {100, 0, 20}, 1e-12);
    EXPECT_TRUE(warnings.items.empty());
}

TEST(Trajectory, SingleEntryIsConstantAndNeverWarns) {
    Warnings warnings;
    const auto t = make_trajectory(read(kData / "hover.ppd"), kScene, kReference, warnings.log());
    for (const double time : {-100.0, 0.0, 1e6}) {
        const Pose p = t->pose_at(time);
        expect_near(p.position_m, {0, 0, 1000}, 0);
        // Yaw 90°: counter-clockwise from above, the nose points west.
        expect_near(rotate(p.orientation, kVehicleForward), {-1, 0, 0}, 1e-12);
        expect_near(t->velocity_m_s(time), {0, 0, 0}, 0);
    }
    EXPECT_TRUE(warnings.items.empty());
    ASSERT_TRUE(t->span());
    EXPECT_EQ(t->span()->begin_s, t->span()->end_s);
}

TEST(Trajectory, ClampsOutsideTheSpanWithOneWarningAcrossThreads) {
    Warnings warnings;
    const std::string file = (kData / "gui.ppd").string();
    const auto t = make_trajectory(read(file), kScene, kReference, warnings.log());
    const Pose first = t->pose_at(0);
    const Pose last = t->pose_at(10);
    std::vector<std::thread> threads;
    for (int k = 0; k < 8; ++k) {
        threads.emplace_back([&, k] {
            for (int i = 0; i < 200; ++i) {
                const double time = (k % 2 == 0) ? -5.0 - i : 50.0 + i;
                const Pose p = t->pose_at(time);
                const Pose& end = (k % 2 == 0) ? first : last;
                if (!(p.position_m == end.position_m) || !(p.orientation == end.orientation)) {
                    ADD_FAILURE() << "not clamped at t = " << time;
                }
            }
        });
    }
    for (std::thread& thread : threads) thread.join();
    expect_near(t->velocity_m_s(50), {100, 0, 20}, 1e-12);
    ASSERT_EQ(warnings.items.size(), 1u);
    EXPECT_THAT(warnings.items[0], HasSubstr(file + ":1: platformmotion: time "));
    EXPECT_THAT(warnings.items[0],
                HasSubstr("is outside the time span of the motion entries (0 s to 10 s); the "
                          "pose is held at the nearest end (warned once per motion)"));
    // A later call outside the span stays silent.
    t->pose_at(-1);
    EXPECT_EQ(warnings.items.size(), 1u);
}

TEST(Trajectory, GeographicPpdUsesTheSceneFrameAndEcefRotations) {
    const model::PlatformMotion motion = read(kData / "geographic.ppd");
    const auto t = make_trajectory(motion, kScene, kReference);
    const model::GenericMotion& g = *motion.generic;
    const Vec3 a = kScene.geodetic_to_enu(43.01, -78.02, 10000 * 0.3048);
    const Vec3 b = kScene.ecef_to_enu(Vec3{3000000, -14000000, 14000000} * 0.3048);
    expect_near(t->pose_at(-5).position_m, a, 1e-6);
    expect_near(t->pose_at(5).position_m, b, 1e-6);
    expect_near(t->pose_at(0).position_m, 0.5 * (a + b), 1e-6);
    // rotationframe ecef: the Euler rotation takes vehicle axes to ECEF, then ECEF → ENU.
    const Mat3 euler = vehicle_to_scene_rotation(
        to_vehicle_attitude(to_vec3(g.entries[0].euler_rad)), EulerOrder::zyx);
    const Quaternion expected = quaternion_from_matrix(kScene.ecef_to_enu_rotation() * euler);
    EXPECT_NEAR(angle_between(t->pose_at(-5).orientation, expected), 0.0, 1e-12);
    const Quaternion ecef_axes = quaternion_from_matrix(kScene.ecef_to_enu_rotation());
    EXPECT_NEAR(angle_between(t->pose_at(5).orientation, ecef_axes), 0.0, 1e-12);
}

TEST(TrajectoryErrors, BadTleIsReportedAtItsLine) {
    TempDir dir;
    const std::string file = (dir / "bad.motion").string();
    std::ofstream(file) << "<motion type=\"flexible\">\n"
                           "  <locationengine type=\"sgp4\">\n"
                           "    <data source=\"internal\">\n"
                           "      <tle1>1 25544U 98067A   08264.51782528 -.00002182  00000-0 "
                           "-11606-4 0  2928</tle1>\n"
                           "      <tle2>2 25544  51.6416 247.4627 0006703 130.5360 325.0288 "
                           "15.72125391563537</tle2>\n"
                           "    </data>\n"
                           "  </locationengine>\n"
                           "  <orientationengine type=\"velocity\"/>\n"
                           "</motion>\n";
    const model::PlatformMotion motion = read(file);
    const Error error = thrown([&] { make_trajectory(motion, kScene, kReference); });
    EXPECT_EQ(error.category(), ErrorCategory::input);
    EXPECT_EQ(error.context().file, file);
    EXPECT_EQ(error.context().line, 4);
    EXPECT_THAT(error.context().element, ::testing::StartsWith("motion/locationengine/data/tle1"));
    EXPECT_THAT(error.message(), HasSubstr("checksum"));

    model::FlexMotion second = *motion.flexible;
    second.location.tle1.back() = '7';  // line 1 now valid
    second.location.tle2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.7212539156353";
    const Error error2 = thrown([&] { make_trajectory(second, kScene, kReference); });
    EXPECT_EQ(error2.context().line, 5);  // line 2 of the element set
    EXPECT_THAT(error2.context().element, HasSubstr("TLE line 2"));
    EXPECT_EQ(error2.message(), "has 68 characters, expected 69");
}

TEST(TrajectoryErrors, ElementSetThatCannotReachTheReferenceTime) {
    model::FlexMotion f = *read(kData / "iss.motion").flexible;
    const Error error =
        thrown([&] { make_trajectory(f, kScene, parse_iso8601("2300-01-01T00:00:00Z")); });
    EXPECT_EQ(error.category(), ErrorCategory::input);
    EXPECT_EQ(error.context().line, 4);
    EXPECT_THAT(error.message(),
                HasSubstr("the element set of satellite 25544 cannot be propagated to the "
                          "reference time 2300-01-01T00:00:00.000Z"));
}

}  // namespace trajectory_files_test
}  // namespace glint::motion
