// SPDX-License-Identifier: Apache-2.0
// Schedule::build and the capture generator on the tests/data/schedule inputs: sources and
// counts, the sorted interleaving of several focal planes (ties by plugin, instrument, focal
// plane, task), gapless capture indices, zero-length, straddling and overlapping tasks,
// synchronous and triggered clocks, two entries sharing a platform, output names,
// scale_resolution, the 3.6e8-capture line scanner, and bad inputs with their messages.
#include "glint/schedule/schedule.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "glint/core/error.h"
#include "glint/inputs/load.h"
#include "glint/test/schedules.h"
#include "glint/test/temp_dir.h"

namespace glint::schedule {
namespace schedule_test {

using ::testing::DoubleNear;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kData = GLINT_TEST_DATA_DIR "/schedule";

Schedule load(const std::string& name, const ScheduleOptions& options, Diagnostics& diagnostics) {
    return test::load_schedule(kData + "/" + name, options, diagnostics);
}

Schedule load(const std::string& name, const ScheduleOptions& options = {}) {
    Diagnostics diagnostics;
    return load(name, options, diagnostics);
}

/// The message load() throws (what()), with the diagnostics it left.
std::string load_error(const std::string& name, Diagnostics& diagnostics,
                       const ScheduleOptions& options = {}) {
    try {
        load(name, options, diagnostics);
    } catch (const Error& error) {
        return error.what();
    }
    return "no error";
}

std::vector<std::string> error_texts(const Diagnostics& diagnostics) {
    std::vector<std::string> texts;
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == Diagnostic::Severity::error) texts.push_back(d.text());
    }
    return texts;
}

std::vector<Capture> all_captures(const Schedule& schedule) {
    std::vector<Capture> captures;
    Schedule::Generator generator = schedule.captures();
    while (std::optional<Capture> capture = generator.next()) captures.push_back(*capture);
    return captures;
}

/// Checks the generator's invariants: global index 0, 1, …; sorted by (t0, source, task);
/// capture_index 0, 1, … per (source, task) in time order; as many as count() says.
void expect_well_ordered(const Schedule& schedule, const std::vector<Capture>& captures) {
    std::map<std::pair<std::size_t, std::size_t>, std::uint64_t> next_index;
    for (std::size_t i = 0; i < captures.size(); ++i) {
        const Capture& c = captures[i];
        ASSERT_EQ(c.index, i);
        if (i > 0) {
            const Capture& p = captures[i - 1];
            ASSERT_LE(std::tie(p.t0_s, p.source, p.task_index),
                      std::tie(c.t0_s, c.source, c.task_index))
                << i;
        }
        std::uint64_t& expected = next_index[{c.source, c.task_index}];
        ASSERT_EQ(c.capture_index, expected) << i;
        ++expected;
        EXPECT_EQ(c.t0_s, schedule.ticks(c.source, c.task_index).time_s(c.capture_index));
        EXPECT_EQ(c.t1_s, c.t0_s + schedule.sources()[c.source].window_s());
    }
    std::uint64_t total = 0;
    for (std::size_t s = 0; s < schedule.sources().size(); ++s) {
        const PluginSchedule& plugin = schedule.plugins()[schedule.sources()[s].plugin];
        for (std::size_t t = 0; t < plugin.tasks.tasks.size(); ++t) {
            const auto found = next_index.find({s, t});
            EXPECT_EQ(schedule.count(s, t), found == next_index.end() ? 0u : found->second);
            total += schedule.count(s, t);
        }
    }
    EXPECT_EQ(total, captures.size());
    EXPECT_EQ(schedule.total_captures(), captures.size());
}

