// SPDX-License-Identifier: Apache-2.0
// The pose service: identity mounts look along vehicle −Z, the instruments of
// two_instruments.platform land where the hand-composed chain puts them (level and yawed
// hover), tracking through the whole chain for a moving, jittered vehicle, instrument ↔
// vehicle consistency, errors, and determinism of jittered poses (same seed, two threads).
#include "glint/motion/pose_service.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "glint/core/error.h"
#include "glint/dirsig/readers.h"
#include "glint/inputs/load.h"
#include "glint/motion/euler.h"
#include "glint/test/angles.h"
#include "glint/test/errors.h"
#include "glint/test/platforms.h"
#include "motion_expect.h"

namespace glint::motion {
namespace pose_service_test {

using glint::test::kDeg;
using glint::test::kPi;
const std::string kData = GLINT_TEST_DATA_DIR;

double angle(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

Vec3 boresight(const Rigid& r) { return apply_direction(r, kInstrumentBoresight); }

/// A vehicle at p0 + v·t whose attitude (pitch, roll, yaw, xyz) changes linearly with time.
class LineTrajectory : public Trajectory {
public:
    LineTrajectory(Vec3 p0, Vec3 v, Vec3 attitude0, Vec3 attitude_rate)
        : m_p0(p0), m_v(v), m_a0(attitude0), m_rate(attitude_rate) {}
    Pose pose_at(double t) const override {
        return {m_p0 + m_v * t, euler_to_quaternion(m_a0 + m_rate * t, EulerOrder::xyz)};
    }
    Vec3 velocity_m_s(double) const override { return m_v; }
    std::optional<TimeSpan> span() const override { return std::nullopt; }

private:
    Vec3 m_p0, m_v, m_a0, m_rate;
};

std::unique_ptr<Trajectory> hover(Vec3 position, Vec3 attitude = {}) {
    return std::make_unique<LineTrajectory>(position, Vec3{}, attitude, Vec3{});
}

std::vector<model::Simulation> read_poses_jsim() {
    Diagnostics diagnostics;
    auto sims = dirsig::read_jsim(kData + "/poses/poses.jsim", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors()) << diagnostics.items().front().text();
    return sims;
}

/// Reads BasicPlatform entry `plugin` of `simulation` (throws what read_platform_entry throws).
model::PlatformInputs entry_of(const model::Simulation& simulation, std::size_t plugin) {
    Diagnostics diagnostics;
    auto entry = inputs::read_platform_entry(simulation, plugin, {}, diagnostics);
    diagnostics.throw_if_errors();
    return std::move(*entry);
}

PoseService service_for(std::size_t plugin, std::uint64_t seed = 1) {
    const auto sims = read_poses_jsim();
    return make_pose_service(entry_of(sims.at(0), plugin), seed, {});
}

TEST(PoseService, IdentityMountsLookAlongVehicleMinusZ) {
    // Level vehicle: straight down.
    PoseService level(test::one_mount_platform(), hover({5, 6, 700}), {}, {});
    ASSERT_EQ(level.instrument_count(), 1u);
    const Rigid r = level.instrument_to_scene(0, 0.0);
    expect_near(boresight(r), {0, 0, -1}, 1e-15);
    expect_near(r.translation_m, {5, 6, 700}, 1e-12);
    // Any attitude: along the vehicle's −Z axis.
    const Vec3 attitude{0.2, -0.3, 1.0};
    PoseService tilted(test::one_mount_platform(), hover({0, 0, 700}, attitude), {}, {});
    const Vec3 vehicle_minus_z =
        -to_matrix(euler_to_quaternion(attitude, EulerOrder::xyz)).column(2);
    expect_near(boresight(tilted.instrument_to_scene(0, 0.0)), vehicle_minus_z, 1e-15);
}

TEST(PoseService, StaticThirtyDegreeXMountLooksForwardOfNadir) {
    // Vehicle nose north: +30° about X tilts the boresight 30° towards north (forward).
    PoseService service(test::one_mount_platform({30 * kDeg, 0, 0}), hover({0, 0, 1000}), {}, {});
    const Vec3 b = boresight(service.instrument_to_scene(0, 0.0));
    expect_near(b, {0, 0.5, -std::sqrt(3.0) / 2}, 1e-15);
    // The ground point it sees: 1000·tan 30° north of the nadir.
    EXPECT_NEAR(1000.0 * b.y / -b.z, 1000.0 * std::tan(30 * kDeg), 1e-9);
}

// two_instruments.platform, composed by hand:
//   Wide:   A0 = translate (1.5, −0.25, 0.1); M0 = zyx (0, −30°, 90°) = Ry(−30°)·Rz(90°);
//           A1 = I; M1 = xyz (0.1 rad, 0, 0) = Rx(0.1); A2 = I.
//           Rx(0.1)·(0,0,−1) = (0, s, −c); Rz(90°) → (−s, 0, −c);
//           Ry(−30°) → (c/2 − (√3/2)s, 0, −s/2 − (√3/2)c), s = sin 0.1, c = cos 0.1.
//   Narrow: identity mounts at the vehicle origin: straight down.
TEST(PoseService, TwoInstrumentsOnALevelHover) {
    const PoseService service = service_for(0);
    ASSERT_EQ(service.instrument_count(), 2u);
    EXPECT_EQ(service.instrument_path(0).instrument->name, "Wide");
    EXPECT_EQ(service.instrument_path(1).instrument->name, "Narrow");
    const double s = std::sin(0.1), c = std::cos(0.1), r3 = std::sqrt(3.0) / 2;
    for (const double t : {0.0, 1.0, 2.5}) {
        const Rigid wide = service.instrument_to_scene(0, t);
        expect_near(wide.translation_m, {1.5, -0.25, 1000.1}, 1e-9);
        expect_near(boresight(wide), {c / 2 - r3 * s, 0, -s / 2 - r3 * c}, 1e-14);
        const Rigid narrow = service.instrument_to_scene(1, t);
        expect_near(narrow.translation_m, {0, 0, 1000}, 1e-9);
        expect_near(boresight(narrow), {0, 0, -1}, 1e-14);
    }
}

TEST(PoseService, TwoInstrumentsOnAYawedHover) {
    // Nose west (yaw +90°): vehicle +X (right wing) points north, +Y (nose) west.
    const PoseService service = service_for(2);
    const double s = std::sin(0.1), c = std::cos(0.1), r3 = std::sqrt(3.0) / 2;
    const Rigid wide = service.instrument_to_scene(0, 1.0);
    expect_near(wide.translation_m, {10 + 0.25, 20 + 1.5, 1000.1}, 1e-9);
    // Rz(90°)·(bx, 0, bz) = (0, bx, bz).
    expect_near(boresight(wide), {0, c / 2 - r3 * s, -s / 2 - r3 * c}, 1e-14);
    expect_near(service.instrument_to_scene(1, 1.0).translation_m, {10, 20, 1000}, 1e-9);
    expect_near(service.vehicle_pose(1.0).position_m, {10, 20, 1000}, 1e-9);
}

TEST(PoseService, InstrumentToVehicleComposesWithTheVehiclePose) {
    for (const std::size_t plugin : {std::size_t{0}, std::size_t{3}}) {
        const PoseService service = service_for(plugin);
        for (std::size_t k = 0; k < service.instrument_count(); ++k) {
            for (const double t : {0.0, 1.3, 2.9}) {
                const Pose v = service.vehicle_pose(t);
                const Rigid a =
                    Rigid{v.orientation, v.position_m} * service.instrument_to_vehicle(k, t);
                const Rigid b = service.instrument_to_scene(k, t);
                expect_near(a.translation_m, b.translation_m, 1e-9);
                EXPECT_LT(angle_between(a.rotation, b.rotation), 1e-7);
            }
        }
    }
}

TEST(PoseService, TrackingThroughTheChainForAMovingJitteredVehicle) {
    // scan_stare.platform, plugin 3: StareRecorder tracks (100, 50, 0) from 0.5 m below a
    // vehicle flying north at 100 m/s with platform jitter.
    const PoseService service = service_for(3);
    ASSERT_EQ(service.instrument_count(), 2u);
    ASSERT_EQ(service.instrument_path(1).instrument->name, "StareRecorder");
    for (double t = 0.0; t <= 10.0; t += 0.173) {
        const Rigid stare = service.instrument_to_scene(1, t);
        const Vec3 to_target = Vec3{100, 50, 0} - stare.translation_m;
        EXPECT_LT(angle(boresight(stare), to_target), 1e-9) << "t=" << t;
        // The instrument sits 0.5 m below the (jittered) vehicle origin.
        const Pose v = service.vehicle_pose(t);
        expect_near(stare.translation_m, v.position_m + rotate(v.orientation, Vec3{0, 0, -0.5}),
                    1e-9);
    }
}

TEST(PoseService, WhiskScannerPeaksAtAQuarterPeriodWithSmallJitter) {
    // 0.25 Hz, ±20° across-track: +20° about Y at t = 1 s, i.e. 20° towards vehicle −X
    // (west for a nose-north vehicle), within the mount and platform jitter (~1e-4 rad).
    const PoseService service = service_for(3);
    const Vec3 b = boresight(service.instrument_to_scene(0, 1.0));
    EXPECT_LT(angle(b, {-std::sin(20 * kDeg), 0, -std::cos(20 * kDeg)}), 2e-3);
    const Vec3 b3 = boresight(service.instrument_to_scene(0, 3.0));
    EXPECT_LT(angle(b3, {std::sin(20 * kDeg), 0, -std::cos(20 * kDeg)}), 2e-3);
}

TEST(PoseService, JitterIsAppliedAndDeterministic) {
    const PoseService a = service_for(3, 42);
    const PoseService b = service_for(3, 42);
    const PoseService other = service_for(3, 43);
    bool differs_from_nominal = false, differs_between_seeds = false;
    for (double t = 0.0; t < 5.0; t += 0.01) {
        for (std::size_t k = 0; k < a.instrument_count(); ++k) {
            const Rigid ra = a.instrument_to_scene(k, t);
            const Rigid rb = b.instrument_to_scene(k, t);
            ASSERT_EQ(ra, rb) << "t=" << t << " instrument " << k;  // bit-identical
            differs_between_seeds =
                differs_between_seeds || !(ra == other.instrument_to_scene(k, t));
        }
        const Pose jittered = a.vehicle_pose(t), nominal = a.nominal_vehicle_pose(t);
        differs_from_nominal =
            differs_from_nominal || norm(jittered.position_m - nominal.position_m) > 1e-3;
    }
    EXPECT_TRUE(differs_from_nominal);
    EXPECT_TRUE(differs_between_seeds);
    // Size of the jitter: the x location jitter is N(0, 0.5 m); positions stay within 5σ.
    for (double t = 0.0; t < 5.0; t += 0.05) {
        EXPECT_LT(std::abs(a.vehicle_pose(t).position_m.x), 2.5);
    }
}

TEST(PoseService, TwoThreadsGiveTheSamePoses) {
    const PoseService service = service_for(3, 7);
    constexpr int kSamples = 2000;
    const auto run = [&](std::vector<Rigid>& out, bool reverse) {
        out.assign(2 * kSamples, Rigid{});
        for (int n = 0; n < kSamples; ++n) {
            const int i = reverse ? kSamples - 1 - n : n;
            for (std::size_t k = 0; k < 2; ++k) {
                out[2 * i + k] = service.instrument_to_scene(k, 0.0025 * i);
            }
        }
    };
    std::vector<Rigid> serial, first, second;
    run(serial, false);
    std::thread t1([&] { run(first, false); });
    std::thread t2([&] { run(second, true); });
    t1.join();
    t2.join();
    EXPECT_EQ(first, serial);
    EXPECT_EQ(second, serial);
}

TEST(PoseService, NamedTrackingTargetNeedsAScene) {
    Diagnostics diagnostics;
    model::Platform platform =
        dirsig::read_platform(kData + "/platform/mounts.platform", {}, diagnostics);
    inputs::read_psd_tables(platform, {}, diagnostics);
    ASSERT_FALSE(diagnostics.has_errors());
    const std::string msg = test::error_text([&] {
        PoseService(std::make_shared<model::Platform>(platform), hover({0, 0, 1000}), {}, {});
    });
    EXPECT_THAT(msg, testing::HasSubstr("mounts.platform:"));
    EXPECT_THAT(
        msg, testing::HasSubstr("mount \"Tracker\": tracking a named target "
                                "(\"truck_01\") needs the scene (its instances are the targets)"));
}

TEST(PoseService, BadPluginIndexAndInstrumentIndex) {
    const auto sims = read_poses_jsim();
    EXPECT_THAT(test::error_text([&] { entry_of(sims.at(0), 1); }),
                testing::HasSubstr("plugin_list[1] of"));
    EXPECT_THAT(test::error_text([&] { entry_of(sims.at(0), 9); }),
                testing::HasSubstr("plugin index 9 out of range"));
    const PoseService service = service_for(0);
    EXPECT_THAT(test::error_text([&] { service.instrument_to_scene(2, 0.0); }),
                testing::HasSubstr("instrument index 2 out of range"));
}

TEST(PoseService, JitterSpanCoversTheTasks) {
    model::TaskList tasks;
    EXPECT_EQ(jitter_span_of(tasks).begin_s, -1.0);
    tasks.tasks.push_back({"a", "", 5.0, 7.0, {}});
    tasks.tasks.push_back({"b", "", 2.0, 3.0, {}});
    EXPECT_EQ(jitter_span_of(tasks).begin_s, 1.0);
    EXPECT_EQ(jitter_span_of(tasks).end_s, 8.0);
}

}  // namespace pose_service_test
}  // namespace glint::motion
