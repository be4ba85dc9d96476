// SPDX-License-Identifier: Apache-2.0
// glint-schedule called in-process on tests/data/schedule_tool: the JSON document (header,
// self-contained captures in schedule order, totals), poses equal to the pose service's at
// mid-window, sun angles equal to NREL SPA's, the capture_list view, the text table, the
// summary (analytic equals enumerated), filters, shards (their union is the schedule, no
// capture twice), the seed's effect, --output_prefix/--scale_resolution, atomic files, and
// the failure cases (message, status, nothing written).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "glint/app_schedule/schedule_tool.h"
#include "glint/core/error.h"
#include "glint/dirsig/readers.h"
#include "glint/inputs/load.h"
#include "glint/motion/pose_service.h"
#include "glint/motion/sun.h"
#include "glint/test/temp_dir.h"

namespace glint::app_schedule {
namespace run_test {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kData = fs::path(GLINT_TEST_DATA_DIR) / "schedule_tool";

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

class ScheduleToolTest : public ::testing::Test {
protected:
    ScheduleToolTest() {
        m_ctx.log = Log(
            [this](LogLevel level, const std::string& message) {
                m_log.push_back(std::string(log_level_name(level)) + ": " + message);
            },
            LogLevel::debug);
        m_options.input = kData / "small.jsim";
        m_ctx.arguments = {"glint-schedule", "small.jsim"};
    }

    /// Runs with m_options; returns stdout.
    std::string run_tool(int expected_status = 0) {
        std::ostringstream out;
        EXPECT_EQ(run(m_options, m_ctx, out), expected_status);
        return out.str();
    }
    Json run_json() { return Json::parse(run_tool()); }

    bool logged(const std::string& needle) const {
        for (const std::string& line : m_log) {
            if (line.find(needle) != std::string::npos) return true;
        }
        return false;
    }

