// SPDX-License-Identifier: Apache-2.0
// Tests of the detector-array and clock part of the `.platform` reader: the clocks.platform
// fixture (clock table, synchronous clocks, external triggers, rolling readout) field by
// field, and the bad arrays and clocks (counts, sizes, units, clock types, masters), each
// with its message, line and element path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "platform_test_util.h"

namespace glint::test::plat {
namespace array_clock_reader_test {

using ::testing::HasSubstr;
using Severity = Diagnostic::Severity;

const model::FocalPlane& plane_of(const model::Platform& platform, std::size_t instrument,
                                  std::size_t plane) {
    return model::list_instruments(platform).at(instrument).instrument->focal_planes.at(plane);
}

/// A detector array of `body` lines, on lines of their own after the opening tag.
std::string array(const std::string& body, const std::string& attributes = "") {
    return "<detectorarray" + attributes + ">\n" + body + "\n</detectorarray>";
}

constexpr const char* kClock =
    "<clock type=\"independent\" temporalunits=\"hertz\"><rate>10</rate></clock>";

TEST(DetectorReader, ClocksFixtureFieldByField) {
    const Read read = read_fixture("clocks.platform");
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    EXPECT_EQ(read.diagnostics.warning_count(), 0u) << dump(read.diagnostics);
    const model::Platform& p = read.platform;
    ASSERT_EQ(p.clock_table.size(), 2u);
    EXPECT_EQ(p.clock_table[0].name, "Master");
    EXPECT_EQ(p.clock_table[0].rate_hz, 100.0);
    EXPECT_EQ(p.clock_table[0].offset_s, 0.01);
    EXPECT_EQ(p.clock_table[0].where.line, 9);
    EXPECT_EQ(p.clock_table[0].where.element, "platform/clocktable/clock[Master]");
    EXPECT_EQ(p.clock_table[1].name, "Slow");
    EXPECT_EQ(p.clock_table[1].rate_hz, 1.0);

    const model::Clock& sync = plane_of(p, 0, 0).detector_array.clock;
    EXPECT_EQ(sync.type, model::ClockType::synchronous);
    EXPECT_EQ(sync.master, "Master");
    EXPECT_EQ(sync.divider, 4);
    EXPECT_EQ(sync.offset_count, 2);
    const model::Clock& slow = plane_of(p, 0, 1).detector_array.clock;
    EXPECT_EQ(slow.type, model::ClockType::synchronous);
    EXPECT_EQ(slow.master, "Slow");
    EXPECT_EQ(slow.divider, 1);  // defaults
    EXPECT_EQ(slow.offset_count, 0);

    const model::DetectorArray& rolling = plane_of(p, 0, 2).detector_array;
    EXPECT_EQ(rolling.clock.type, model::ClockType::independent);
    EXPECT_EQ(rolling.clock.rate_hz, 30.0);
    EXPECT_EQ(rolling.clock.offset_s, 0.005);
    EXPECT_EQ(rolling.y_count, 480u);
    ASSERT_TRUE(rolling.rolling_line_time_s);
    EXPECT_DOUBLE_EQ(*rolling.rolling_line_time_s, 2.5e-5);
    EXPECT_FALSE(plane_of(p, 0, 0).detector_array.rolling_line_time_s);

    const model::Clock& external = plane_of(p, 1, 0).detector_array.clock;
    EXPECT_EQ(external.type, model::ClockType::external_trigger);
    EXPECT_EQ(external.trigger_file.text, "triggers.txt");
    EXPECT_EQ(external.trigger_file.resolved, fixture_dir() / "triggers.txt");
    EXPECT_TRUE(std::filesystem::exists(external.trigger_file.resolved));
    const model::Clock& irregular = plane_of(p, 1, 1).detector_array.clock;
    EXPECT_EQ(irregular.type, model::ClockType::external_trigger);
    EXPECT_EQ(irregular.trigger_file.resolved, fixture_dir() / "sub" / "more_triggers.txt");
    EXPECT_TRUE(std::filesystem::exists(irregular.trigger_file.resolved));
}

// ---- counts ----------------------------------------------------------------------------------

TEST(DetectorReader, HugeArrayRefusedBeforeAllocation) {
    TempDir dir;
    const std::string text =
        with_detector(array(std::string(kClock) + "\n<xelementcount>10000000</xelementcount>\n"
                                                  "<yelementcount>10000000</yelementcount>\n"
                                                  "<xelementspacing>5</xelementspacing>\n"
                                                  "<yelementspacing>5</yelementspacing>"));
    const Read read = read_text(dir, text);
    expect_diagnostic(read,
                      "xelementcount x yelementcount = 10000000 x 10000000: a detector array so "
                      "large it would exhaust memory (refused before allocation), expected each "
                      "count in [1, 1000000] and at most 2147483648 elements",
                      line_of(text, "<xelementcount>"),
                      std::string(kDetectorPath) + "/xelementcount");
    EXPECT_EQ(read.diagnostics.error_count(), 1u) << dump(read.diagnostics);
    const auto& a = plane_of(read.platform, 0, 0).detector_array;
    EXPECT_EQ(a.x_count, 0u);
    EXPECT_EQ(a.y_count, 0u);
}

TEST(DetectorReader, ProductOverTwoToThe31Refused) {
    TempDir dir;
    const std::string text =
        with_detector(array(std::string(kClock) + "\n<xelementcount>1000000</xelementcount>\n"
                                                  "<yelementcount>2148</yelementcount>\n"
                                                  "<xelementspacing>5</xelementspacing>\n"
                                                  "<yelementspacing>5</yelementspacing>"));
    const Read read = read_text(dir, text);
    expect_diagnostic(read, "1000000 x 2148: a detector array so large it would exhaust memory",
                      line_of(text, "<detectorarray"), kDetectorPath);
    // 1,000,000 x 2,147 = 2.147e9 < 2^31: accepted.
    std::string ok = text;
    ok.replace(ok.find("2148"), 4, "2147");
    const Read fine = read_text(dir, ok);
    EXPECT_FALSE(fine.diagnostics.has_errors()) << dump(fine.diagnostics);
    EXPECT_EQ(plane_of(fine.platform, 0, 0).detector_array.y_count, 2147u);
}

TEST(DetectorReader, NegativeCountIsOutOfRange) {
    TempDir dir;
    const Read negative = read_text(
        dir, with_detector(array(std::string(kClock) +
                                 "\n<xelementcount>-3</xelementcount>\n<yelementcount>2"
                                 "</yelementcount>\n<xelementspacing>5</xelementspacing>\n"
                                 "<yelementspacing>5</yelementspacing>")));
    EXPECT_NE(find(negative.diagnostics, "xelementcount -3 is out of range"), nullptr)
        << dump(negative.diagnostics);
}

// ---- sizes and units -------------------------------------------------------------------------

TEST(DetectorReader, SpacingSmallerThanSize) {
    TempDir dir;
    const std::string text =
        with_detector(array(std::string(kClock) +
                            "\n<xelementcount>2</xelementcount><yelementcount>2</yelementcount>\n"
                            "<xelementsize>5</xelementsize>\n<yelementsize>-1</yelementsize>\n"
                            "<xelementspacing>4</xelementspacing>\n"
                            "<yelementspacing>abc</yelementspacing>"));
    const Read read = read_text(dir, text);
    expect_diagnostic(read,
                      "xelementspacing 4 is smaller than xelementsize 5, expected a spacing >= "
                      "the element size (elements cannot overlap)",
                      line_of(text, "<xelementspacing>"),
                      std::string(kDetectorPath) + "/xelementspacing");
    expect_diagnostic(read, "expected a number > 0, got \"-1\"", line_of(text, "<yelementsize>"),
                      std::string(kDetectorPath) + "/yelementsize");
    expect_diagnostic(read, "expected a number > 0, got \"abc\"",
                      line_of(text, "<yelementspacing>"),
                      std::string(kDetectorPath) + "/yelementspacing");
    EXPECT_EQ(read.diagnostics.error_count(), 3u) << dump(read.diagnostics);
}

TEST(DetectorReader, SpatialUnits) {
    TempDir dir;
    const std::string body = std::string(kClock) +
                             "\n<xelementcount>2</xelementcount><yelementcount>2</yelementcount>"
                             "<xelementspacing>2</xelementspacing><yelementspacing>3"
                             "</yelementspacing><xarrayoffset>1</xarrayoffset>";
    struct Case {
        const char* units;
        double metres;
    };
    for (const Case& c : {Case{"microns", 1e-6}, Case{"um", 1e-6}, Case{"millimeters", 1e-3},
                          Case{"MM", 1e-3}, Case{"meters", 1.0}, Case{"m", 1.0}}) {
        const Read read = read_text(
            dir, with_detector(array(body, " spatialunits=\"" + std::string(c.units) + "\"")));
        ASSERT_FALSE(read.diagnostics.has_errors()) << c.units << "\n" << dump(read.diagnostics);
        const auto& a = plane_of(read.platform, 0, 0).detector_array;
        EXPECT_EQ(a.spatial_units, c.units);
        EXPECT_DOUBLE_EQ(a.x_spacing_m, 2 * c.metres) << c.units;
        EXPECT_DOUBLE_EQ(a.y_size_m, 3 * c.metres) << c.units;
        EXPECT_DOUBLE_EQ(a.x_offset_m, 1 * c.metres) << c.units;
    }
    const std::string text = with_detector(array(body, " spatialunits=\"inches\""));
    const Read bad = read_text(dir, text);
    expect_diagnostic(bad,
                      "unknown spatialunits \"inches\", expected microns, millimeters or meters "
                      "(or um, mm, m)",
                      line_of(text, "<detectorarray"),
                      std::string(kDetectorPath) + "@spatialunits");
    // Default: microns.
    const Read fallback = read_text(dir, with_detector(array(body)));
    EXPECT_DOUBLE_EQ(plane_of(fallback.platform, 0, 0).detector_array.x_spacing_m, 2e-6);
}

TEST(DetectorReader, FlipAxesAndOffsets) {
    TempDir dir;
    const std::string text = with_detector(array(
        std::string(kClock) +
        "\n<xelementcount>2</xelementcount><yelementcount>2</yelementcount>"
        "<xelementspacing>2</xelementspacing><yelementspacing>2</yelementspacing>\n"
        "<xflipaxis>true</xflipaxis>\n<yflipaxis>2</yflipaxis>\n<yarrayoffset>up</yarrayoffset>"));
    const Read read = read_text(dir, text);
    EXPECT_TRUE(plane_of(read.platform, 0, 0).detector_array.x_flip);
    expect_diagnostic(read, "expected a boolean (true, false, yes, no, 1 or 0), got \"2\"",
                      line_of(text, "<yflipaxis>"), std::string(kDetectorPath) + "/yflipaxis");
    expect_diagnostic(read, "expected a number, got \"up\"", line_of(text, "<yarrayoffset>"),
                      std::string(kDetectorPath) + "/yarrayoffset");
}

TEST(DetectorReader, ExtrasWarnAndUnknownsWarn) {
    TempDir dir;
    const std::string text = with_detector(
        array(std::string(kClock) +
              "\n<xelementcount>2</xelementcount><yelementcount>2</yelementcount>"
              "<xelementspacing>2</xelementspacing><yelementspacing>2</yelementspacing>\n"
              "<xoversample>2</xoversample>\n<gain>3</gain>"));
    const Read read = read_text(dir, text);
    EXPECT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    // Oversampling is a raw capture's: on this simple one it is read, not applied.
    expect_diagnostic(read,
                      "<xoversample>/<yoversample> are read, not applied: they oversample a raw "
                      "capture only",
                      line_of(text, "<xoversample>"), std::string(kDetectorPath) + "/xoversample",
                      Severity::warning);
    EXPECT_EQ(read.platform.attachments.at(0)
                  .instruments.at(0)
                  .focal_planes.at(0)
                  .detector_array.x_oversample,
              2u);
    expect_diagnostic(read, "unknown element <gain> ignored", line_of(text, "<gain>"),
                      std::string(kDetectorPath) + "/gain", Severity::warning);
}

// ---- rolling readout ------------------------------------------------------------------------

TEST(DetectorReader, LineTimeWithoutRollingReadoutAndBadRollingReadout) {
    TempDir dir;
    const std::string body = std::string(kClock) +
                             "\n<xelementcount>2</xelementcount><yelementcount>2</yelementcount>"
                             "<xelementspacing>2</xelementspacing><yelementspacing>2"
                             "</yelementspacing>";
    const std::string ignored_text = with_detector(array(body + "\n<linetime>1e-5</linetime>"));
    const Read ignored = read_text(dir, ignored_text);
    EXPECT_FALSE(ignored.diagnostics.has_errors());
    expect_diagnostic(ignored, "<linetime> ignored: rollingreadout is not \"true\"",
                      line_of(ignored_text, "<linetime>"), std::string(kDetectorPath) + "/linetime",
                      Severity::warning);
    EXPECT_FALSE(plane_of(ignored.platform, 0, 0).detector_array.rolling_line_time_s);
    const Read bad = read_text(dir, with_detector(array(body, " rollingreadout=\"sometimes\"")));
    EXPECT_NE(find(bad.diagnostics, "got \"sometimes\""), nullptr) << dump(bad.diagnostics);
}

// ---- clocks ----------------------------------------------------------------------------------

/// A valid array whose clock is `clock`.
std::string with_clock(const std::string& clock, const std::string& clocktable = "<clocktable/>") {
    return with_detector(array(clock + "\n<xelementcount>2</xelementcount><yelementcount>2"
                                       "</yelementcount><xelementspacing>2</xelementspacing>"
                                       "<yelementspacing>2</yelementspacing>"),
                         clocktable);
}

TEST(DetectorReader, SynchronousClockNeedsAnExistingMaster) {
    TempDir dir;
    const std::string table =
        "<clocktable><clock name=\"Main\" type=\"independent\" temporalunits=\"hertz\">"
        "<rate>50</rate></clock></clocktable>";
    const std::string clock_path = std::string(kDetectorPath) + "/clock";
    const std::string text = with_clock("<clock type=\"synchronous\" master=\"Other\"/>", table);
    const Read read = read_text(dir, text);
    expect_diagnostic(read,
                      "synchronous clock names master \"Other\", which is not in the "
                      "<clocktable> (it has Main)",
                      line_of(text, "<clock type=\"synchronous\""), clock_path);
    EXPECT_EQ(read.diagnostics.error_count(), 1u) << dump(read.diagnostics);
    const Read empty = read_text(dir, with_clock("<clock type=\"synchronous\" master=\"M\"/>"));
    EXPECT_NE(find(empty.diagnostics, "(the clocktable is empty)"), nullptr)
        << dump(empty.diagnostics);
    const Read ok =
        read_text(dir, with_clock("<clock type=\"synchronous\" master=\"Main\"/>", table));
    EXPECT_FALSE(ok.diagnostics.has_errors()) << dump(ok.diagnostics);
}

// ---- one bad array or clock, its diagnostics -------------------------------------------------

/// A platform text and one error it must give, on the line of `anchor` plus `below`.
struct DetectorErrorCase {
    std::string name;
    std::string text;
    std::string message;  ///< part of the error's message
    std::string anchor;   ///< text whose line (line_of) the error is on...
    int below = 0;        ///< ...plus this many lines
    std::string element;
};

class DetectorReaderErrors : public ::testing::TestWithParam<DetectorErrorCase> {};

TEST_P(DetectorReaderErrors, MessageLineAndElement) {
    const DetectorErrorCase& c = GetParam();
    TempDir dir;
    const Read read = read_text(dir, c.text);
    expect_diagnostic(read, c.message, line_of(c.text, c.anchor) + c.below, c.element);
}

std::vector<DetectorErrorCase> detector_errors() {
    const std::string array_path = kDetectorPath;
    const std::string clock_path = array_path + "/clock";
    const std::string bad_counts =
        with_detector(array(std::string(kClock) + "\n<xelementcount>0</xelementcount>\n"
                                                  "<yelementcount>12.5</yelementcount>\n"
                                                  "<xelementspacing>5</xelementspacing>\n"
                                                  "<yelementspacing>5</yelementspacing>"));
    const std::string no_counts = with_detector(array(kClock));
    const std::string rolling_body = std::string(kClock) +
                                     "\n<xelementcount>2</xelementcount><yelementcount>2"
                                     "</yelementcount><xelementspacing>2</xelementspacing>"
                                     "<yelementspacing>2</yelementspacing>";
    const std::string independent = with_clock(
        "<clock type=\"independent\" temporalunits=\"seconds\">\n<rate>-10</rate>\n"
        "<offset>soon</offset>\n</clock>");
    const std::string table =
        "<clocktable><clock name=\"Main\" type=\"independent\" temporalunits=\"hertz\">"
        "<rate>50</rate></clock></clocktable>";
    const std::string synchronous = with_clock(
        "<clock type=\"synchronous\">\n<divider>0</divider>\n<offset>-1</offset>\n</clock>", table);
    return {
        // counts
        {"CountZero", bad_counts,
         "xelementcount 0 is out of range, expected an integer in [1, 1000000]", "<xelementcount>",
         0, array_path + "/xelementcount"},
        {"CountNotAnInteger", bad_counts, "expected an integer, got \"12.5\"", "<yelementcount>", 0,
         array_path + "/yelementcount"},
        {"MissingXCount", no_counts, "missing required element <xelementcount>", "<detectorarray",
         0, array_path},
        {"MissingYCount", no_counts, "missing required element <yelementcount>", "<detectorarray",
         0, array_path},
        {"MissingXSpacing", no_counts, "missing required element <xelementspacing>",
         "<detectorarray", 0, array_path},
        {"MissingYSpacing", no_counts, "missing required element <yelementspacing>",
         "<detectorarray", 0, array_path},
        // rolling readout
        {"RollingReadoutNeedsLineTime",
         with_detector(array(rolling_body, " rollingreadout=\"true\"")),
         "rollingreadout=\"true\" needs <linetime> (seconds between the readout of consecutive "
         "rows)",
         "<detectorarray", 0, array_path + "@rollingreadout"},
        {"RollingReadoutZeroLineTime",
         with_detector(array(rolling_body + "\n<linetime>0</linetime>", " rollingreadout=\"yes\"")),
         "expected a number > 0, got \"0\"", "<linetime>", 0, array_path + "/linetime"},
        // clock types
        {"UnknownClockType", with_clock("<clock type=\"quartz\"/>"),
         "unknown clock type \"quartz\", expected independent, synchronous or external (also "
         "externaltrigger, trigger, irregular)",
         "<detectorarray", 1, clock_path + "@type"},
        {"UntypedClock", with_clock("<clock><rate>1</rate></clock>"),
         "missing required attribute type", "<detectorarray", 1, clock_path},
        {"NoClock",
         with_detector(array("<xelementcount>2</xelementcount><yelementcount>2</yelementcount>"
                             "<xelementspacing>2</xelementspacing><yelementspacing>2"
                             "</yelementspacing>")),
         "missing required element <clock>", "<detectorarray", 0, array_path},
        // independent clocks
        {"IndependentClockUnits", independent, "unknown temporalunits \"seconds\", expected hertz",
         "<detectorarray", 1, clock_path + "@temporalunits"},
        {"IndependentClockNegativeRate", independent, "expected a number > 0, got \"-10\"",
         "<rate>", 0, clock_path + "/rate"},
        {"IndependentClockBadOffset", independent, "expected a number, got \"soon\"", "<offset>", 0,
         clock_path + "/offset"},
        {"IndependentClockWithoutRate", with_clock("<clock type=\"independent\"/>"),
         "missing required element <rate>", "<detectorarray", 1, clock_path},
        // synchronous clocks
        {"SynchronousClockWithoutMaster", synchronous,
         "synchronous clock has no master, expected @master or <master>",
         "<clock type=\"synchronous\"", 0, clock_path},
        {"SynchronousClockZeroDivider", synchronous,
         "expected an integer in [1, 1000000000], got \"0\"", "<divider>", 0,
         clock_path + "/divider"},
        {"SynchronousClockNegativeOffset", synchronous,
         "expected an integer in [0, 1000000000], got \"-1\"", "<offset>", 0,
         clock_path + "/offset"},
        {"SynchronousClockMasterTwice",
         with_clock("<clock type=\"synchronous\" master=\"Main\">\n<master>Main</master>\n</clock>",
                    table),
         "both @master and <master> given", "<master>", 0, clock_path + "/master"},
    };
}

INSTANTIATE_TEST_SUITE_P(DetectorReader, DetectorReaderErrors,
                         ::testing::ValuesIn(detector_errors()),
                         [](const ::testing::TestParamInfo<DetectorErrorCase>& test_case) {
                             return test_case.param.name;
                         });

TEST(DetectorReader, ClockTableErrors) {
    TempDir dir;
    const std::string table =
        "<clocktable>\n<clock name=\"A\" type=\"independent\"><rate>1</rate></clock>\n"
        "<clock name=\"A\" type=\"independent\"><rate>2</rate></clock>\n"
        "<clock type=\"independent\"><rate>2</rate></clock>\n"
        "<clock name=\"S\" type=\"synchronous\"><rate>0</rate></clock>\n</clocktable>";
    const std::string text = "<platform>\n" + table + "\n</platform>\n";
    const Read read = read_text(dir, text);
    expect_diagnostic(read,
                      "clock \"A\" is defined twice in the clocktable (first at line 3), expected "
                      "unique names",
                      4, "platform/clocktable/clock[A]");
    expect_diagnostic(read, "clocktable clock has no name, expected @name", 5,
                      "platform/clocktable/clock");
    expect_diagnostic(read,
                      "clocktable clock type \"synchronous\" is not supported, expected "
                      "independent",
                      6, "platform/clocktable/clock[S]@type");
    expect_diagnostic(read, "expected a number > 0, got \"0\"", 6,
                      "platform/clocktable/clock[S]/rate");
    EXPECT_EQ(read.platform.clock_table.size(), 3u);
}

TEST(DetectorReader, ExternalClockFiles) {
    TempDir dir;
    const std::string clock_path = std::string(kDetectorPath) + "/clock";
    const Read trigger =
        read_text(dir, with_clock("<clock type=\"ExternalTrigger\"><triggerfile>t/times.txt"
                                  "</triggerfile></clock>"));
    ASSERT_FALSE(trigger.diagnostics.has_errors()) << dump(trigger.diagnostics);
    EXPECT_EQ(plane_of(trigger.platform, 0, 0).detector_array.clock.trigger_file.resolved,
              dir.path() / "t" / "times.txt");
    const Read windows = read_text(
        dir,
        with_clock("<clock type=\"trigger\"><filename>C:\\runs\\times.txt</filename></clock>"));
    ASSERT_FALSE(windows.diagnostics.has_errors()) << dump(windows.diagnostics);
    EXPECT_EQ(plane_of(windows.platform, 0, 0).detector_array.clock.trigger_file.resolved,
              std::filesystem::path("C:/runs/times.txt"));
    const std::string none_text = with_clock("<clock type=\"external\"/>");
    const Read none = read_text(dir, none_text);
    expect_diagnostic(none, "external clock has no trigger file, expected <filename>",
                      line_of(none_text, "<detectorarray") + 1, clock_path);
    const std::string twice_text = with_clock(
        "<clock type=\"external\" filename=\"a.txt\"><filename>b.txt</filename></clock>");
    const Read twice = read_text(dir, twice_text);
    expect_diagnostic(twice, "trigger file given more than once",
                      line_of(twice_text, "<detectorarray") + 1, clock_path);
}

}  // namespace array_clock_reader_test
}  // namespace glint::test::plat
