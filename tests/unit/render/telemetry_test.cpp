// SPDX-License-Identifier: Apache-2.0
// Data-recorder telemetry (glint/sensor/telemetry.h) on tests/data/telemetry (a climbing,
// turning flight; recorders on an attachment turned 30° and 1 m forward): the sample times
// are the recorder clock's ticks in each task window; each record is the pose service's
// instrument pose; its Euler angles rebuild its quaternion in the platform's order; its
// velocity and body rates carry the pose over a 10 ms step; the noise is zero without
// <noise>; bad recorders are refused at the element.
#include "glint/sensor/telemetry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "../../../lib/render/src/render_parts.h"
#include "glint/core/error.h"
#include "glint/motion/euler.h"
#include "glint/test/angles.h"
#include "glint/test/temp_dir.h"
#include "render_fixture.h"

namespace glint::render {
namespace telemetry_test {

namespace fs = std::filesystem;
using test_render::load;
using test_render::options_into;

const fs::path kTelemetry = fs::path(GLINT_TEST_DATA_DIR) / "telemetry";
using glint::test::kDeg;

TEST(Telemetry, RecordsThePoseServicesInstrumentPoseAtTheClockTicks) {
    test::TempDir dir;
    const auto prepared =
        detail::plan_render(load(kTelemetry / "recorder.jsim"), options_into(dir / "out"), {});
    ASSERT_EQ(prepared.plan->telemetry.size(), 2u);
    const detail::PlannedTelemetry& gps = prepared.plan->telemetry[0];
    EXPECT_EQ(gps.recorder->name, "GPS");
    EXPECT_EQ(gps.csv, dir / "out" / "gps.csv");
    const schedule::PluginSchedule& plugin = prepared.plan->inputs.schedule->plugins()[gps.plugin];
    const auto times = sensor::recorder_times_s(*gps.recorder, *plugin.platform, plugin.tasks);
    // 10 Hz in [0, 0.25] and [1, 1.15].
    ASSERT_EQ(times.size(), 5u);
    EXPECT_EQ(times[2], (std::pair<std::uint64_t, double>{0, 0.2}));
    EXPECT_EQ(times[3], (std::pair<std::uint64_t, double>{1, 1.0}));

    const motion::PoseService& poses = *plugin.poses;
    EXPECT_EQ(poses.platform_rotation_order(), motion::EulerOrder::zyx);
    const auto records =
        sensor::record_telemetry(poses, gps.instrument, times, prepared.plan->inputs.frame,
                                 gps.recorder->recorder.noise, 1, plugin.plugin_index);
    ASSERT_EQ(records.size(), 5u);
    for (const sensor::TelemetryRecord& r : records) {
        const motion::Rigid pose = poses.instrument_to_scene(gps.instrument, r.time_s);
        EXPECT_EQ(r.position_enu_m, pose.translation_m);  // no noise configured
        EXPECT_NEAR(std::abs(motion::dot(r.orientation, pose.rotation)), 1.0, 1e-15);
        EXPECT_GE(r.orientation.w, 0.0);
        // The Euler angles rebuild the quaternion in the platform's order.
        const motion::Quaternion rebuilt =
            motion::euler_to_quaternion(r.euler_deg * kDeg, motion::EulerOrder::zyx);
        EXPECT_NEAR(std::abs(motion::dot(rebuilt, r.orientation)), 1.0, 1e-12) << r.time_s;
        // Velocity and body rate carry the pose 10 ms on (the motion is smooth: the error of
        // a first-order step is ~ (10 ms)² × the second derivative, well below 1 mm, 1e-5 rad).
        constexpr double dt = 0.01;
        const motion::Rigid later = poses.instrument_to_scene(gps.instrument, r.time_s + dt);
        const motion::Vec3 predicted = r.position_enu_m + r.velocity_enu_m_s * dt;
        EXPECT_LT(motion::norm(predicted - later.translation_m), 1e-3) << r.time_s;
        const motion::Vec3 w = r.angular_rate_deg_s * kDeg;
        const double angle = motion::norm(w) * dt;
        const motion::Quaternion step =
            angle > 0 ? motion::quaternion_from_axis_angle(w * (1 / motion::norm(w)), angle)
                      : motion::Quaternion::identity();
        EXPECT_NEAR(std::abs(motion::dot(r.orientation * step, later.rotation)), 1.0, 1e-9)
            << r.time_s;
        // The geodetic and ECEF positions are the ENU point's.
        const motion::Vec3 back = prepared.plan->inputs.frame.ecef_to_enu(r.position_ecef_m);
        EXPECT_LT(motion::norm(back - r.position_enu_m), 1e-6);
    }
    // It turns: about 10°/s about the vertical.
    EXPECT_GT(std::abs(records[0].angular_rate_deg_s.z), 5.0);
}

/// Writes a copy of the fixture whose recorder XML is `recorder` and prepares it.
void prepare_with(const fs::path& dir, const std::string& recorder) {
    const std::string platform = "<platform><clocktable/><attachment><affinetransform/>" +
                                 recorder + "</attachment></platform>\n";
    std::ofstream(dir / "recorder.platform") << platform;
    fs::copy_file(kTelemetry / "turning.ppd", dir / "turning.ppd");
    std::ifstream in(kTelemetry / "recorder.jsim");
    std::string jsim((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string from = "../render/";
    for (std::size_t at = jsim.find(from); at != std::string::npos; at = jsim.find(from)) {
        jsim.replace(at, from.size(), (fs::path(GLINT_TEST_DATA_DIR) / "render").string() + "/");
    }
    std::ofstream(dir / "recorder.jsim") << jsim;
    (void)detail::plan_render(load(dir / "recorder.jsim"), options_into(dir / "out"), {});
}

TEST(Telemetry, TwoRecordersWritingOneFileAreRefused) {
    test::TempDir dir;
    const std::string clock =
        "<clock type=\"independent\" temporalunits=\"hertz\"><rate>1</rate></clock>";
    try {
        prepare_with(dir.path(), "<instrument name=\"A\" type=\"datarecorder\">" + clock +
                                     "<output><basename>log</basename></output></instrument>"
                                     "<instrument name=\"B\" type=\"datarecorder\">" +
                                     clock +
                                     "<output><basename>log</basename></output>"
                                     "</instrument>");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(e.message().find("data recorder \"B\" would write " +
                                   (dir / "out" / "log.csv").string() +
                                   ", which another recorder writes"),
                  std::string::npos)
            << e.message();
        EXPECT_NE(e.context().file.find("recorder.platform"), std::string::npos);
    }
}

TEST(Telemetry, ExternalTriggerClockOfTheRecorderItselfIsRefused) {
    test::TempDir dir;
    std::ofstream(dir / "triggers.txt") << "0.1\n0.2\n";
    EXPECT_THROW(prepare_with(dir.path(),
                              "<instrument name=\"A\" type=\"datarecorder\"><clock "
                              "type=\"external\"><filename>triggers.txt</filename></clock>"
                              "</instrument>"),
                 Error);
}

}  // namespace telemetry_test
}  // namespace glint::render