TEST(Schedule, SourcesAreTheEnabledFocalPlanesInInstrumentOrder) {
    Diagnostics diagnostics;
    const Schedule schedule = load("frames.jsim", {}, diagnostics);
    ASSERT_EQ(schedule.plugins().size(), 1u);
    EXPECT_EQ(schedule.plugins()[0].plugin_index, 1u);  // after the BasicAtmosphere
    EXPECT_EQ(schedule.plugins()[0].tasks.tasks.size(), 3u);
    ASSERT_EQ(schedule.sources().size(), 3u);
    std::vector<std::tuple<std::size_t, std::size_t, std::string>> seen;
    for (const ClockedFocalPlane& s : schedule.sources()) {
        seen.emplace_back(s.instrument_index, s.focal_plane_index, s.focal_plane->name);
        EXPECT_EQ(&schedule.plugins()[0].poses->instrument_path(s.instrument_index).instrument[0],
                  s.instrument);
    }
    EXPECT_THAT(seen, ElementsAre(std::make_tuple(0u, 0u, "Fast"), std::make_tuple(0u, 1u, "Slow"),
                                  std::make_tuple(1u, 0u, "Line")));
    const ClockedFocalPlane& fast = schedule.sources()[0];
    EXPECT_EQ(fast.x_count, 8u);
    EXPECT_EQ(fast.y_count, 6u);
    EXPECT_EQ(fast.problems_per_capture, 48u);
    EXPECT_EQ(fast.integration_time_s, 0.08);
    EXPECT_EQ(fast.tdi_stages, 1u);
    EXPECT_EQ(fast.lines_per_capture(), 6u);
    EXPECT_EQ(fast.window_s(), 0.08);
    const ClockedFocalPlane& line = schedule.sources()[2];
    EXPECT_EQ(line.problems_per_capture, 16u);  // TDI: one line per capture
    EXPECT_EQ(line.tdi_stages, 4u);
    EXPECT_EQ(line.lines_per_capture(), 1u);
    EXPECT_EQ(line.window_s(), 4 * 0.001);  // stage k integrates during [t0 + k t, t0 + (k+1) t]
    // The data recorder has no focal plane: no source (its reader warned that it has no clock
    // at all; its own <clock> would make no capture either, docs/data-recorder.md).
    for (const ClockedFocalPlane& source : schedule.sources()) {
        EXPECT_NE(source.instrument->name, "Recorder");
    }
}

TEST(Schedule, CountsPerSourceAndTask) {
    const Schedule schedule = load("frames.jsim");
    // Tasks: [0, 1] s, the instant 2 s, [0.5, 1.5] s. Fast 10 Hz from 0.05 s, Slow 4 Hz,
    // Line 10 Hz: ticks at a task's start and stop count.
    const std::vector<std::vector<std::uint64_t>> expected{{10, 1, 10}, {5, 1, 5}, {11, 1, 11}};
    for (std::size_t s = 0; s < 3; ++s) {
        for (std::size_t t = 0; t < 3; ++t) EXPECT_EQ(schedule.count(s, t), expected[s][t]);
    }
    EXPECT_EQ(schedule.total_captures(), 55u);
    EXPECT_EQ(schedule.total_problems(), 21u * 48 + 11u * 8 + 23u * 16);
    EXPECT_THROW(schedule.count(3, 0), Error);
    EXPECT_THROW(schedule.count(0, 3), Error);
}

TEST(Schedule, FocalPlanesInterleaveInTimeOrderWithGaplessIndices) {
    const Schedule schedule = load("frames.jsim");
    const std::vector<Capture> captures = all_captures(schedule);
    ASSERT_EQ(captures.size(), 55u);
    expect_well_ordered(schedule, captures);
    // (source, task, capture_index, t0) of the first captures: at 0 s Slow (instrument 0,
    // focal plane 1) before Line (instrument 1); at 0.25 s Fast before Slow.
    std::vector<std::tuple<std::size_t, std::size_t, std::uint64_t>> head;
    std::vector<double> times;
    for (std::size_t i = 0; i < 9; ++i) {
        head.emplace_back(captures[i].source, captures[i].task_index, captures[i].capture_index);
        times.push_back(captures[i].t0_s);
    }
    EXPECT_THAT(head, ElementsAre(std::make_tuple(1u, 0u, 0u), std::make_tuple(2u, 0u, 0u),
                                  std::make_tuple(0u, 0u, 0u), std::make_tuple(2u, 0u, 1u),
                                  std::make_tuple(0u, 0u, 1u), std::make_tuple(2u, 0u, 2u),
                                  std::make_tuple(0u, 0u, 2u), std::make_tuple(1u, 0u, 1u),
                                  std::make_tuple(2u, 0u, 3u)));
    EXPECT_THAT(times, ElementsAre(0.0, 0.0, 0.05, 0.1, DoubleNear(0.15, 1e-15), 0.2, 0.25, 0.25,
                                   DoubleNear(0.3, 1e-15)));
}

