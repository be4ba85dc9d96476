// SPDX-License-Identifier: Apache-2.0
// Tests of PixelRaySource with a real PoseService: a camera 1000 m above flat ground (z = 0
// in scene ENU). The pixel a ground point falls in is predicted twice — through the pose and
// CameraModel::project, and by closed-form trigonometry — for nadir and tilted views (vehicle
// roll, a pitched mount), with flips and array offsets; the sample rays' ground hits, times
// and origins are checked against the same arithmetic replayed from the documented draw
// order (u, v, τ), for a hovering and a moving platform with a rolling shutter.
#include "glint/sensor/pixel_ray_source.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/rng.h"
#include "glint/motion/euler.h"
#include "glint/motion/rigid.h"
#include "glint/sensor/camera.h"
#include "glint/test/angles.h"
#include "glint/test/platforms.h"

namespace glint::sensor {
namespace pixel_ray_source_test {

using motion::Rigid;

using glint::test::kDeg;
constexpr double kHeight_m = 1000.0;
constexpr double kFocal_m = 0.1;
constexpr double kPitch_m = 10e-6;
constexpr std::size_t kColumns = 64;
constexpr std::size_t kRows = 48;

/// A vehicle at p0 + v·t with a constant attitude (pitch, roll, yaw; xyz).
class LineTrajectory : public motion::Trajectory {
public:
    LineTrajectory(Vec3 p0, Vec3 v, Vec3 attitude) : m_p0(p0), m_v(v), m_attitude(attitude) {}
    motion::Pose pose_at(double t) const override {
        return {m_p0 + m_v * t, motion::euler_to_quaternion(m_attitude, motion::EulerOrder::xyz)};
    }
    Vec3 velocity_m_s(double) const override { return m_v; }
    std::optional<motion::TimeSpan> span() const override { return std::nullopt; }

private:
    Vec3 m_p0, m_v, m_attitude;
};

motion::PoseService poses(Vec3 p0, Vec3 v = {}, Vec3 attitude = {},
                          std::array<double, 3> mount_rad = {}) {
    return motion::PoseService(test::one_mount_platform(mount_rad),
                               std::make_unique<LineTrajectory>(p0, v, attitude), {}, {});
}

model::DetectorArray array(double size_m = kPitch_m, double x_offset_m = 0, double y_offset_m = 0,
                           bool x_flip = false, bool y_flip = false) {
    model::DetectorArray a;
    a.x_count = kColumns;
    a.y_count = kRows;
    a.x_spacing_m = a.y_spacing_m = kPitch_m;
    a.x_size_m = a.y_size_m = size_m;
    a.x_offset_m = x_offset_m;
    a.y_offset_m = y_offset_m;
    a.x_flip = x_flip;
    a.y_flip = y_flip;
    return a;
}

CameraModel camera(const model::DetectorArray& a) {
    model::InstrumentProperties p;
    p.focal_length_m = kFocal_m;
    return CameraModel(p, a, a.x_count, a.y_count);
}

/// Where a ray meets the ground plane z = 0.
Vec3 ground_hit(const radiometry::SampleRay& ray) {
    const double s = -ray.origin_m.z / ray.direction.z;
    return ray.origin_m + ray.direction * s;
}

/// The fractional pixel of a ground point by the pose service and CameraModel::project.
std::array<double, 2> pixel_by_pose(const motion::PoseService& service, const CameraModel& cam,
                                    const Vec3& ground, double t) {
    const Rigid pose = service.instrument_to_scene(0, t);
    const Vec3 d = motion::apply_direction(motion::inverse(pose), ground - pose.translation_m);
    const auto px = cam.project(d);
    EXPECT_TRUE(px.has_value());
    return px.value_or(std::array<double, 2>{});
}

/// The fractional pixel of instrument tangent coordinates (x/depth, y/depth), by hand:
/// focal-plane point f·tan − offset, mirrored by the flips, over the pitch, from the centre;
/// rows count downwards (−Y).
std::array<double, 2> pixel_by_hand(double tan_x, double tan_y, const model::DetectorArray& a) {
    double xf = kFocal_m * tan_x - a.x_offset_m;
    double yf = kFocal_m * tan_y - a.y_offset_m;
    if (a.x_flip) xf = -xf;
    if (a.y_flip) yf = -yf;
    return {xf / kPitch_m + kColumns / 2.0, -yf / kPitch_m + kRows / 2.0};
}

/// Every combination of flips, with and without an array offset.
std::vector<model::DetectorArray> array_variants() {
    std::vector<model::DetectorArray> out;
    for (const int flips : {0, 1, 2, 3}) {
        for (const bool offset : {false, true}) {
            out.push_back(array(kPitch_m, offset ? 7.5e-5 : 0, offset ? -4e-5 : 0, (flips & 1) != 0,
                                (flips & 2) != 0));
        }
    }
    return out;
}

RandomStream stream(std::uint64_t seed, std::uint64_t problem, std::uint64_t sample) {
    return RandomStream(seed, {0, 0, 0, problem, sample});
}

// Nadir view, level vehicle hovering at 1000 m: ground (X, Y) is at tan = (X/H, Y/H).
TEST(PixelRaySource, NadirGroundPointFallsInThePredictedPixel) {
    const Vec3 vehicle{20, -30, kHeight_m};
    const motion::PoseService service = poses(vehicle);
    const std::vector<Vec3> ground = {{21.234, -30.77, 0}, {18.7, -29.1, 0}, {21.9, -31.3, 0}};
    for (const model::DetectorArray& a : array_variants()) {
        const CameraModel cam = camera(a);
        for (const Vec3& g : ground) {
            const auto by_pose = pixel_by_pose(service, cam, g, 0.0);
            const auto by_hand =
                pixel_by_hand((g.x - vehicle.x) / kHeight_m, (g.y - vehicle.y) / kHeight_m, a);
            EXPECT_NEAR(by_pose[0], by_hand[0], 1e-9);  // px, round-off
            EXPECT_NEAR(by_pose[1], by_hand[1], 1e-9);
            ASSERT_GE(by_hand[0], 0);
            ASSERT_LT(by_hand[0], kColumns);
            ASSERT_GE(by_hand[1], 0);
            ASSERT_LT(by_hand[1], kRows);
            // The sample rays of that pixel land around the point: within the 0.1 m ground
            // footprint of the pixel (H·p/f), and re-project into the pixel.
            const auto i = static_cast<std::uint64_t>(by_hand[0]);
            const auto j = static_cast<std::uint64_t>(by_hand[1]);
            const PixelRaySource source(cam, service, 0, {0.0, 0.0, 0.0});
            for (std::uint64_t n = 0; n < 20; ++n) {
                RandomStream rng = stream(5, j * kColumns + i, n);
                const Vec3 hit = ground_hit(source.generate(j * kColumns + i, n, rng));
                EXPECT_LE(std::abs(hit.x - g.x), 0.1 + 1e-9);  // m: one pixel footprint
                EXPECT_LE(std::abs(hit.y - g.y), 0.1 + 1e-9);
                const auto back = pixel_by_hand((hit.x - vehicle.x) / kHeight_m,
                                                (hit.y - vehicle.y) / kHeight_m, a);
                EXPECT_GE(back[0], i - 1e-9);  // px, round-off at the pixel edge
                EXPECT_LE(back[0], i + 1 + 1e-9);
                EXPECT_GE(back[1], j - 1e-9);
                EXPECT_LE(back[1], j + 1 + 1e-9);
            }
        }
    }
}

// A northbound nadir pass: the top line looks forward (north), the left column west.
TEST(PixelRaySource, TopLineIsForwardAndLeftColumnIsWestForANorthboundPass) {
    const motion::PoseService service = poses({0, 0, kHeight_m}, {0, 50, 0});
    const CameraModel cam = camera(array());
    const PixelRaySource source(cam, service, 0, {0.0, 0.0, 0.0});
    const auto centre_hit = [&](std::uint64_t i, std::uint64_t j) {
        RandomStream rng = stream(1, j * kColumns + i, 0);
        return ground_hit(source.generate(j * kColumns + i, 0, rng));
    };
    EXPECT_GT(centre_hit(10, 0).y, 0.0);
    EXPECT_LT(centre_hit(10, kRows - 1).y, 0.0);
    EXPECT_LT(centre_hit(0, 10).x, 0.0);
    EXPECT_GT(centre_hit(kColumns - 1, 10).x, 0.0);
}

// Vehicle rolled right wing down by θ: the instrument sees ground (X, Y) at
// tan_x = tan(atan(X/H) + θ) and tan_y = Y / (H cos θ − X sin θ).
TEST(PixelRaySource, RolledVehicleSeesThePredictedPixel) {
    const double roll = 5 * kDeg;
    const motion::PoseService service = poses({0, 0, kHeight_m}, {}, {0, roll, 0});
    for (const model::DetectorArray& a : array_variants()) {
        const CameraModel cam = camera(a);
        // Points near where the boresight meets the ground, X = −H tan θ ≈ −87.5 m.
        for (const Vec3& g : {Vec3{-87.0, 1.3, 0}, Vec3{-89.2, -2.0, 0}, Vec3{-85.6, 0.4, 0}}) {
            const double tan_x = std::tan(std::atan(g.x / kHeight_m) + roll);
            const double tan_y = g.y / (kHeight_m * std::cos(roll) - g.x * std::sin(roll));
            const auto by_hand = pixel_by_hand(tan_x, tan_y, a);
            const auto by_pose = pixel_by_pose(service, cam, g, 0.0);
            EXPECT_NEAR(by_pose[0], by_hand[0], 1e-9);  // px, round-off
            EXPECT_NEAR(by_pose[1], by_hand[1], 1e-9);
            EXPECT_TRUE(by_hand[0] > 0 && by_hand[0] < kColumns && by_hand[1] > 0 &&
                        by_hand[1] < kRows);
        }
    }
}

// A mount pitched forward by θ about X: ground (X, Y) at tan_y = tan(atan(Y/H) − θ) and
// tan_x = X / (H cos θ + Y sin θ). The rays of the pixel come back to it.
TEST(PixelRaySource, PitchedMountSeesThePredictedPixel) {
    const double pitch = 20 * kDeg;
    const motion::PoseService service = poses({0, 0, kHeight_m}, {}, {}, {pitch, 0, 0});
    for (const model::DetectorArray& a : array_variants()) {
        const CameraModel cam = camera(a);
        for (const Vec3& g : {Vec3{1.0, 364.0, 0}, Vec3{-2.0, 362.1, 0}, Vec3{2.0, 365.8, 0}}) {
            const double tan_y = std::tan(std::atan(g.y / kHeight_m) - pitch);
            const double tan_x = g.x / (kHeight_m * std::cos(pitch) + g.y * std::sin(pitch));
            const auto by_hand = pixel_by_hand(tan_x, tan_y, a);
            const auto by_pose = pixel_by_pose(service, cam, g, 0.0);
            EXPECT_NEAR(by_pose[0], by_hand[0], 1e-9);  // px, round-off
            EXPECT_NEAR(by_pose[1], by_hand[1], 1e-9);
            ASSERT_TRUE(by_hand[0] > 0 && by_hand[0] < kColumns && by_hand[1] > 0 &&
                        by_hand[1] < kRows);
            const auto i = static_cast<std::uint64_t>(by_hand[0]);
            const auto j = static_cast<std::uint64_t>(by_hand[1]);
            const PixelRaySource source(cam, service, 0, {0.0, 0.0, 0.0});
            for (std::uint64_t n = 0; n < 10; ++n) {
                RandomStream rng = stream(9, j * kColumns + i, n);
                const Vec3 hit = ground_hit(source.generate(j * kColumns + i, n, rng));
                const auto back = pixel_by_pose(service, cam, hit, 0.0);
                EXPECT_GE(back[0], i - 1e-9);  // px, round-off at the pixel edge
                EXPECT_LE(back[0], i + 1 + 1e-9);
                EXPECT_GE(back[1], j - 1e-9);
                EXPECT_LE(back[1], j + 1 + 1e-9);
            }
        }
    }
}

// A platform flying north at 100 m/s with a rolling shutter: each sample's time, origin and
// ground hit follow from u, v, τ drawn in that order from the same stream.
TEST(PixelRaySource, MovingPlatformRaysReplayTheDocumentedDraws) {
    const Vec3 p0{10, -50, kHeight_m};
    const Vec3 velocity{0, 100, 0};
    const motion::PoseService service = poses(p0, velocity);
    const double element_m = 8e-6;
    for (const model::DetectorArray& a :
         {array(element_m), array(element_m, 5e-5, 2e-5, true, false),
          array(element_m, 0, 0, false, true)}) {
        const CameraModel cam = camera(a);
        const CaptureTiming timing{0.2, 0.25, 1e-3};
        const PixelRaySource source(cam, service, 0, timing);
        for (const std::uint64_t problem : {0ull, 63ull, 64ull, 1000ull, 3071ull}) {
            const std::uint64_t i = problem % kColumns;
            const std::uint64_t j = problem / kColumns;
            for (std::uint64_t n = 0; n < 8; ++n) {
                RandomStream rng = stream(77, problem, n);
                const radiometry::SampleRay ray = source.generate(problem, n, rng);
                RandomStream replay = stream(77, problem, n);
                const double u = replay.uniform();
                const double v = replay.uniform();
                const double tau = replay.uniform();
                EXPECT_EQ(rng.position(), replay.position());  // nothing else drawn
                const double t = 0.2 + static_cast<double>(j) * 1e-3 + tau * (0.25 - 0.2);
                EXPECT_DOUBLE_EQ(ray.time_s, t);
                EXPECT_GE(ray.time_s, 0.2 + j * 1e-3);
                EXPECT_LE(ray.time_s, 0.25 + j * 1e-3);
                EXPECT_EQ(ray.weight, 1.0);
                const Vec3 origin = p0 + velocity * t;
                EXPECT_NEAR(ray.origin_m.x, origin.x, 1e-9);  // m, round-off
                EXPECT_NEAR(ray.origin_m.y, origin.y, 1e-9);
                EXPECT_NEAR(ray.origin_m.z, origin.z, 1e-9);
                EXPECT_NEAR(norm(ray.direction), 1.0, 1e-15);
                // Focal-plane point by hand (flips mirror about the offset), scaled to the
                // ground: X = x_vehicle(t) + x_f H / f.
                double xf = (i + 0.5 - kColumns / 2.0) * kPitch_m + (u - 0.5) * element_m;
                double yf = -((j + 0.5 - kRows / 2.0) * kPitch_m + (v - 0.5) * element_m);
                if (a.x_flip) xf = -xf;
                if (a.y_flip) yf = -yf;
                xf += a.x_offset_m;
                yf += a.y_offset_m;
                const Vec3 hit = ground_hit(ray);
                EXPECT_NEAR(hit.x, origin.x + xf * kHeight_m / kFocal_m, 1e-8);  // m, round-off
                EXPECT_NEAR(hit.y, origin.y + yf * kHeight_m / kFocal_m, 1e-8);
            }
        }
    }
}

// Same stream → the same ray, bit for bit; another sample index → another ray.
TEST(PixelRaySource, SameStreamGivesTheSameRay) {
    const motion::PoseService service = poses({0, 0, kHeight_m}, {0, 80, 0}, {0.01, -0.02, 0.3});
    const CameraModel cam = camera(array(7e-6, 1e-5, 0, true, true));
    const PixelRaySource source(cam, service, 0, {1.0, 1.004, 2e-5});
    for (const std::uint64_t problem : {0ull, 777ull, 3071ull}) {
        RandomStream a = stream(3, problem, 4);
        RandomStream b = stream(3, problem, 4);
        RandomStream c = stream(3, problem, 5);
        const radiometry::SampleRay ra = source.generate(problem, 4, a);
        const radiometry::SampleRay rb = source.generate(problem, 4, b);
        const radiometry::SampleRay rc = source.generate(problem, 5, c);
        EXPECT_EQ(ra.origin_m, rb.origin_m);
        EXPECT_EQ(ra.direction, rb.direction);
        EXPECT_EQ(ra.time_s, rb.time_s);
        EXPECT_NE(ra.direction, rc.direction);
        EXPECT_NE(ra.time_s, rc.time_s);
    }
}

// The samples cover the element area and the window uniformly: (u, v, τ) recovered from the
// rays of one pixel, binned 4 × 4 × 4, pass a chi-square test (63 degrees of freedom, 6400
// samples, fixed seed; the 0.1 % critical value is 103.4).
TEST(PixelRaySource, SamplesAreUniformOverElementAndWindow) {
    const motion::PoseService service = poses({0, 0, kHeight_m});
    const double element_m = 6e-6;
    const CameraModel cam = camera(array(element_m));
    const PixelRaySource source(cam, service, 0, {2.0, 2.01, 0.0});
    const std::uint64_t i = 40, j = 11, problem = j * kColumns + i;
    std::array<int, 64> counts{};
    const int samples = 6400;
    for (int n = 0; n < samples; ++n) {
        RandomStream rng = stream(11, problem, static_cast<std::uint64_t>(n));
        const radiometry::SampleRay ray =
            source.generate(problem, static_cast<std::uint64_t>(n), rng);
        const Vec3 hit = ground_hit(ray);
        const double xf = hit.x * kFocal_m / kHeight_m;
        const double yf = hit.y * kFocal_m / kHeight_m;
        const double u = (xf - (i + 0.5 - kColumns / 2.0) * kPitch_m) / element_m + 0.5;
        const double v = (-yf - (j + 0.5 - kRows / 2.0) * kPitch_m) / element_m + 0.5;
        const double tau = (ray.time_s - 2.0) / 0.01;
        ASSERT_GE(u, -1e-6);
        ASSERT_LT(u, 1 + 1e-6);
        ASSERT_GE(v, -1e-6);
        ASSERT_LT(v, 1 + 1e-6);
        ASSERT_GE(tau, 0.0);
        ASSERT_LT(tau, 1.0);
        const auto bin = [](double x) { return std::clamp(static_cast<int>(x * 4), 0, 3); };
        ++counts[static_cast<std::size_t>(bin(u) * 16 + bin(v) * 4 + bin(tau))];
    }
    const double expected = samples / 64.0;
    double chi2 = 0;
    for (const int c : counts) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 103.4);
}

// TDI: N stages (the camera's rows) on a platform flying +Y at one ground sample per stage
// time. Replaying the draws, a sample's stage is ⌊τ N⌋, its row that stage, its time in the
// stage's part of the window; and every stage of a column looks at the same ground line:
// the along-track ground position of a sample is y0 + (N/2 + f − v)·GSD (f the fraction of
// its stage time, v its place in the element), within one GSD of the line's centre whatever
// the stage. Unsynchronised stages would spread it over N GSD.
TEST(PixelRaySource, TdiStagesFollowTheGroundLine) {
    constexpr std::size_t kStages = 6;
    const double gsd_m = kPitch_m * kHeight_m / kFocal_m;  // 0.1 m
    const double speed_m_s = 100.0;
    const double stage_s = gsd_m / speed_m_s;  // 1 ms
    const Vec3 p0{0, -20, kHeight_m};
    const motion::PoseService service = poses(p0, {0, speed_m_s, 0});
    model::DetectorArray a = array();
    a.y_count = kStages;
    const CameraModel cam(
        [] {
            model::InstrumentProperties p;
            p.focal_length_m = kFocal_m;
            return p;
        }(),
        a, kColumns, kStages);
    const double t0 = 0.3;
    const CaptureTiming timing{t0, t0 + kStages * stage_s, 0.0, kStages};
    const PixelRaySource source(cam, service, 0, timing);
    std::array<int, kStages> per_stage{};
    for (const std::uint64_t column : {0ull, 17ull, 63ull}) {
        for (std::uint64_t n = 0; n < 600; ++n) {
            RandomStream rng = stream(5, column, n);
            const radiometry::SampleRay ray = source.generate(column, n, rng);
            RandomStream replay = stream(5, column, n);
            const double u = replay.uniform();
            const double v = replay.uniform();
            const double tau = replay.uniform();
            EXPECT_EQ(rng.position(), replay.position());
            const auto stage = static_cast<std::size_t>(tau * kStages);
            ++per_stage[stage];
            EXPECT_DOUBLE_EQ(ray.time_s, t0 + tau * kStages * stage_s);
            EXPECT_GE(ray.time_s, t0 + static_cast<double>(stage) * stage_s - 1e-12);
            EXPECT_LE(ray.time_s, t0 + static_cast<double>(stage + 1) * stage_s + 1e-12);
            const Vec3 hit = ground_hit(ray);
            const double x_expected =
                ((column + 0.5 - kColumns / 2.0) + (u - 0.5)) * gsd_m;  // element = pitch
            EXPECT_NEAR(hit.x, x_expected, 1e-8);                       // m, round-off
            // The ground line of the capture: where the array's centre looks at t0, plus the
            // half array ahead of it that the last stage reaches.
            const double line_centre_m = p0.y + speed_m_s * t0 + kStages / 2.0 * gsd_m;
            const double f = tau * kStages - static_cast<double>(stage);
            EXPECT_NEAR(hit.y, line_centre_m + (f - v) * gsd_m, 1e-8) << stage;
            EXPECT_LT(std::fabs(hit.y - line_centre_m), gsd_m);
        }
    }
    for (std::size_t k = 0; k < kStages; ++k) EXPECT_GT(per_stage[k], 200) << k;  // of 1800
    RandomStream rng(1, {0});
    EXPECT_THROW(source.generate(kColumns, 0, rng), Error);  // one line: problems = columns
    EXPECT_NO_THROW(source.generate(kColumns - 1, 0, rng));
    // Stages other than the rows, or with a rolling readout, are refused.
    EXPECT_THROW(PixelRaySource(cam, service, 0, {t0, t0 + 1, 0.0, kStages + 1}), Error);
    EXPECT_THROW(PixelRaySource(cam, service, 0, {t0, t0 + 1, 1e-4, kStages}), Error);
    EXPECT_THROW(PixelRaySource(cam, service, 0, {t0, t0 + 1, 0.0, 0}), Error);
}

TEST(PixelRaySource, BadArgumentsAreInternalErrors) {
    const motion::PoseService service = poses({0, 0, kHeight_m});
    const CameraModel cam = camera(array());
    const auto category = [](auto&& f) {
        try {
            f();
        } catch (const Error& e) {
            return e.category();
        }
        return ErrorCategory::usage;  // not thrown
    };
    EXPECT_EQ(category([&] { PixelRaySource(cam, service, 1, {}); }), ErrorCategory::internal);
    EXPECT_EQ(category([&] {
                  PixelRaySource(cam, service, 0, {1.0, 0.5, 0.0});
              }),
              ErrorCategory::internal);
    EXPECT_EQ(category([&] {
                  PixelRaySource(cam, service, 0, {0.0, 1.0, -1e-3});
              }),
              ErrorCategory::internal);
    const PixelRaySource source(cam, service, 0, {});
    RandomStream rng(1, {0});
    EXPECT_EQ(category([&] { source.generate(kColumns * kRows, 0, rng); }),
              ErrorCategory::internal);
    EXPECT_NO_THROW(source.generate(kColumns * kRows - 1, 0, rng));
}

}  // namespace pixel_ray_source_test
}  // namespace glint::sensor