    Context m_ctx;
    Options m_options;
    std::vector<std::string> m_log;
    test::TempDir m_temp;
};

TEST_F(ScheduleToolTest, JsonHeaderAndTotals) {
    const Json j = run_json();
    EXPECT_EQ(j["format"], "glint-schedule");
    EXPECT_EQ(j["version"], 1);
    EXPECT_EQ(j["provenance"]["tool"], "glint-schedule");
    EXPECT_EQ(j["provenance"]["seed"], 1);
    EXPECT_EQ(j["provenance"]["arguments"], Json::array({"glint-schedule", "small.jsim"}));
    EXPECT_FALSE(j["provenance"]["glint_version"].get<std::string>().empty());
    EXPECT_EQ(j["provenance"]["working_folder"], std::filesystem::current_path().generic_string());
    EXPECT_EQ(j["reference_datetime"], "2020-06-21T16:00:00.000000Z");  // 12:00-04:00
    ASSERT_EQ(j["plugins"].size(), 2u);
    const Json& first = j["plugins"][0];
    EXPECT_EQ(first["plugin_index"], 0);
    EXPECT_EQ(first["output_folder"], "out");
    EXPECT_EQ(first["output_prefix"], "");
    EXPECT_EQ(first["tasks"].size(), 2u);
    EXPECT_EQ(first["tasks"][1]["name"], "Second pass");
    EXPECT_EQ(first["tasks"][1]["start_s"], 5.0);
    EXPECT_EQ(first["tasks"][1]["stop_s"], 5.5);
    // RGB 10 Hz: 11 + 6 captures, NIR 5 Hz: 6 + 3, Pan 20 Hz: 21 + 11.
    EXPECT_EQ(first["tasks"][0]["capture_count"], 11 + 6 + 21);
    EXPECT_EQ(first["tasks"][1]["capture_count"], 6 + 3 + 11);
    EXPECT_EQ(j["plugins"][1]["plugin_index"], 2);  // BasicAtmosphere is plugin 1
    EXPECT_EQ(j["plugins"][1]["output_prefix"], "b_");
    // Plugin 2: one task [1.5, 2] s: RGB 6, NIR 3 (1.6, 1.8, 2.0), Pan 11.
    EXPECT_EQ(j["plugins"][1]["tasks"][0]["capture_count"], 6 + 3 + 11);
    const std::uint64_t captures = 38 + 20 + 20;
    EXPECT_EQ(j["captures"].size(), captures);
    EXPECT_EQ(j["capture_count"], captures);
    std::uint64_t problems = 0;
    for (const Json& c : j["captures"]) problems += c["problem_count"].get<std::uint64_t>();
    EXPECT_EQ(j["problem_count"], problems);
}

TEST_F(ScheduleToolTest, CapturesAreOrderedNumberedAndSelfContained) {
    const Json j = run_json();
    double last_t0 = -1e300;
    std::map<std::pair<int, int>, std::uint64_t> events;  // (plugin, task) → last event
    for (std::size_t i = 0; i < j["captures"].size(); ++i) {
        const Json& c = j["captures"][i];
        EXPECT_EQ(c["index"], i);
        const double t0 = c["time_window_s"][0];
        const double t1 = c["time_window_s"][1];
        EXPECT_GE(t0, last_t0);
        last_t0 = t0;
        EXPECT_GE(t1, t0);
        EXPECT_NEAR(t1 - t0, c["focal_plane"]["integration_time_s"].get<double>(), 1e-12);
        for (const char* key :
             {"task_index", "capture_index", "event_number", "event_count", "plugin", "instrument",
              "focal_plane", "datetime_utc", "problem_count", "pose", "sun", "files"}) {
            EXPECT_TRUE(c.contains(key)) << key;
        }
        EXPECT_TRUE(c["plugin"].contains("reference_datetime"));
        const auto key =
            std::make_pair(c["plugin"]["index"].get<int>(), c["task_index"].get<int>());
        EXPECT_EQ(c["event_number"], events[key] + 1);
        events[key] = c["event_number"];
        EXPECT_LE(c["event_number"], c["event_count"]);
        EXPECT_EQ(c["problem_count"], c["focal_plane"]["x_count"].get<std::uint64_t>() *
                                          c["focal_plane"]["y_count"].get<std::uint64_t>());
    }
    EXPECT_EQ((events[{0, 0}]), 38u);
    EXPECT_EQ((events[{0, 1}]), 20u);
    EXPECT_EQ((events[{2, 0}]), 20u);
}

TEST_F(ScheduleToolTest, OutputFileNamesFollowTheImageFileSchedule) {
    const Json j = run_json();
    std::set<std::string> pan_files;
    for (const Json& c : j["captures"]) {
        const std::string name = c["focal_plane"]["name"];
        const std::string image = c["files"]["image"];
        const int plugin = c["plugin"]["index"];
        const std::string stem = plugin == 0 ? "out/" : "b_";
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "-t%04d-c%04d", c["task_index"].get<int>(),
                      c["capture_index"].get<int>());
        if (name == "RGB") {
            EXPECT_EQ(image, stem + "rgb" + suffix + ".img");
            ASSERT_EQ(c["files"]["truth"].size(), 1u);
            EXPECT_EQ(c["files"]["truth"][0], stem + "rgb_truth" + suffix + ".img");
        } else if (name == "NIR") {
            EXPECT_EQ(image, stem + "nir" + std::string(suffix).substr(0, 6) + ".img");
            EXPECT_TRUE(c["files"]["truth"].empty());
            ASSERT_TRUE(c.contains("rolling_readout"));
            EXPECT_EQ(c["rolling_readout"]["line_time_s"], 1e-4);
            EXPECT_EQ(c["rolling_readout"]["line_count"], 4);
            EXPECT_NEAR(c["rolling_readout"]["last_line_window_s"][0].get<double>(),
                        c["time_window_s"][0].get<double>() + 3e-4, 1e-12);
        } else {
            EXPECT_EQ(name, "Pan");
            pan_files.insert(image);
            EXPECT_FALSE(c.contains("rolling_readout"));
        }
    }
    EXPECT_EQ(pan_files, (std::set<std::string>{"out/pan.img", "b_pan.img"}));
}

TEST_F(ScheduleToolTest, PosesEqualThePoseServiceAtMidWindow) {
    m_ctx.seed = 7;
    const Json j = run_json();
    Diagnostics diagnostics;
    const std::vector<model::Simulation> simulations =
        dirsig::read_simulation(kData / "small.jsim", {}, diagnostics);
    ASSERT_EQ(simulations.size(), 1u);
    std::map<int, motion::PoseService> services;
    for (int plugin : {0, 2}) {
        const auto entry = inputs::read_platform_entry(simulations[0], plugin, {}, diagnostics);
        ASSERT_TRUE(entry);
        services.emplace(plugin, motion::make_pose_service(*entry, 7, Log{}));
    }
    const motion::SceneFrame frame;
    for (const Json& c : j["captures"]) {
        const motion::PoseService& poses = services.at(c["plugin"]["index"].get<int>());
        const double t_mid =
            0.5 * (c["time_window_s"][0].get<double>() + c["time_window_s"][1].get<double>());
        EXPECT_EQ(c["pose"]["time_s"].get<double>(), t_mid);
        const motion::Rigid expected =
            poses.instrument_to_scene(c["instrument"]["index"].get<std::size_t>(), t_mid);
        const Json& instrument = c["pose"]["instrument"];
        EXPECT_EQ(instrument["position_enu_m"],
                  Json::array({expected.translation_m.x, expected.translation_m.y,
                               expected.translation_m.z}));
        EXPECT_EQ(instrument["orientation_wxyz"],
                  Json::array({expected.rotation.w, expected.rotation.x, expected.rotation.y,
                               expected.rotation.z}));
        const motion::Vec3 ecef = frame.enu_to_ecef(expected.translation_m);
        EXPECT_EQ(instrument["position_ecef_m"], Json::array({ecef.x, ecef.y, ecef.z}));
        const motion::Pose vehicle = poses.vehicle_pose(t_mid);
        const Json& platform = c["pose"]["platform"];
        EXPECT_EQ(platform["position_enu_m"],
                  Json::array({vehicle.position_m.x, vehicle.position_m.y, vehicle.position_m.z}));
        const motion::Geodetic geodetic = frame.enu_to_geodetic(vehicle.position_m);
        EXPECT_EQ(platform["geodetic"]["latitude_deg"], geodetic.latitude_deg);
        EXPECT_EQ(platform["geodetic"]["altitude_m"], geodetic.altitude_m);
    }
    // Plugin 0 flies north at 100 m/s from y = -500 m at t = 0, yawed 10°.
    const Json& first = j["captures"][0];
    EXPECT_NEAR(first["pose"]["platform"]["position_enu_m"][1].get<double>(), -400 + 0.05, 1e-9);
    EXPECT_NEAR(first["pose"]["platform"]["euler_xyz_deg"][2].get<double>(), 10.0, 1e-6);
}

TEST_F(ScheduleToolTest, SunAnglesAreSpaAtTheSceneOriginAtMidWindow) {
    const Json j = run_json();
    const motion::SceneFrame frame;
    for (const Json& c : j["captures"]) {
        const double t_mid = c["pose"]["time_s"];
        const DateTime utc = add_seconds(parse_iso8601("2020-06-21T12:00:00-04:00"), t_mid);
        const motion::SunPosition sun = motion::sun_position(utc, frame);
        EXPECT_EQ(c["sun"]["zenith_deg"].get<double>(), sun.zenith_deg);
        EXPECT_EQ(c["sun"]["azimuth_deg"].get<double>(), sun.azimuth_deg);
        EXPECT_EQ(c["sun"]["direction_enu"].size(), 3u);
    }
    // 16:00 UTC at 78° W on the solstice: late morning, sun high in the south-east.
    const double zenith = j["captures"][0]["sun"]["zenith_deg"];
    const double azimuth = j["captures"][0]["sun"]["azimuth_deg"];
    EXPECT_GT(zenith, 20.0);
    EXPECT_LT(zenith, 30.0);
    EXPECT_GT(azimuth, 120.0);
    EXPECT_LT(azimuth, 150.0);
}

TEST_F(ScheduleToolTest, SeedChangesJitteredPosesOnly) {
    m_ctx.seed = 1;
    const Json a = run_json();
    m_ctx.seed = 2;
    const Json b = run_json();
    ASSERT_EQ(a["captures"].size(), b["captures"].size());
    EXPECT_NE(a["captures"][0]["pose"]["platform"]["orientation_wxyz"],
              b["captures"][0]["pose"]["platform"]["orientation_wxyz"]);
    EXPECT_EQ(a["captures"][0]["files"], b["captures"][0]["files"]);
    m_ctx.seed = 1;
    EXPECT_EQ(run_json(), a) << "same seed, same bytes";
}

TEST_F(ScheduleToolTest, CaptureListMatchesTheSchedule) {
    const Json schedule = run_json();
    m_options.format = OutputFormat::capture_list;
    const Json list = run_json();
    EXPECT_EQ(list["format"], "glint-capture-list");
    EXPECT_EQ(list["run_info"]["reference_date_time"], "2020-06-21T16:00:00.000000Z");
    ASSERT_EQ(list["capture_list"].size(), schedule["captures"].size());
    for (std::size_t i = 0; i < list["capture_list"].size(); ++i) {
        const Json& entry = list["capture_list"][i];
        const Json& capture = schedule["captures"][i];
        EXPECT_EQ(entry["task_index"], capture["task_index"]);
        EXPECT_EQ(entry["capture_index"], capture["capture_index"]);
        EXPECT_EQ(entry["relative_time_window"], capture["time_window_s"]);
        EXPECT_EQ(entry["plugin_data"]["filename"], capture["files"]["image"]);
        EXPECT_EQ(entry["plugin_data"]["truth_filenames"], capture["files"]["truth"]);
    }
}

TEST_F(ScheduleToolTest, LogInfoFileIsWrittenBesideTheSchedule) {
    m_options.output = (m_temp / "schedule.json").string();
    m_options.log_info_file = (m_temp / "log_info.json").string();
    m_options.filters.task = 1;
    EXPECT_EQ(run_tool(), "");
    const Json schedule = Json::parse(read_text(m_temp / "schedule.json"));
    const Json list = Json::parse(read_text(m_temp / "log_info.json"));
    EXPECT_EQ(schedule["capture_count"], 20);
    EXPECT_EQ(list["capture_list"].size(), 20u);
    EXPECT_EQ(m_temp.entries(), (std::vector<std::string>{"log_info.json", "schedule.json"}));
}

TEST_F(ScheduleToolTest, TextTableLooksLikeDirsigConsole) {
    m_options.format = OutputFormat::text;
    const std::string text = run_tool();
    std::istringstream lines(text);
    std::string header;
    std::getline(lines, header);
    EXPECT_NE(header.find("event"), std::string::npos);
    EXPECT_NE(header.find("instrument -> focal plane"), std::string::npos);
    std::string first;
    std::getline(lines, first);
    EXPECT_NE(first.find("1 of 38"), std::string::npos) << first;
    EXPECT_NE(first.find("2020-06-21T12:00:01.000000-04:00"), std::string::npos) << first;
    EXPECT_NE(first.find("1.000000e+00"), std::string::npos) << first;
    EXPECT_NE(first.find("Cam -> RGB"), std::string::npos) << first;
    EXPECT_NE(first.find("0.400000 - 0.700000 @ 0.010000 microns (31 samples)"), std::string::npos)
        << first;
    EXPECT_NE(first.find("16 x 12"), std::string::npos) << first;
    std::size_t rows = 1;
    for (std::string line; std::getline(lines, line);) ++rows;
    EXPECT_EQ(rows, 78u);
}

TEST_F(ScheduleToolTest, FiltersSelectCaptures) {
    m_options.filters.focal_plane = "NIR";
    Json j = run_json();
    EXPECT_EQ(j["captures"].size(), 6u + 3u + 3u);
    for (const Json& c : j["captures"]) EXPECT_EQ(c["focal_plane"]["name"], "NIR");
    EXPECT_EQ(j["selection"]["focal_plane"], "NIR");

    m_options.filters = {};
    m_options.filters.task = 0;
    m_options.filters.focal_plane = "Line/Pan";
    j = run_json();
    EXPECT_EQ(j["captures"].size(), 21u + 11u);

    m_options.filters = {};
    m_options.filters.captures = CaptureRange{10, 15};
    j = run_json();
    ASSERT_EQ(j["captures"].size(), 5u);
    EXPECT_EQ(j["captures"][0]["index"], 10);
    EXPECT_EQ(j["captures"][4]["index"], 14);
    EXPECT_EQ(j["selection"]["captures"], Json::array({10, 15}));
}

TEST_F(ScheduleToolTest, ShardsPartitionTheScheduleBalancedByProblems) {
    const Json full = run_json();
    const std::uint64_t total = full["problem_count"];
    for (std::uint64_t n : {1u, 2u, 3u, 5u, 100u}) {
        std::vector<std::uint64_t> indices;
        for (std::uint64_t k = 1; k <= n; ++k) {
            m_options.filters.shard = ShardSpec{k, n};
            const Json shard = run_json();
            std::uint64_t problems = 0;
            for (const Json& c : shard["captures"]) {
                indices.push_back(c["index"]);
                problems += c["problem_count"].get<std::uint64_t>();
            }
            EXPECT_EQ(shard["problem_count"], problems);
            EXPECT_LE(std::abs(static_cast<double>(problems) - static_cast<double>(total) / n),
                      1024.0)
                << k << "/" << n;
        }
        ASSERT_EQ(indices.size(), full["captures"].size()) << n;
        for (std::size_t i = 0; i < indices.size(); ++i) EXPECT_EQ(indices[i], i) << n;
    }
}

TEST_F(ScheduleToolTest, ShardsOfAFilteredSelection) {
    m_options.filters.focal_plane = "RGB";
    const std::size_t all = run_json()["captures"].size();
    std::size_t sum = 0;
    for (std::uint64_t k = 1; k <= 4; ++k) {
        m_options.filters.shard = ShardSpec{k, 4};
        const std::size_t n = run_json()["captures"].size();
        EXPECT_GE(n, all / 4 - 1);
        EXPECT_LE(n, all / 4 + 2);
        sum += n;
    }
    EXPECT_EQ(sum, all);
}

TEST_F(ScheduleToolTest, SummaryAnalyticEqualsEnumerated) {
    m_options.summary = true;
    m_options.format = OutputFormat::json;
    const Json analytic = run_json();
    EXPECT_EQ(analytic["format"], "glint-schedule-summary");
    EXPECT_EQ(analytic["capture_count"], 78);
    EXPECT_EQ(analytic["task_span_s"], Json::array({1.0, 5.5}));
    EXPECT_EQ(analytic["duration_s"], 4.5);
    EXPECT_TRUE(analytic["capture_span_s"].is_null());
    m_options.filters.captures = CaptureRange{0, std::nullopt};
    const Json enumerated = run_json();
    EXPECT_EQ(enumerated["capture_count"], analytic["capture_count"]);
    EXPECT_EQ(enumerated["problem_count"], analytic["problem_count"]);
    EXPECT_EQ(enumerated["plugins"], analytic["plugins"]);
    EXPECT_EQ(enumerated["capture_span_s"][0], 1.0);
    EXPECT_NEAR(enumerated["capture_span_s"][1].get<double>(), 5.501, 1e-12);  // RGB t1

    m_options.format = OutputFormat::text;
    m_options.filters = {};
    const std::string text = run_tool();
    EXPECT_NE(text.find("captures: 78\n"), std::string::npos) << text;
    EXPECT_NE(text.find("task span: 1.000000 s to 5.500000 s (4.500000 s)"), std::string::npos)
        << text;
}

TEST_F(ScheduleToolTest, TenHourTaskAtTenKilohertzIsCountedNotEnumerated) {
    m_options.input = kData / "ten_hours.jsim";
    m_options.summary = true;
    m_options.format = OutputFormat::json;
    const Json j = run_json();
    EXPECT_EQ(j["capture_count"], 360'000'001u);
    EXPECT_EQ(j["problem_count"], 360'000'001u);
    EXPECT_EQ(j["duration_s"], 36000.0);
}

TEST_F(ScheduleToolTest, CommandLineFolderAndPrefixYieldToTheJsim) {
    m_options.schedule.output_prefix = "cli_";
    m_options.schedule.output_folder = "cli_out";
    const Json j = run_json();
    EXPECT_EQ(j["options"]["output_prefix"], "cli_");
    EXPECT_EQ(j["plugins"][0]["output_folder"], "out");      // from the .jsim
    EXPECT_EQ(j["plugins"][0]["output_prefix"], "cli_");     // from the command line
    EXPECT_EQ(j["plugins"][1]["output_folder"], "cli_out");  // from the command line
    EXPECT_EQ(j["plugins"][1]["output_prefix"], "b_");       // from the .jsim
    EXPECT_EQ(j["captures"][0]["files"]["image"], "out/cli_rgb-t0000-c0000.img");
}

TEST_F(ScheduleToolTest, ScaleResolutionScalesPixelCounts) {
    m_options.schedule.scale_resolution = 2.0;
    const Json j = run_json();
    const Json& rgb = j["captures"][0];
    EXPECT_EQ(rgb["focal_plane"]["name"], "RGB");
    EXPECT_EQ(rgb["focal_plane"]["x_count"], 32);
    EXPECT_EQ(rgb["focal_plane"]["y_count"], 24);
    EXPECT_EQ(rgb["problem_count"], 32 * 24);
    EXPECT_EQ(j["options"]["scale_resolution"], 2.0);
}

TEST_F(ScheduleToolTest, FileOutputIsAtomicAndComplete) {
    m_options.output = (m_temp / "schedule.json").string();
    EXPECT_EQ(run_tool(), "");
    const Json j = Json::parse(read_text(m_temp / "schedule.json"));
    EXPECT_EQ(j["capture_count"], 78);
    EXPECT_EQ(m_temp.entries(), (std::vector<std::string>{"schedule.json"}));
}

TEST_F(ScheduleToolTest, BadInputsWriteNothing) {
    for (const char* name : {"missing_platform.jsim", "zero_rate.jsim", "decreasing_triggers.jsim",
                             "backwards_task.jsim"}) {
        SCOPED_TRACE(name);
        m_log.clear();
        m_options.input = kData / name;
        m_options.output = (m_temp / "schedule.json").string();
        EXPECT_EQ(run_tool(1), "");
        EXPECT_TRUE(logged("nothing written")) << name;
        EXPECT_TRUE(m_temp.entries().empty());
    }
    EXPECT_TRUE(logged("backwards.tasks:7"));
}

TEST_F(ScheduleToolTest, MessagesNameTheProblem) {
    m_options.input = kData / "zero_rate.jsim";
    run_tool(1);
    EXPECT_TRUE(logged("zero_rate.platform:24")) << m_log.front();
    m_log.clear();
    m_options.input = kData / "decreasing_triggers.jsim";
    run_tool(1);
    EXPECT_TRUE(logged("decreasing_triggers.txt:2")) << m_log.front();
}

TEST_F(ScheduleToolTest, UsageErrors) {
    const auto expect_usage = [&](const Options& options, const std::string& needle) {
        std::ostringstream out;
        try {
            run(options, m_ctx, out);
            ADD_FAILURE() << "no usage error for " << needle;
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::usage);
            EXPECT_NE(e.message().find(needle), std::string::npos) << e.message();
        }
        EXPECT_TRUE(m_temp.entries().empty());
    };
    Options options = m_options;
    options.output = (kData / "cams.platform").string();
    expect_usage(options, "refusing to overwrite input");
    options = m_options;
    options.output = (kData / "small.jsim").string();
    expect_usage(options, "refusing to overwrite input");
    options = m_options;
    options.output = (m_temp / "a.json").string();
    options.log_info_file = options.output;
    expect_usage(options, "name the same file");
    options = m_options;
    options.summary = true;
    options.log_info_file = (m_temp / "b.json").string();
    expect_usage(options, "--summary");
}

TEST_F(ScheduleToolTest, UnknownFocalPlaneIsAnInputError) {
    m_options.filters.focal_plane = "SWIR";
    m_options.output = (m_temp / "schedule.json").string();
    std::ostringstream out;
    try {
        run(m_options, m_ctx, out);
        FAIL() << "accepted SWIR";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
    }
    EXPECT_TRUE(m_temp.entries().empty());
}

TEST_F(ScheduleToolTest, CancelLeavesNoFile) {
    m_options.output = (m_temp / "schedule.json").string();
    m_ctx.cancel.cancel();
    std::ostringstream out;
    try {
        run(m_options, m_ctx, out);
        FAIL() << "not cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::cancelled);
    }
    EXPECT_TRUE(m_temp.entries().empty());
}

TEST(ParseOutputFormat, KnowsTheThreeFormats) {
    EXPECT_EQ(parse_output_format("json"), OutputFormat::json);
    EXPECT_EQ(parse_output_format("text"), OutputFormat::text);
    EXPECT_EQ(parse_output_format("capture_list"), OutputFormat::capture_list);
    EXPECT_FALSE(parse_output_format("yaml"));
}

}  // namespace run_test
}  // namespace glint::app_schedule