TEST(Schedule, OverlappingTasksAreSortedTogetherTiesByTask) {
    const Schedule schedule = load("frames.jsim");
    const std::vector<Capture> captures = all_captures(schedule);
    // At 0.5 s: Slow in task 0 then task 2, then Line in task 0 then task 2.
    std::vector<std::tuple<std::size_t, std::size_t, std::uint64_t>> at_half;
    for (const Capture& c : captures) {
        if (c.t0_s == 0.5) at_half.emplace_back(c.source, c.task_index, c.capture_index);
    }
    EXPECT_THAT(at_half, ElementsAre(std::make_tuple(1u, 0u, 2u), std::make_tuple(1u, 2u, 0u),
                                     std::make_tuple(2u, 0u, 5u), std::make_tuple(2u, 2u, 0u)));
}

TEST(Schedule, ZeroLengthTaskAndStraddlingWindows) {
    const Schedule schedule = load("frames.jsim");
    const std::vector<Capture> captures = all_captures(schedule);
    std::vector<std::size_t> snap_sources;
    for (const Capture& c : captures) {
        if (c.task_index != 1) continue;
        snap_sources.push_back(c.source);
        EXPECT_EQ(c.capture_index, 0u);
        EXPECT_EQ(c.t0_s, 2.0);  // at the instant, not on a tick (Fast ticks at 1.95, 2.05)
    }
    EXPECT_THAT(snap_sources, ElementsAre(0u, 1u, 2u));
    // Fast's last capture of task 0 starts at 0.95 s (inside) and integrates past the stop.
    const Capture* last = nullptr;
    for (const Capture& c : captures) {
        if (c.source == 0 && c.task_index == 0) last = &c;
    }
    ASSERT_NE(last, nullptr);
    EXPECT_EQ(last->capture_index, 9u);
    EXPECT_NEAR(last->t0_s, 0.95, 1e-15);
    EXPECT_NEAR(last->t1_s, 1.03, 1e-15);
}

TEST(Schedule, OutputNamesForTheThreeSchedules) {
    ScheduleOptions options;
    options.output_folder = "runs";
    options.output_prefix = "a_";
    const Schedule schedule = load("frames.jsim", options);
    EXPECT_EQ(schedule.plugins()[0].output_folder, "runs");
    EXPECT_EQ(schedule.plugins()[0].output_prefix, "a_");
    Capture capture;
    capture.source = 0;  // Fast: capture schedule, truth by task (the disabled one left out)
    capture.task_index = 0;
    capture.capture_index = 3;
    EXPECT_EQ(schedule.image_file(capture), "runs/a_fast-t0000-c0003.img");
    EXPECT_THAT(schedule.truth_files(capture), ElementsAre("runs/a_fast_truth-t0000.img"));
    capture.source = 1;  // Slow: task schedule
    capture.task_index = 2;
    EXPECT_EQ(schedule.image_file(capture), "runs/a_slow-t0002.img");
    EXPECT_TRUE(schedule.truth_files(capture).empty());
    capture.source = 2;  // Line: simulation schedule
    EXPECT_EQ(schedule.image_file(capture), "runs/a_line.img");

    const Schedule plain = load("frames.jsim");
    EXPECT_EQ(plain.plugins()[0].output_folder, "");
    capture.source = 0;
    EXPECT_EQ(plain.image_file(capture), "fast-t0002-c0003.img");
}

TEST(Schedule, IndicesBeyondFourDigitsAreWrittenInFull) {
    model::ImageFile image;
    image.basename = "frame";
    image.schedule = model::ImageSchedule::capture;
    EXPECT_EQ(output_file(image, "", "", 7, 42), "frame-t0007-c0042.img");
    EXPECT_EQ(output_file(image, "out/", "p_", 10000, 123456), "out/p_frame-t10000-c123456.img");
    image.schedule = model::ImageSchedule::task;
    EXPECT_EQ(output_file(image, "out", "", 9999, 5), "out/frame-t9999.img");
    image.schedule = model::ImageSchedule::simulation;
    image.extension = "";
    EXPECT_EQ(output_file(image, "", "", 1, 1), "frame");
}

