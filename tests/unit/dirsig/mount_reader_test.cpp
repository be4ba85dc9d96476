// SPDX-License-Identifier: Apache-2.0
// Tests of the mount part of the `.platform` reader: the mounts.platform fixture (commanded,
// tabulated, whisk and tracking mounts, normal and PSD jitter) field by field, and every bad
// mount input with its message, line and element path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "glint/test/angles.h"
#include "platform_test_util.h"

namespace glint::test::plat {
namespace mount_reader_test {

using ::testing::HasSubstr;
using Severity = Diagnostic::Severity;

using glint::test::kDeg;
constexpr const char* kMountPath = "platform/attachment/mount[M]";

TEST(MountReader, MountsFixtureFieldByField) {
    const Read read = read_fixture("mounts.platform");
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    // The only warnings: the two data recorders have no clock, so they record nothing.
    ASSERT_EQ(read.diagnostics.warning_count(), 2u) << dump(read.diagnostics);
    for (const Diagnostic& item : read.diagnostics.items()) {
        EXPECT_THAT(item.message, HasSubstr("has no <clock> (nor an enabled focal plane's): it "
                                            "records nothing"));
    }
    const model::Platform& p = read.platform;
    ASSERT_EQ(p.attachments.size(), 3u);

    // Commanded, degrees, three entries with times, rotations and translations.
    const model::Mount& pointer = p.attachments[0].mounts.at(0);
    EXPECT_EQ(pointer.name, "Pointer");
    EXPECT_EQ(pointer.type, model::MountType::commanded);
    EXPECT_EQ(pointer.type_text, "commanded");
    ASSERT_EQ(pointer.entries.size(), 3u);
    EXPECT_EQ(pointer.entries[0].time_s, 0.0);
    EXPECT_DOUBLE_EQ(pointer.entries[0].rotation_rad[1], -10 * kDeg);
    EXPECT_EQ(pointer.entries[1].time_s, 1.5);
    EXPECT_DOUBLE_EQ(pointer.entries[1].rotation_rad[0], 5 * kDeg);
    EXPECT_EQ(pointer.entries[1].translation_m, (std::array<double, 3>{0.5, 0, -0.2}));
    EXPECT_EQ(pointer.entries[2].time_s, 3.0);
    EXPECT_EQ(pointer.entries[2].translation_m, (std::array<double, 3>{0, 0, 0}));
    EXPECT_EQ(pointer.entries[2].where.element, "platform/attachment/mount[Pointer]/data/entry");
    EXPECT_FALSE(pointer.period_s);
    // Jitter: along-track = x (normal), across-track = y (psd), z none.
    ASSERT_TRUE(pointer.deviates.any());
    const auto& x = pointer.deviates.axes[0];
    EXPECT_EQ(x.kind, model::JitterSpec::Kind::normal);
    EXPECT_EQ(x.mean, 0.0);
    EXPECT_DOUBLE_EQ(x.stddev, 0.01 * kDeg);
    const auto& y = pointer.deviates.axes[1];
    EXPECT_EQ(y.kind, model::JitterSpec::Kind::psd);
    EXPECT_EQ(y.psd_file.text, "jitter_psd.txt");
    EXPECT_EQ(y.psd_file.resolved, fixture_dir() / "jitter_psd.txt");
    EXPECT_TRUE(std::filesystem::exists(y.psd_file.resolved));
    EXPECT_EQ(pointer.deviates.axes[2].kind, model::JitterSpec::Kind::none);

    // Tabulated in radians with @period.
    const model::Mount& table = pointer.attachments.at(0).mounts.at(0);
    EXPECT_EQ(table.type, model::MountType::tabulated);
    EXPECT_EQ(table.rotation_order, "zyx");
    ASSERT_EQ(table.entries.size(), 2u);
    EXPECT_DOUBLE_EQ(table.entries[1].rotation_rad[2], 0.5);
    ASSERT_TRUE(table.period_s);
    EXPECT_EQ(*table.period_s, 2.0);
    EXPECT_FALSE(table.deviates.any());
    const model::Instrument& recorder = table.attachments.at(0).instruments.at(0);
    EXPECT_EQ(recorder.type, model::InstrumentType::data_recorder);
    EXPECT_EQ(recorder.type_text, "data_recorder");

    // Tabulated with <period>; whisk across track; whisk along track from <alongtrack>.
    const model::Attachment& second = p.attachments[1];
    ASSERT_EQ(second.mounts.size(), 3u);
    const model::Mount& tab2 = second.mounts[0];
    EXPECT_EQ(*tab2.period_s, 4.0);
    EXPECT_DOUBLE_EQ(tab2.entries[1].rotation_rad[1], 20 * kDeg);
    const model::Mount& scanner = second.mounts[1];
    EXPECT_EQ(scanner.type, model::MountType::whisk);
    ASSERT_TRUE(scanner.whisk);
    EXPECT_EQ(scanner.whisk->axis, model::WhiskScan::Axis::across_track);
    EXPECT_DOUBLE_EQ(scanner.whisk->min_angle_rad, -15 * kDeg);
    EXPECT_DOUBLE_EQ(scanner.whisk->max_angle_rad, 15 * kDeg);
    EXPECT_EQ(scanner.whisk->rate_hz, 10.0);
    EXPECT_DOUBLE_EQ(scanner.whisk->phase_rad, std::numbers::pi / 2);
    EXPECT_FALSE(scanner.whisk->sinusoidal);
    EXPECT_EQ(scanner.deviates.axes[0].kind, model::JitterSpec::Kind::normal);
    EXPECT_DOUBLE_EQ(scanner.deviates.axes[0].mean, 0.001);
    EXPECT_DOUBLE_EQ(scanner.deviates.axes[0].stddev, 0.0002);  // <sigma>
    EXPECT_EQ(scanner.deviates.axes[1].kind, model::JitterSpec::Kind::none);
    EXPECT_EQ(scanner.deviates.axes[2].kind, model::JitterSpec::Kind::none);
    const model::Mount& nodder = second.mounts[2];
    ASSERT_TRUE(nodder.whisk);
    EXPECT_EQ(nodder.whisk->axis, model::WhiskScan::Axis::along_track);
    EXPECT_DOUBLE_EQ(nodder.whisk->min_angle_rad, -0.1);
    EXPECT_DOUBLE_EQ(nodder.whisk->max_angle_rad, 0.2);
    EXPECT_EQ(nodder.whisk->rate_hz, 0.5);
    EXPECT_EQ(nodder.whisk->phase_rad, 0.0);
    EXPECT_TRUE(nodder.whisk->sinusoidal);

    // Tracking: a named target with an offset (in <data>), and a fixed point (on the mount).
    const model::Attachment& third = p.attachments[2];
    EXPECT_EQ(third.transform.translation_m, (std::array<double, 3>{0, 0, -0.5}));
    const model::Mount& tracker = third.mounts.at(0);
    EXPECT_EQ(tracker.type, model::MountType::tracking);
    ASSERT_TRUE(tracker.tracking);
    EXPECT_EQ(tracker.tracking->name, "truck_01");
    EXPECT_EQ(tracker.tracking->offset_m, (std::array<double, 3>{0, 1.5, 2}));
    EXPECT_FALSE(tracker.tracking->point_m);
    const model::Mount& stare = third.mounts.at(1);
    ASSERT_TRUE(stare.tracking);
    EXPECT_EQ(stare.tracking->name, "");
    ASSERT_TRUE(stare.tracking->point_m);
    EXPECT_EQ(*stare.tracking->point_m, (std::array<double, 3>{100, -50.5, 2}));

    // Instruments in document order, with their mount chains.
    const auto list = model::list_instruments(p);
    ASSERT_EQ(list.size(), 3u);
    EXPECT_EQ(list[0].instrument->name, "Recorder");
    ASSERT_EQ(list[0].mounts.size(), 2u);
    EXPECT_EQ(list[0].mounts[0]->name, "Pointer");
    EXPECT_EQ(list[0].mounts[1]->name, "Table");
    EXPECT_EQ(list[0].attachments.size(), 3u);
    EXPECT_EQ(list[1].instrument->name, "ScanRecorder");
    EXPECT_EQ(list[1].mounts.at(0)->name, "Scanner");
    EXPECT_EQ(list[2].instrument->name, "TrackCam");
    EXPECT_EQ(list[2].mounts.at(0)->name, "Tracker");
}

// ---- types ----------------------------------------------------------------------------------

TEST(MountReader, UnsupportedTypesWarnAndHoldStatic) {
    TempDir dir;
    const Read read = read_text(
        dir, with_mount("<mount name=\"M\" type=\"Lemniscate\">\n<data><xrotation>3</xrotation>"
                        "<scanrange/></data>\n<alongtrack/>\n</mount>"));
    EXPECT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    expect_diagnostic(read, "mount type \"Lemniscate\" is not supported yet; treated as static", 5,
                      std::string(kMountPath) + "@type", Severity::warning);
    EXPECT_EQ(read.diagnostics.warning_count(), 1u) << dump(read.diagnostics);
    const model::Mount& m = read.platform.attachments.at(0).mounts.at(0);
    EXPECT_EQ(m.type, model::MountType::other);
    EXPECT_DOUBLE_EQ(m.rotation_rad[0], 3 * kDeg);
}

TEST(MountReader, StaticMountDefaultsAndErrors) {
    TempDir dir;
    const Read plain = read_text(dir, with_mount("<mount name=\"M\"/>"));
    EXPECT_FALSE(plain.diagnostics.has_errors());
    EXPECT_EQ(plain.platform.attachments.at(0).mounts.at(0).type, model::MountType::static_mount);
    const std::string text = with_mount(
        "<mount name=\"M\" type=\"static\">\n"
        "<data angularunits=\"gradians\" rotationorder=\"xyzz\">\n"
        "<xrotation>north</xrotation>\n<wobble/>\n</data>\n</mount>");
    const Read read = read_text(dir, text);
    const std::string data = std::string(kMountPath) + "/data";
    expect_diagnostic(read, "unknown angularunits \"gradians\", expected degrees or radians", 6,
                      data + "@angularunits");
    expect_diagnostic(read, "rotationorder \"xyzz\" is not a permutation of xyz", 6,
                      data + "@rotationorder");
    expect_diagnostic(read, "expected a number, got \"north\"", 7, data + "/xrotation");
    expect_diagnostic(read, "unknown element <wobble> ignored", 8, data + "/wobble",
                      Severity::warning);
}

TEST(MountReader, EveryRotationOrderPermutationIsAccepted) {
    TempDir dir;
    for (const char* order : {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "YZX"}) {
        const Read read = read_text(dir, with_mount("<mount name=\"M\"><data rotationorder=\"" +
                                                    std::string(order) + "\"/></mount>"));
        EXPECT_FALSE(read.diagnostics.has_errors()) << order << "\n" << dump(read.diagnostics);
    }
}

// ---- commanded / tabulated -------------------------------------------------------------------

TEST(MountReader, CommandedEntryErrors) {
    TempDir dir;
    const std::string text = with_mount(
        "<mount name=\"M\" type=\"commanded\">\n<data>\n"
        "<entry><datetime type=\"relative\">2</datetime></entry>\n"
        "<entry><datetime type=\"relative\">2</datetime></entry>\n"
        "<entry><datetime type=\"absolute\">2020-01-01T00:00:00</datetime></entry>\n"
        "<entry><xrotation>1</xrotation></entry>\n"
        "<entry><datetime>soon</datetime></entry>\n"
        "<entry><datetime type=\"julian\">1</datetime></entry>\n"
        "<entry><datetime type=\"relative\">1</datetime><yrotation>-</yrotation></entry>\n"
        "</data>\n</mount>");
    const Read read = read_text(dir, text);
    const std::string entry = std::string(kMountPath) + "/data/entry";
    expect_diagnostic(read,
                      "entry time 2 s is not after the previous entry's 2 s, expected strictly "
                      "increasing times",
                      8, entry);
    expect_diagnostic(read, "absolute mount times need the tasks file's reference date", 9,
                      entry + "/datetime");
    expect_diagnostic(read, "missing required element <datetime>", 10, entry);
    expect_diagnostic(read, "expected a number, got \"soon\"", 11, entry + "/datetime");
    expect_diagnostic(read, "unknown datetime type \"julian\", expected relative or absolute", 12,
                      entry + "/datetime@type");
    expect_diagnostic(read, "entry time 1 s is not after the previous entry's 2 s", 13, entry);
    expect_diagnostic(read, "expected a number, got \"-\"", 13, entry + "/yrotation");
    EXPECT_EQ(read.diagnostics.error_count(), 7u) << dump(read.diagnostics);
}

TEST(MountReader, TabulatedPeriod) {
    TempDir dir;
    const std::string entries =
        "<entry><datetime>0</datetime></entry><entry><datetime>3</datetime></entry>";
    const Read fallback = read_text(dir, with_mount("<mount name=\"M\" type=\"tabulated\"><data>" +
                                                    entries + "</data></mount>"));
    ASSERT_FALSE(fallback.diagnostics.has_errors()) << dump(fallback.diagnostics);
    EXPECT_EQ(*fallback.platform.attachments.at(0).mounts.at(0).period_s, 3.0);  // last time

    const Read constant =
        read_text(dir, with_mount("<mount name=\"M\" type=\"tabulated\"><data><entry><datetime>0"
                                  "</datetime></entry></data></mount>"));
    ASSERT_FALSE(constant.diagnostics.has_errors());
    EXPECT_FALSE(constant.platform.attachments.at(0).mounts.at(0).period_s);
}

// ---- tracking --------------------------------------------------------------------------------

TEST(MountReader, TrackingOffsetWithoutPointElement) {
    TempDir dir;
    const Read read = read_text(
        dir, with_mount("<mount name=\"M\" type=\"tracking\"><data><targetname>t</targetname>"
                        "<targetoffset><x>1</x><z>-1</z></targetoffset></data></mount>"));
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    EXPECT_EQ(read.platform.attachments.at(0).mounts.at(0).tracking->offset_m,
              (std::array<double, 3>{1, 0, -1}));
}

// ---- rotation deviates -----------------------------------------------------------------------

TEST(MountReader, RotationDeviatesErrors) {
    TempDir dir;
    const std::string text = with_mount(
        "<mount name=\"M\">\n<rotationdeviates angularunits=\"arcsec\">\n"
        "<xrotation type=\"uniform\"/>\n"
        "<yrotation type=\"normal\"><mean>0</mean></yrotation>\n"
        "<acrosstrack type=\"normal\"><stddev>1</stddev></acrosstrack>\n"
        "<zrotation type=\"psd\"/>\n"
        "</rotationdeviates>\n</mount>");
    const Read read = read_text(dir, text);
    const std::string rd = std::string(kMountPath) + "/rotationdeviates";
    expect_diagnostic(read, "unknown angularunits \"arcsec\"", 6, rd + "@angularunits");
    expect_diagnostic(
        read,
        "unknown jitter type \"uniform\", expected correlated (psd), uncorrelated (normal) or none",
        7, rd + "/xrotation@type");
    expect_diagnostic(read, "missing required element <stddev>", 8, rd + "/yrotation");
    expect_diagnostic(read, "<yrotation> and <acrosstrack> both give the jitter about y", 9,
                      rd + "/acrosstrack");
    expect_diagnostic(
        read,
        "missing required element <psd> (a correlated jitter needs a <psd> table or a <psdfile>)",
        10, rd + "/zrotation");
}

// A mount axis is read by the same reader as a motion file's jitter axis: an inline <psd>
// table, and the axis' own angularunits over the element's.
TEST(MountReader, RotationDeviatesTakeTheMotionJitterVocabulary) {
    TempDir dir;
    const Read read = read_text(
        dir, with_mount("<mount name=\"M\"><rotationdeviates angularunits=\"radians\">\n"
                        "<xrotation type=\"correlated\" angularunits=\"degrees\">\n"
                        "<psd magnitudeunits=\"degrees\"><entry><frequency>0</frequency>"
                        "<magnitude>2</magnitude></entry><entry><frequency>5</frequency>"
                        "<magnitude>1</magnitude></entry></psd></xrotation>\n"
                        "<yrotation type=\"uncorrelated\"><stddev>0.5</stddev></yrotation>\n"
                        "</rotationdeviates></mount>"));
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    const auto& d = read.platform.attachments.at(0).mounts.at(0).deviates;
    EXPECT_EQ(d.axes[0].kind, model::JitterSpec::Kind::psd);
    ASSERT_TRUE(d.axes[0].psd);
    EXPECT_EQ(d.axes[0].psd->frequency_hz, (std::vector<double>{0.0, 5.0}));
    // 2 deg²/Hz and 1 deg²/Hz in rad²/Hz.
    EXPECT_DOUBLE_EQ(d.axes[0].psd->psd[0], 2.0 * kDeg * kDeg);
    EXPECT_DOUBLE_EQ(d.axes[0].psd->psd[1], 1.0 * kDeg * kDeg);
    EXPECT_EQ(d.axes[0].where.element, std::string(kMountPath) + "/rotationdeviates/xrotation");
    EXPECT_EQ(d.axes[1].kind, model::JitterSpec::Kind::normal);
    EXPECT_EQ(d.axes[1].stddev, 0.5) << "the element's radians";
}

TEST(MountReader, RotationDeviatesInferredKindsAndVariables) {
    TempDir dir;
    const Read read = read_text(
        dir, with_mount("<mount name=\"M\"><rotationdeviates angularunits=\"radians\">"
                        "<xrotation><stddev>0.5</stddev></xrotation>"
                        "<yrotation><filename>$GLINT_TEST_VAR/psd.txt</filename></yrotation>"
                        "<zrotation/></rotationdeviates></mount>"));
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    const auto& d = read.platform.attachments.at(0).mounts.at(0).deviates;
    EXPECT_EQ(d.axes[0].kind, model::JitterSpec::Kind::normal);
    EXPECT_EQ(d.axes[0].stddev, 0.5);
    EXPECT_EQ(d.axes[1].kind, model::JitterSpec::Kind::psd);
    EXPECT_EQ(d.axes[1].psd_file.resolved, std::filesystem::path("/opt/glint-test/psd.txt"));
    EXPECT_EQ(d.axes[2].kind, model::JitterSpec::Kind::none);
    EXPECT_EQ(d.where.element, std::string(kMountPath) + "/rotationdeviates");

    const Read undefined = read_text(
        dir, with_mount("<mount name=\"M\">\n<rotationdeviates><xrotation type=\"psd\">\n"
                        "<psdfile>$NOPE_NOT_SET/psd.txt</psdfile></xrotation></rotationdeviates>"
                        "</mount>"));
    expect_diagnostic(undefined, "undefined variable $NOPE_NOT_SET", 7,
                      std::string(kMountPath) + "/rotationdeviates/xrotation/psdfile");
}

// ---- one bad mount, one diagnostic ------------------------------------------------------------

/// A mount (wrapped by with_mount: its opening tag on line 5) and the error it must give.
struct MountErrorCase {
    std::string name;
    std::string mount;
    std::string message;  ///< part of the error's message
    int line;
    std::string element;  ///< element path after kMountPath
};

class MountReaderErrors : public ::testing::TestWithParam<MountErrorCase> {};

TEST_P(MountReaderErrors, MessageLineAndElement) {
    const MountErrorCase& c = GetParam();
    TempDir dir;
    const Read read = read_text(dir, with_mount(c.mount));
    expect_diagnostic(read, c.message, c.line, std::string(kMountPath) + c.element);
}

constexpr const char* kBadWhisk =
    "<mount name=\"M\" type=\"whisk\">\n<data>\n<axis>diagonal</axis>\n"
    "<minimumangle>10</minimumangle>\n<maximumangle>-10</maximumangle>\n<rate>0</rate>\n"
    "<profile>square</profile>\n</data>\n</mount>";
constexpr const char* kWhiskWithoutAngles =
    "<mount name=\"M\" type=\"whisk\">\n<data><rate>1</rate></data></mount>";
constexpr const char* kTrackingBadPoints =
    "<mount name=\"M\" type=\"tracking\">\n<data>\n<point>1, 2</point>\n"
    "<targetoffset><point>a b c</point></targetoffset>\n</data>\n</mount>";

std::vector<MountErrorCase> mount_errors() {
    const std::string entries =  // tabulated entries at 0 and 3 s
        "<entry><datetime>0</datetime></entry><entry><datetime>3</datetime></entry>";
    return {
        {"UnknownMountType", "<mount name=\"M\" type=\"gyro\"/>",
         "unknown mount type \"gyro\", expected static, commanded, tabulated, whisk, tracking, "
         "lemniscate, line or scripted",
         5, "@type"},
        // commanded / tabulated
        {"CommandedNeedsData", "<mount name=\"M\" type=\"commanded\"/>",
         "missing required element <data> (a commanded mount needs a table", 5, ""},
        {"CommandedNeedsEntries", "<mount name=\"M\" type=\"commanded\">\n<data/>\n</mount>",
         "commanded mount has no <entry>, expected at least one", 6, "/data"},
        {"TabulatedPeriodShorterThanTheLastEntry",
         "<mount name=\"M\" type=\"tabulated\">\n<data period=\"2\">" + entries + "</data></mount>",
         "period 2 s is shorter than the last entry time 3 s, expected a period >= the last time",
         6, "/data@period"},
        {"TabulatedNegativePeriod",
         "<mount name=\"M\" type=\"tabulated\">\n<data>\n<period>-1</period>" + entries +
             "</data></mount>",
         "expected a number > 0, got \"-1\"", 7, "/data/period"},
        {"TabulatedPeriodTwice",
         "<mount name=\"M\" type=\"tabulated\">\n<data period=\"5\">\n<period>5</period>" +
             entries + "</data></mount>",
         "both @period and <period> given", 7, "/data/period"},
        // whisk
        {"WhiskNeedsData", "<mount name=\"M\" type=\"whisk\"/>",
         "missing required element <data> (a whisk mount needs its scan)", 5, ""},
        {"WhiskUnknownAxis", kBadWhisk, "expected one of acrosstrack, alongtrack, got \"diagonal\"",
         7, "/data/axis"},
        {"WhiskMaximumBelowMinimum", kBadWhisk,
         "maximumangle -10 is less than minimumangle 10, expected minimumangle <= maximumangle", 9,
         "/data/maximumangle"},
        {"WhiskZeroRate", kBadWhisk, "expected a number > 0, got \"0\"", 10, "/data/rate"},
        {"WhiskUnknownProfile", kBadWhisk, "expected one of sinusoidal, linear, got \"square\"", 11,
         "/data/profile"},
        {"WhiskNeedsMinimumAngle", kWhiskWithoutAngles, "missing required element <minimumangle>",
         6, "/data"},
        {"WhiskNeedsMaximumAngle", kWhiskWithoutAngles, "missing required element <maximumangle>",
         6, "/data"},
        {"WhiskBothAxisElements",
         "<mount name=\"M\" type=\"whisk\">\n<data><rate>1</rate>\n"
         "<alongtrack><minimumangle>0</minimumangle><maximumangle>1</maximumangle>"
         "</alongtrack>\n<acrosstrack/>\n</data></mount>",
         "both <alongtrack> and <acrosstrack> given, expected one scan axis", 8,
         "/data/acrosstrack"},
        {"WhiskAxisElementContradictsAxis",
         "<mount name=\"M\" type=\"whisk\">\n<data><rate>1</rate>"
         "<axis>acrosstrack</axis>\n<alongtrack><minimumangle>0</minimumangle>"
         "<maximumangle>1</maximumangle></alongtrack>\n</data></mount>",
         "<alongtrack> contradicts <axis>acrosstrack</axis>", 7, "/data/alongtrack"},
        // tracking
        {"TrackingNeedsATarget", "<mount name=\"M\" type=\"tracking\">\n<data/>\n</mount>",
         "tracking mount has no target, expected <targetname> or <point>", 6, "/data"},
        {"TrackingTwoTargets",
         "<mount name=\"M\" type=\"tracking\">\n<targetname>car</targetname>\n"
         "<point>1 2 3</point>\n</mount>",
         "both <targetname> and <point> given, expected one target", 7, "/point"},
        {"TrackingBadPoint", kTrackingBadPoints, "\"1, 2\" is not a point, expected x y z", 7,
         "/data/point"},
        {"TrackingBadOffsetPoint", kTrackingBadPoints, "\"a b c\" is not a point", 8,
         "/data/targetoffset/point"},
        // rotation deviates
        {"NegativeRotationDeviate",
         "<mount name=\"M\">\n<rotationdeviates>\n<xrotation><stddev>-1</stddev>"
         "</xrotation>\n</rotationdeviates>\n</mount>",
         "expected a number >= 0, got \"-1\"", 7, "/rotationdeviates/xrotation/stddev"},
    };
}

INSTANTIATE_TEST_SUITE_P(MountReader, MountReaderErrors, ::testing::ValuesIn(mount_errors()),
                         [](const ::testing::TestParamInfo<MountErrorCase>& test_case) {
                             return test_case.param.name;
                         });

TEST(MountReader, NestedMountsRecurse) {
    TempDir dir;
    std::string mount = "<instrument name=\"R\" type=\"datarecorder\"/>";
    for (int i = 3; i >= 1; --i) {
        mount = "<mount name=\"N" + std::to_string(i) + "\"><attachment>" + mount +
                "</attachment></mount>";
    }
    const Read read = read_text(dir, with_mount(mount));
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    const auto list = model::list_instruments(read.platform);
    ASSERT_EQ(list.size(), 1u);
    ASSERT_EQ(list[0].mounts.size(), 3u);
    EXPECT_EQ(list[0].mounts[2]->name, "N3");
    EXPECT_EQ(list[0].attachments.size(), 4u);
    EXPECT_EQ(list[0].instrument->where.element,
              "platform/attachment/mount[N1]/attachment/mount[N2]/attachment/mount[N3]/"
              "attachment/instrument[R]");
}

}  // namespace mount_reader_test
}  // namespace glint::test::plat