TEST(Schedule, EntriesSharingAPlatformAreToldApartByPrefixAndFolder) {
    ScheduleOptions options;
    options.output_folder = "cli";
    options.output_prefix = "ignored_";
    const Schedule schedule = load("constellation.jsim", options);
    ASSERT_EQ(schedule.plugins().size(), 2u);
    EXPECT_EQ(schedule.plugins()[0].plugin_index, 0u);
    EXPECT_EQ(schedule.plugins()[1].plugin_index, 2u);
    EXPECT_EQ(schedule.plugins()[0].output_folder, "cli");  // the .jsim sets only the prefix
    EXPECT_EQ(schedule.plugins()[0].output_prefix, "sat1_");
    EXPECT_EQ(schedule.plugins()[1].output_folder, "out");
    EXPECT_EQ(schedule.plugins()[1].output_prefix, "sat2_");
    ASSERT_EQ(schedule.sources().size(), 6u);
    const std::vector<Capture> captures = all_captures(schedule);
    ASSERT_EQ(captures.size(), 52u);
    expect_well_ordered(schedule, captures);
    // At 0 s: the first entry's Slow and Line, then the second entry's.
    std::vector<std::size_t> first_sources;
    for (std::size_t i = 0; i < 4; ++i) first_sources.push_back(captures[i].source);
    EXPECT_THAT(first_sources, ElementsAre(1u, 2u, 4u, 5u));
    EXPECT_EQ(schedule.image_file(captures[0]), "cli/sat1_slow-t0000.img");
    EXPECT_EQ(schedule.image_file(captures[2]), "out/sat2_slow-t0000.img");
}

TEST(Schedule, EntriesWritingTheSameFilesAreAnError) {
    Diagnostics diagnostics;
    const std::string error = load_error("collision.jsim", diagnostics);
    EXPECT_THAT(error, HasSubstr("collision.jsim:"));
    EXPECT_THAT(error,
                HasSubstr("output file \"sat_fast-t0000-c0000.img\" of plugin_list[1] (instrument "
                          "\"Camera\" focal plane \"Fast\") is also written by plugin_list[0] "
                          "(instrument \"Camera\" focal plane \"Fast\"): give the BasicPlatform "
                          "entries different output_prefix or output_folder values (and 3 more "
                          "errors)"));
    const std::vector<std::string> errors = error_texts(diagnostics);
    ASSERT_EQ(errors.size(), 4u);
    EXPECT_THAT(errors[1], HasSubstr("\"sat_fast_truth-t0000.img\""));
}

/// Writes `platform` as <name>.platform in `dir` and <name>.jsim flying it with hover.ppd
/// over one.tasks.
void write_hover_simulation(const std::filesystem::path& dir, const std::string& name,
                            const std::string& platform) {
    std::ofstream(dir / (name + ".platform")) << platform;
    std::ofstream(dir / (name + ".jsim"))
        << R"([{"plugin_list": [{"name": "BasicPlatform", "inputs": {)"
        << R"("platform_filename": ")" << name << R"(.platform", "motion_filename": ")" << kData
        << R"(/hover.ppd", "tasks_filename": ")" << kData << R"(/one.tasks"}}]}])";
}

TEST(Schedule, FocalPlanesOfOneEntryWritingTheSameFileAreAnError) {
    // frames.platform with Slow writing Fast's files.
    const test::TempDir dir;
    std::ifstream in(kData + "/frames.platform");
    std::string platform((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string slow =
        "<basename>slow</basename><extension>img</extension>\n"
        "                <schedule>task</schedule>";
    ASSERT_NE(platform.find(slow), std::string::npos);
    platform.replace(platform.find(slow), slow.size(),
                     "<basename>fast</basename><extension>img</extension>\n"
                     "                <schedule>capture</schedule>");
    write_hover_simulation(dir.path(), "same", platform);
    Diagnostics diagnostics;
    try {
        test::load_schedule(dir / "same.jsim", {}, diagnostics);
        ADD_FAILURE() << "no error";
    } catch (const Error& error) {
        EXPECT_EQ(error.what(),
                  (dir / "same.platform").string() +
                      ":65: platform/attachment/mount[Belly]/attachment/instrument[Camera]/"
                      "focalplane[Slow]/capturemethod[Simple]/imagefile: output file "
                      "\"fast-t0000-c0000.img\" of instrument \"Camera\" focal plane \"Slow\" is "
                      "also written by instrument \"Camera\" focal plane \"Fast\", expected "
                      "different basenames");
    }
}

TEST(Schedule, EmptyTruthCollectionsClaimNoFile) {
    // frames.platform's Fast focal plane with the collections a GUI leaves: two named "truth"
    // writing truth.img, one with an empty <collectorlist/>, one without a list. They collect
    // nothing, so they name no file and do not clash (they were refused as writing the same
    // file); the collection with a collector still names its own.
    const test::TempDir dir;
    std::ifstream in(kData + "/frames.platform");
    std::string platform((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string off_start = "<truthcollection>\n              <enabled>false</enabled>";
    ASSERT_NE(platform.find(off_start), std::string::npos);
    const std::string empty =
        "<truthcollection><enabled>true</enabled><name>truth</name>"
        "<imagefile><basename>truth</basename></imagefile><collectorlist/></truthcollection>\n"
        "            <truthcollection><enabled>true</enabled><name>truth</name>"
        "<imagefile><basename>truth</basename></imagefile></truthcollection>\n            ";
    platform.insert(platform.find(off_start), empty);
    write_hover_simulation(dir.path(), "gui", platform);
    Diagnostics diagnostics;
    const Schedule schedule = test::load_schedule(dir / "gui.jsim", {}, diagnostics);
    EXPECT_FALSE(diagnostics.has_errors());
    // The reader says of each that it collects nothing.
    int nothing = 0;
    for (const Diagnostic& item : diagnostics.items()) {
        if (item.message.find("nothing to collect") != std::string::npos) ++nothing;
    }
    EXPECT_EQ(nothing, 2);
    const std::vector<Capture> captures = all_captures(schedule);
    bool fast_seen = false;
    for (const Capture& capture : captures) {
        if (schedule.sources()[capture.source].focal_plane->name != "Fast") continue;
        fast_seen = true;
        const std::vector<std::filesystem::path> files = schedule.truth_files(capture);
        ASSERT_EQ(files.size(), 1u);
        EXPECT_EQ(files[0].filename().string().rfind("fast_truth", 0), 0u) << files[0];
    }
    EXPECT_TRUE(fast_seen);
}

TEST(Schedule, SynchronousAndTriggeredClocks) {
    const Schedule schedule = load("clocks.jsim");
    ASSERT_EQ(schedule.sources().size(), 4u);  // Div4, Every, Seconds, External
    // Tasks [0, 0.2] s and [0, 2] s; master 100 Hz from 0.01 s; triggers 0 0.1 0.2 0.35 0.5
    // repeating every 0.625 s.
    const std::vector<std::vector<std::uint64_t>> expected{{5, 50}, {20, 200}, {1, 3}, {3, 17}};
    for (std::size_t s = 0; s < 4; ++s) {
        for (std::size_t t = 0; t < 2; ++t) EXPECT_EQ(schedule.count(s, t), expected[s][t]) << s;
    }
    EXPECT_THAT(schedule.sources()[3].trigger_times_s, ElementsAre(0.0, 0.1, 0.2, 0.35, 0.5));
    const std::vector<Capture> captures = all_captures(schedule);
    EXPECT_EQ(captures.size(), 299u);
    expect_well_ordered(schedule, captures);
    std::vector<double> external;
    for (const Capture& c : captures) {
        if (c.source == 3 && c.task_index == 1) external.push_back(c.t0_s);
    }
    ASSERT_EQ(external.size(), 17u);
    EXPECT_NEAR(external[5], 0.625, 1e-12);  // first trigger of the first repetition
    EXPECT_NEAR(external[16], 1.975, 1e-12);
}

TEST(Schedule, RollingLineTimeIsNoneForGlobalShuttersAndTdi) {
    model::FocalPlane plane;
    ClockedFocalPlane source;
    source.focal_plane = &plane;                            // never null in a loaded schedule
    EXPECT_EQ(source.rolling_line_time_s(), std::nullopt);  // global shutter
    plane.detector_array.rolling_line_time_s = 2e-5;
    EXPECT_EQ(source.rolling_line_time_s(), 2e-5);
    source.tdi_stages = 4;
    EXPECT_EQ(source.rolling_line_time_s(), std::nullopt);  // stages read once per capture
}

TEST(Schedule, ScaleResolutionScalesPixelCounts) {
    ScheduleOptions options;
    options.scale_resolution = 0.5;
    const Schedule half = load("frames.jsim", options);
    EXPECT_EQ(half.sources()[0].x_count, 4u);
    EXPECT_EQ(half.sources()[0].y_count, 3u);
    EXPECT_EQ(half.sources()[1].x_count, 2u);
    EXPECT_EQ(half.sources()[1].y_count, 1u);
    EXPECT_EQ(half.sources()[2].x_count, 8u);
    EXPECT_EQ(half.sources()[2].y_count, 4u);  // TDI stages are not resolution
    EXPECT_EQ(half.sources()[2].tdi_stages, 4u);
    EXPECT_EQ(half.total_problems(), 21u * 12 + 11u * 2 + 23u * 8);
    options.scale_resolution = 0.1;  // rounds to 0: at least one pixel
    const Schedule tiny = load("frames.jsim", options);
    EXPECT_EQ(tiny.sources()[1].x_count, 1u);
    EXPECT_EQ(tiny.sources()[1].y_count, 1u);
    options.scale_resolution = 2.5;
    EXPECT_EQ(load("frames.jsim", options).sources()[0].x_count, 20u);
}

TEST(Schedule, BadScaleResolution) {
    ScheduleOptions options;
    options.scale_resolution = 0.0;
    Diagnostics diagnostics;
    EXPECT_EQ(load_error("frames.jsim", diagnostics, options),
              "--scale_resolution 0 is not a positive number, expected a factor > 0");
    options.scale_resolution = 1e5;
    EXPECT_THAT(load_error("frames.jsim", diagnostics, options),
                HasSubstr("frames.platform:42: platform/attachment/mount[Belly]/attachment/"
                          "instrument[Camera]/focalplane[Fast]/detectorarray: --scale_resolution "
                          "1e+05 makes the 8x6 detector array 800000x600000 elements, expected at "
                          "most 1000000 per axis and 2^31 in all (and 2 more errors)"));
}

TEST(Schedule, TenHoursAtTenKilohertz) {
    const Schedule schedule = load("line_scanner.jsim");
    EXPECT_EQ(schedule.total_captures(), 360000001u);
    EXPECT_EQ(schedule.total_problems(), 360000001000u);
    Schedule::Generator generator = schedule.captures();
    for (std::uint64_t i = 0; i < 100000; ++i) {
        const std::optional<Capture> capture = generator.next();
        ASSERT_TRUE(capture.has_value());
        ASSERT_EQ(capture->index, i);
        ASSERT_EQ(capture->capture_index, i);
        ASSERT_EQ(capture->t0_s, static_cast<double>(i) / 10000.0);
    }
}

TEST(Schedule, AScheduleMovesWithItsGenerator) {
    Schedule schedule = load("frames.jsim");
    Schedule::Generator generator = schedule.captures();
    const Schedule moved = std::move(schedule);
    std::uint64_t count = 0;
    while (generator.next()) ++count;
    EXPECT_EQ(count, moved.total_captures());
}

TEST(Schedule, ClockRateOfZeroIsAnError) {
    Diagnostics diagnostics;
    const std::string error = load_error("bad_rate.jsim", diagnostics);
    EXPECT_EQ(error, kData +
                         "/bad_rate.platform:43: platform/attachment/mount[Belly]/attachment/"
                         "instrument[Camera]/focalplane[Zero]/detectorarray/clock/rate: expected "
                         "a number > 0, got \"0\"");
    EXPECT_TRUE(diagnostics.has_errors());
}

TEST(Schedule, BadTriggerFilesAreErrorsAtFileAndLine) {
    Diagnostics diagnostics;
    const std::string error = load_error("bad_triggers.jsim", diagnostics);
    EXPECT_EQ(error, kData +
                         "/nonnumeric_triggers.txt:3: trigger time \"soon\" is not a finite "
                         "number, expected seconds after the reference time (and 1 more error)");
    EXPECT_THAT(error_texts(diagnostics),
                ElementsAre(kData + "/nonnumeric_triggers.txt:3: trigger time \"soon\" is not a "
                                    "finite number, expected seconds after the reference time",
                            kData + "/decreasing_triggers.txt:4: trigger time 0.4 s is before the "
                                    "previous one (0.5 s at line 3), expected strictly increasing "
                                    "times"));
}

TEST(Schedule, TaskEndingBeforeItStartsIsAnError) {
    Diagnostics diagnostics;
    const std::string error = load_error("bad_window.jsim", diagnostics);
    EXPECT_EQ(error, kData +
                         "/bad_window.tasks:16: tasklist/task/stop: stop time 1 s is before "
                         "start time 3 s: expected stop >= start");
}

TEST(Schedule, MissingPlatformIsAnError) {
    Diagnostics diagnostics;
    const std::string error = load_error("missing_platform.jsim", diagnostics);
    EXPECT_EQ(error, kData +
                         "/missing_platform.jsim:5: [0].plugin_list[0].inputs.platform_filename: "
                         "platform file does not exist: " +
                         kData + "/nowhere.platform");
    EXPECT_TRUE(diagnostics.has_errors());
}

TEST(Schedule, LegacySimFileTakesTheCommandLineFolderAndPrefix) {
    ScheduleOptions options;
    options.output_folder = "out";
    options.output_prefix = "p_";
    const Schedule schedule = load("../legacy/example.sim", options);
    ASSERT_EQ(schedule.sources().size(), 1u);
    EXPECT_EQ(schedule.total_captures(), 21u);  // 10 Hz over [1, 3] s, both ends included
    const std::vector<Capture> captures = all_captures(schedule);
    expect_well_ordered(schedule, captures);
    EXPECT_EQ(captures.front().t0_s, 1.0);
    EXPECT_EQ(captures.back().t0_s, 3.0);
    EXPECT_EQ(schedule.image_file(captures[20]), "out/p_rgb-t0000-c0020.img");
    EXPECT_THAT(schedule.truth_files(captures[20]), ElementsAre("out/p_rgb_truth-t0000-c0020.img"));
}

TEST(Schedule, MissingSimulationIsAnError) {
    Diagnostics diagnostics;
    EXPECT_THAT(load_error("no_such.jsim", diagnostics), HasSubstr("no_such.jsim"));
}

}  // namespace schedule_test
}  // namespace glint::schedule

namespace glint::schedule {
namespace schedule_test {

TEST(ScheduleScene, PosesUseTheSceneOriginAndTrackNamedInstances) {
    // A camera hovering 500 m over the origin tracks the instance truck_01, which drives east
    // from (100, 50, 0) at 10 m/s: its boresight must point at the truck at every capture.
    Diagnostics diagnostics;
    const Schedule schedule = load("tracking/tracking.jsim", {}, diagnostics);
    EXPECT_DOUBLE_EQ(schedule.frame().origin().latitude_deg, 43.1);
    EXPECT_DOUBLE_EQ(schedule.frame().origin().altitude_m, 120.0);
    const motion::PoseService& poses = *schedule.plugins().front().poses;
    for (double t : {0.0, 2.5, 7.0, 10.0}) {
        const motion::Rigid r = poses.instrument_to_scene(0, t);
        const motion::Vec3 look = motion::apply_direction(r, motion::kInstrumentBoresight);
        const motion::Vec3 truck{100.0 + 10.0 * t, 50.0, 0.0};
        const motion::Vec3 expected = motion::normalized(truck - r.translation_m);
        // Both unit vectors: 1e-9 rad is rounding in the mount chain.
        EXPECT_LT(motion::norm(look - expected), 1e-9) << "t = " << t;
    }
}

TEST(ScheduleScene, AnUnknownTargetNameIsAnInputErrorAtTheMount) {
    Diagnostics diagnostics;
    inputs::LoadOptions load;
    load.atmosphere = false;
    model::SimulationInputs loaded =
        inputs::load(kData + "/tracking/tracking.jsim", load, Log{}, diagnostics);
    loaded.scene.instances.clear();  // no instances at all
    try {
        Schedule::build(loaded, {}, Log{}, diagnostics);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_THAT(std::string(e.what()),
                    testing::HasSubstr("tracker.platform:5: platform/attachment/mount[Tracker]: "
                                       "mount \"Tracker\": the scene has no target named "
                                       "\"truck_01\""));
    }
}

}  // namespace schedule_test
}  // namespace glint::schedule
