// SPDX-License-Identifier: Apache-2.0
// Tests of the motion readers: the GenericMotion `.ppd` and FlexMotion `.motion` fixtures of
// tests/data/motion field by field (every engine, every jitter form, units), the inline
// FlexMotion reader, and every bad input with its message, line and element path
// (non-monotonic and duplicate times, bad delimiter, non-numeric CDATA fields at their own
// line, unknown engine types, missing elements, unsupported attributes).
#include "glint/dirsig/motion_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <string_view>

#include "glint/test/angles.h"
#include "glint/test/temp_dir.h"

namespace glint::dirsig {
namespace motion_reader_test {

using glint::test::TempDir;
using ::testing::HasSubstr;
using Severity = Diagnostic::Severity;

using glint::test::kDeg;
constexpr double kFoot = 0.3048;

const std::filesystem::path kData = std::filesystem::path(GLINT_TEST_DATA_DIR) / "motion";

struct Read {
    std::string file;
    model::PlatformMotion motion;
    Diagnostics diagnostics;
};

std::string dump(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics.items()) {
        out += (d.severity == Severity::error ? "error: " : "warning: ") + d.text() + "\n";
    }
    return out;
}

Read read_fixture(const std::string& name) {
    Read read;
    read.file = (kData / name).string();
    read.motion = read_motion(read.file, ReadOptions{}, read.diagnostics);
    return read;
}

Read read_text(const TempDir& dir, const std::string& text, const std::string& name) {
    Read read;
    read.file = (dir / name).string();
    std::ofstream(read.file, std::ios::binary) << text;
    read.motion = read_motion(read.file, ReadOptions{}, read.diagnostics);
    return read;
}

/// 1-based line of the first occurrence of `needle` in `text` (0 when absent).
int line_of(std::string_view text, std::string_view needle) {
    const std::size_t pos = text.find(needle);
    if (pos == std::string_view::npos) return 0;
    return 1 +
           static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

const Diagnostic* find(const Diagnostics& diagnostics, std::string_view part,
                       Severity severity = Severity::error) {
    for (const Diagnostic& d : diagnostics.items()) {
        if (d.severity == severity && d.message.find(part) != std::string::npos) return &d;
    }
    return nullptr;
}

/// Asserts a diagnostic containing `part` at `line` with element path `element`.
void expect_diagnostic(const Read& read, std::string_view part, int line, std::string_view element,
                       Severity severity = Severity::error) {
    const Diagnostic* d = find(read.diagnostics, part, severity);
    ASSERT_NE(d, nullptr) << "no diagnostic containing \"" << part << "\" in:\n"
                          << dump(read.diagnostics);
    EXPECT_EQ(d->where.file, read.file);
    EXPECT_EQ(d->where.line, line) << d->text();
    EXPECT_EQ(d->where.element, element) << d->text();
}

// ---- GenericMotion --------------------------------------------------------------------------

TEST(MotionReader, HoverPpdIsTheFormatNotesExample) {
    const Read read = read_fixture("hover.ppd");
    EXPECT_TRUE(read.diagnostics.items().empty()) << dump(read.diagnostics);
    EXPECT_EQ(read.motion.file, read.file);
    ASSERT_TRUE(read.motion.generic);
    EXPECT_FALSE(read.motion.flexible);
    const model::GenericMotion& g = *read.motion.generic;
    EXPECT_EQ(g.rotation_frame, model::RotationFrame::scene_enu);
    EXPECT_EQ(g.rotation_order, "xyz");
    EXPECT_FALSE(g.jitter.any());
    ASSERT_EQ(g.entries.size(), 1u);
    EXPECT_EQ(g.entries[0].time_s, 0.0);
    EXPECT_EQ(g.entries[0].location.frame, model::LocationFrame::scene);
    EXPECT_EQ(g.entries[0].location.xyz_m, (std::array<double, 3>{0, 0, 1000}));
    EXPECT_EQ(g.entries[0].euler_rad[0], 0.0);
    EXPECT_DOUBLE_EQ(g.entries[0].euler_rad[2], 90 * kDeg);
    EXPECT_EQ(g.entries[0].where.line, 5);
    EXPECT_EQ(g.entries[0].where.element, "platformmotion/data/entry");
}

TEST(MotionReader, GuiPpdWithEmptyJitterAndRadians) {
    const Read read = read_fixture("gui.ppd");
    EXPECT_TRUE(read.diagnostics.items().empty()) << dump(read.diagnostics);
    ASSERT_TRUE(read.motion.generic);
    const model::GenericMotion& g = *read.motion.generic;
    EXPECT_FALSE(g.jitter.any());
    ASSERT_EQ(g.entries.size(), 2u);
    EXPECT_EQ(g.entries[1].time_s, 10.0);
    EXPECT_EQ(g.entries[1].location.xyz_m, (std::array<double, 3>{600, 400, 5200}));
    EXPECT_DOUBLE_EQ(g.entries[1].euler_rad[2], std::numbers::pi / 2);
    EXPECT_EQ(g.entries[1].where.line, 27);
}

TEST(MotionReader, GeographicPpdInFeetWithEcefRotationFrame) {
    const Read read = read_fixture("geographic.ppd");
    EXPECT_TRUE(read.diagnostics.items().empty()) << dump(read.diagnostics);
    ASSERT_TRUE(read.motion.generic);
    const model::GenericMotion& g = *read.motion.generic;
    EXPECT_EQ(g.rotation_frame, model::RotationFrame::ecef);
    EXPECT_EQ(g.rotation_order, "zyx");
    ASSERT_EQ(g.entries.size(), 2u);
    EXPECT_EQ(g.entries[0].time_s, -5.0);
    const model::Location& a = g.entries[0].location;
    EXPECT_EQ(a.frame, model::LocationFrame::geodetic);
    EXPECT_EQ(a.latitude_deg, 43.01);  // degrees are never scaled
    EXPECT_EQ(a.longitude_deg, -78.02);
    EXPECT_DOUBLE_EQ(a.altitude_m, 10000 * kFoot);
    EXPECT_DOUBLE_EQ(g.entries[0].euler_rad[1], 20 * kDeg);
    const model::Location& b = g.entries[1].location;
    EXPECT_EQ(b.frame, model::LocationFrame::ecef);
    EXPECT_DOUBLE_EQ(b.xyz_m[1], -14000000 * kFoot);
    EXPECT_EQ(b.where.element, "platformmotion/data/entry/position/location");
}

// ---- FlexMotion -------------------------------------------------------------------------------

TEST(MotionReader, WaypointsRowsKeepTheirFileLines) {
    const Read read = read_fixture("waypoints.motion");
    EXPECT_TRUE(read.diagnostics.items().empty()) << dump(read.diagnostics);
    ASSERT_TRUE(read.motion.flexible);
    EXPECT_FALSE(read.motion.generic);
    const model::LocationEngine& loc = read.motion.flexible->location;
    EXPECT_EQ(loc.type, model::LocationEngineType::waypoints);
    EXPECT_EQ(loc.waypoint_frame, model::LocationFrame::scene);
    ASSERT_EQ(loc.waypoints.size(), 3u);
    EXPECT_EQ(loc.waypoints[0].time_s, 0.0);
    EXPECT_EQ(loc.waypoints[0].values, (std::array<double, 4>{-500, 0, 2000, 0}));
    EXPECT_EQ(loc.waypoints[0].line, 4);
    EXPECT_EQ(loc.waypoints[1].line, 5);
    EXPECT_EQ(loc.waypoints[2].time_s, 20.0);
    EXPECT_EQ(loc.waypoints[2].values, (std::array<double, 4>{500, 1000, 2500, 0}));
    EXPECT_EQ(loc.waypoints[2].line, 7);  // after a blank line
    EXPECT_EQ(loc.where.element, "motion/locationengine");
    const model::OrientationEngine& o = read.motion.flexible->orientation;
    EXPECT_EQ(o.type, model::OrientationEngineType::velocity);
    EXPECT_EQ(o.up.type, model::DirectionType::constant);
    EXPECT_EQ(o.up.frame, model::LocationFrame::scene);
    EXPECT_EQ(o.up.vector, (std::array<double, 3>{0, 0, 1}));
    EXPECT_FALSE(read.motion.flexible->jitter.any());
}

TEST(MotionReader, StraightEngineOfTheGlistExample) {
    const Read read = read_fixture("straight.motion");
    EXPECT_TRUE(read.diagnostics.items().empty()) << dump(read.diagnostics);
    ASSERT_TRUE(read.motion.flexible);
    const model::LocationEngine& loc = read.motion.flexible->location;
    EXPECT_EQ(loc.type, model::LocationEngineType::straight);
    EXPECT_DOUBLE_EQ(loc.heading_rad, 90 * kDeg);
    EXPECT_EQ(loc.speed_m_s, 100.0);
    EXPECT_EQ(loc.location.frame, model::LocationFrame::scene);
    EXPECT_EQ(loc.location.xyz_m, (std::array<double, 3>{-400, 400, 50000}));
}

TEST(MotionReader, Sgp4AndLookAt) {
    const Read read = read_fixture("iss.motion");
    EXPECT_TRUE(read.diagnostics.items().empty()) << dump(read.diagnostics);
    ASSERT_TRUE(read.motion.flexible);
    const model::LocationEngine& loc = read.motion.flexible->location;
    EXPECT_EQ(loc.type, model::LocationEngineType::sgp4);
    EXPECT_EQ(loc.tle1, "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927");
    EXPECT_EQ(loc.tle2, "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537");
    EXPECT_EQ(loc.tle_where.line, 4);
    EXPECT_EQ(loc.tle_where.element, "motion/locationengine/data/tle1");
    const model::OrientationEngine& o = read.motion.flexible->orientation;
    EXPECT_EQ(o.type, model::OrientationEngineType::lookat);
    ASSERT_TRUE(o.target);
    EXPECT_EQ(o.target->type, model::LocationEngineType::fixed);
    EXPECT_EQ(o.target->location.xyz_m, (std::array<double, 3>{0, 0, 0}));
    EXPECT_EQ(o.up.type, model::DirectionType::velocity);
    EXPECT_EQ(o.up.frame, model::LocationFrame::ecef);
}

TEST(MotionReader, EulerTableAndEveryJitterForm) {
    const Read read = read_fixture("jitter.motion");
    EXPECT_TRUE(read.diagnostics.items().empty()) << dump(read.diagnostics);
    ASSERT_TRUE(read.motion.flexible);
    const model::FlexMotion& f = *read.motion.flexible;
    EXPECT_EQ(f.location.type, model::LocationEngineType::fixed);
    EXPECT_EQ(f.location.location.frame, model::LocationFrame::geodetic);
    EXPECT_EQ(f.location.location.latitude_deg, 43.0);
    EXPECT_EQ(f.location.location.altitude_m, 3000.0);

    EXPECT_EQ(f.orientation.type, model::OrientationEngineType::euler);
    EXPECT_EQ(f.orientation.rotation_order, "zyx");
    ASSERT_EQ(f.orientation.table.size(), 2u);  // blank and tab delimited
    EXPECT_EQ(f.orientation.table[1].time_s, 4.0);
    EXPECT_DOUBLE_EQ(f.orientation.table[1].values[2], 90 * kDeg);
    EXPECT_EQ(f.orientation.table[1].line, 8);

    ASSERT_TRUE(f.jitter.any());
    const model::JitterSpec& lx = f.jitter.location_m[0];
    EXPECT_EQ(lx.kind, model::JitterSpec::Kind::normal);
    EXPECT_DOUBLE_EQ(lx.mean, 1 * kFoot);
    EXPECT_DOUBLE_EQ(lx.stddev, 2 * kFoot);
    EXPECT_EQ(f.jitter.location_m[1].kind, model::JitterSpec::Kind::none);
    const model::JitterSpec& lz = f.jitter.location_m[2];
    EXPECT_EQ(lz.kind, model::JitterSpec::Kind::psd);
    EXPECT_FALSE(lz.psd);
    EXPECT_EQ(lz.psd_file.text, "jitter_psd.txt");
    EXPECT_EQ(lz.psd_file.resolved, kData / "jitter_psd.txt");

    const model::JitterSpec& ox = f.jitter.orientation_rad[0];
    EXPECT_EQ(ox.kind, model::JitterSpec::Kind::psd);
    ASSERT_TRUE(ox.psd);
    EXPECT_EQ(ox.psd->frequency_hz, (std::vector<double>{1, 10}));
    EXPECT_EQ(ox.psd->psd, (std::vector<double>{1e-6, 4e-6}));
    EXPECT_EQ(ox.psd->phase_rad, (std::vector<double>{0.5, 1.5}));
    EXPECT_EQ(ox.psd->where.element, "motion/orientationjitter/xaxis/psd");
    const model::JitterSpec& oy = f.jitter.orientation_rad[1];
    EXPECT_EQ(oy.kind, model::JitterSpec::Kind::normal);
    EXPECT_EQ(oy.mean, 0.0);
    EXPECT_DOUBLE_EQ(oy.stddev, 0.01 * kDeg);
    const model::JitterSpec& oz = f.jitter.orientation_rad[2];
    ASSERT_TRUE(oz.psd);
    // magnitude in deg²/Hz → rad²/Hz; no phases given.
    EXPECT_DOUBLE_EQ(oz.psd->psd[1], 2 * kDeg * kDeg);
    EXPECT_TRUE(oz.psd->phase_rad.empty());
}

TEST(MotionReader, QuaternionSpinAndNestedLookAtTarget) {
    TempDir dir;
    const Read quats = read_text(dir,
                                 "<motion type=\"flexible\">\n"
                                 "<locationengine type=\"fixed\"><point>1, 2, 3</point>"
                                 "</locationengine>\n"
                                 "<orientationengine type=\"quaternions\">\n"
                                 "<data scalar=\"last\" delimiter=\";\">\n"
                                 "0; 0; 0; 0; 1\n"
                                 "1; 0; 0; 0.7071; 0.7071\n"
                                 "</data></orientationengine>\n"
                                 "</motion>\n",
                                 "q.motion");
    EXPECT_TRUE(quats.diagnostics.items().empty()) << dump(quats.diagnostics);
    ASSERT_TRUE(quats.motion.flexible);
    EXPECT_EQ(quats.motion.flexible->location.location.xyz_m, (std::array<double, 3>{1, 2, 3}));
    const auto& table = quats.motion.flexible->orientation.table;
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0].values, (std::array<double, 4>{1, 0, 0, 0}));  // (w, x, y, z)
    EXPECT_EQ(table[1].values, (std::array<double, 4>{0.7071, 0, 0, 0.7071}));
    EXPECT_EQ(table[1].line, 6);  // no CDATA: the text starts on the line after <data>

    const Read spin = read_text(dir,
                                "<motion type=\"flexible\">\n"
                                "<locationengine type=\"fixed\"><location frame=\"ecef\">"
                                "<x>1</x><y>2</y><z>3</z></location></locationengine>\n"
                                "<orientationengine type=\"spin\" angularunits=\"radians\">"
                                "<axis>0 1 0</axis><rate>2</rate><phase>0.5</phase>"
                                "</orientationengine>\n"
                                "</motion>\n",
                                "s.motion");
    EXPECT_TRUE(spin.diagnostics.items().empty()) << dump(spin.diagnostics);
    ASSERT_TRUE(spin.motion.flexible);
    EXPECT_EQ(spin.motion.flexible->location.location.frame, model::LocationFrame::ecef);
    const model::OrientationEngine& s = spin.motion.flexible->orientation;
    EXPECT_EQ(s.type, model::OrientationEngineType::spin);
    EXPECT_EQ(s.spin_axis, (std::array<double, 3>{0, 1, 0}));
    EXPECT_EQ(s.spin_rate_rad_s, 2.0);
    EXPECT_EQ(s.spin_phase_rad, 0.5);

    const Read nested =
        read_text(dir,
                  "<motion type=\"flexible\">\n"
                  "<locationengine type=\"straight\"><velocity>10</velocity><start>0,0,100</start>"
                  "</locationengine>\n"
                  "<orientationengine type=\"lookat\">\n"
                  "<locationengine type=\"straight\"><heading>180</heading><velocity>5</velocity>"
                  "<start frame=\"geodetic\">43, -78, 0</start></locationengine>\n"
                  "<up vector=\"0, 1, 0\"/>\n"
                  "</orientationengine>\n"
                  "</motion>\n",
                  "n.motion");
    EXPECT_TRUE(nested.diagnostics.items().empty()) << dump(nested.diagnostics);
    ASSERT_TRUE(nested.motion.flexible);
    const model::OrientationEngine& o = nested.motion.flexible->orientation;
    ASSERT_TRUE(o.target);
    EXPECT_EQ(o.target->type, model::LocationEngineType::straight);
    EXPECT_DOUBLE_EQ(o.target->heading_rad, std::numbers::pi);
    EXPECT_EQ(o.target->location.frame, model::LocationFrame::geodetic);
    EXPECT_EQ(o.target->location.longitude_deg, -78.0);
    EXPECT_EQ(o.up.vector, (std::array<double, 3>{0, 1, 0}));
    EXPECT_EQ(o.target->where.element, "motion/orientationengine/locationengine");
}

TEST(MotionReader, InlineMotionWithoutSourceReportsRowsAtTheDataLine) {
    const std::string text =
        "<geometrylist>\n"
        "<dynamicinstance name=\"car\">\n"
        "<motion type=\"flexible\">\n"
        "<locationengine type=\"waypoints\"><data><![CDATA[\n"
        "0,0,0,0\n"
        "1,x,0,0\n"
        "]]></data></locationengine>\n"
        "<orientationengine type=\"velocity\"/>\n"
        "</motion>\n"
        "</dynamicinstance>\n"
        "</geometrylist>\n";
    const io::XmlDocument document = io::XmlDocument::parse(text, "scene.glist");
    const io::XmlNode motion = *document.root().child("dynamicinstance")->child("motion");
    for (const bool with_source : {false, true}) {
        const MotionReadContext context{ReadOptions{}, "/tmp",
                                        with_source ? std::string_view(text) : std::string_view()};
        Diagnostics diagnostics;
        const model::FlexMotion flex = read_flex_motion(motion, context, diagnostics);
        ASSERT_EQ(diagnostics.error_count(), 1u) << dump(diagnostics);
        const Diagnostic& d = diagnostics.items()[0];
        EXPECT_EQ(d.message,
                  "row 2 field 2 \"x\" is not a number, expected t, x, y, z separated by \",\"");
        EXPECT_EQ(d.where.file, "scene.glist");
        EXPECT_EQ(d.where.line, with_source ? 6 : 4);
        EXPECT_EQ(d.where.element, "geometrylist/dynamicinstance[car]/motion/locationengine/data");
        ASSERT_EQ(flex.location.waypoints.size(), 1u);
        EXPECT_EQ(flex.location.waypoints[0].line, with_source ? 5 : 4);
    }
}

// ---- bad inputs -------------------------------------------------------------------------------

constexpr const char* kPpdHead =
    "<platformmotion type=\"generic\">\n"
    "<data rotationframe=\"sceneenu\" rotationorder=\"xyz\" angletype=\"absolute\" "
    "angularunits=\"degrees\" spatialunits=\"meters\">\n";

std::string ppd_entry(const std::string& time) {
    return "<entry><datetime type=\"relative\">" + time +
           "</datetime><position><location type=\"scene\"><point><x>0</x><y>0</y><z>1</z>"
           "</point></location></position><orientation><eulerangles><cartesiantriple><x>0</x>"
           "<y>0</y><z>0</z></cartesiantriple></eulerangles></orientation></entry>\n";
}

TEST(MotionReaderErrors, PpdTimesMustIncreaseStrictly) {
    TempDir dir;
    const std::string text = std::string(kPpdHead) + ppd_entry("0") + ppd_entry("5") +
                             ppd_entry("5") + ppd_entry("3") + "</data>\n</platformmotion>\n";
    const Read read = read_text(dir, text, "t.ppd");
    EXPECT_EQ(read.diagnostics.error_count(), 2u) << dump(read.diagnostics);
    expect_diagnostic(read,
                      "entry 3 has the same time (5 s) as entry 2: duplicate times, expected "
                      "strictly increasing times",
                      5, "platformmotion/data/entry");
    expect_diagnostic(read,
                      "entry 4 time 3 s is before entry 3's 5 s, expected strictly increasing "
                      "times",
                      6, "platformmotion/data/entry");
}

TEST(MotionReaderErrors, PpdMissingAndUnsupportedElements) {
    TempDir dir;
    const std::string text =
        "<platformmotion type=\"generic\">\n"
        "<method type=\"cooked\"/>\n"
        "<data rotationframe=\"ned\" rotationorder=\"xzz\" angletype=\"delta\" "
        "angularunits=\"grads\" spatialunits=\"parsecs\">\n"
        "<entry><datetime type=\"absolute\">2020-01-01</datetime></entry>\n"
        "<entry><datetime>1</datetime><position><location type=\"mars\"/></position>"
        "<orientation><eulerangles/></orientation></entry>\n"
        "<entry><datetime>2</datetime><position><location type=\"geodetic\"><latitude>91"
        "</latitude><longitude>0</longitude><altitude>0</altitude></location></position>"
        "<orientation><eulerangles><cartesiantriple><x>0</x><y>0</y></cartesiantriple>"
        "</eulerangles></orientation><speed>3</speed></entry>\n"
        "</data>\n"
        "</platformmotion>\n";
    const Read read = read_text(dir, text, "bad.ppd");
    const std::string data = "platformmotion/data";
    expect_diagnostic(read, "unknown method type \"cooked\", expected raw", 2,
                      "platformmotion/method@type");
    expect_diagnostic(read, "rotationframe \"ned\" is not supported, expected sceneenu or ecef", 3,
                      data + "@rotationframe");
    expect_diagnostic(read, "rotationorder \"xzz\" is not a permutation of xyz", 3,
                      data + "@rotationorder");
    expect_diagnostic(read, "angletype \"delta\" is not supported yet, expected absolute", 3,
                      data + "@angletype");
    expect_diagnostic(read, "unknown angularunits \"grads\", expected degrees or radians", 3,
                      data + "@angularunits");
    expect_diagnostic(read, "unknown spatialunits \"parsecs\", expected meters, kilometers or feet",
                      3, data + "@spatialunits");
    expect_diagnostic(read, "absolute motion times need the tasks file's reference date", 4,
                      data + "/entry/datetime@type");
    expect_diagnostic(read, "missing required element <position>", 4, data + "/entry");
    expect_diagnostic(read, "missing required element <orientation>", 4, data + "/entry");
    expect_diagnostic(read, "unknown location frame \"mars\", expected scene, ecef or geodetic", 5,
                      data + "/entry/position/location@type");
    expect_diagnostic(read, "missing required element <cartesiantriple>", 5,
                      data + "/entry/orientation/eulerangles");
    expect_diagnostic(read, "expected a number in [-90, 90]", 6,
                      data + "/entry/position/location/latitude");
    expect_diagnostic(read, "missing required element <z>", 6,
                      data + "/entry/orientation/eulerangles/cartesiantriple");
    expect_diagnostic(read, "unknown element <speed> ignored", 6, data + "/entry/speed",
                      Severity::warning);
    EXPECT_TRUE(read.motion.generic);
    EXPECT_TRUE(read.motion.generic->entries.empty());
}

TEST(MotionReaderErrors, PpdWithoutDataOrEntries) {
    TempDir dir;
    const Read no_data = read_text(dir, "<platformmotion type=\"generic\"/>\n", "a.ppd");
    expect_diagnostic(no_data, "missing required element <data>", 1, "platformmotion");
    const Read no_entry =
        read_text(dir, std::string(kPpdHead) + "</data>\n</platformmotion>\n", "b.ppd");
    expect_diagnostic(no_entry, "no <entry> in <data>, expected at least one", 2,
                      "platformmotion/data");
}

TEST(MotionReaderErrors, RootElementTellsTheKind) {
    TempDir dir;
    const Read other = read_text(dir, "<platform/>\n", "a.motion");
    expect_diagnostic(other,
                      "expected root element <platformmotion> (GenericMotion .ppd) or <motion> "
                      "(FlexMotion .motion), got <platform>",
                      1, "platform");
    const Read generic_motion = read_text(
        dir, "<motion type=\"generic\"><filename>a.ppd</filename></motion>\n", "b.motion");
    expect_diagnostic(generic_motion, "motion type \"generic\" is not supported in a motion file",
                      1, "motion@type");
    const Read untyped = read_text(dir, "<motion/>\n", "c.motion");
    expect_diagnostic(untyped, "missing required attribute type, expected type=\"flexible\"", 1,
                      "motion");
    const Read delta = read_text(dir, "<platformmotion type=\"delta\"/>\n", "d.ppd");
    expect_diagnostic(delta, "platformmotion type \"delta\" is not supported, expected generic", 1,
                      "platformmotion@type");
    const Read malformed =
        read_text(dir, "<motion type=\"flexible\">\n<a>\n</motion>\n", "e.motion");
    expect_diagnostic(malformed, "malformed XML", 2, "");
    Read missing;
    missing.file = (dir / "nope.motion").string();
    missing.motion = read_motion(missing.file, ReadOptions{}, missing.diagnostics);
    EXPECT_EQ(missing.diagnostics.error_count(), 1u);
    EXPECT_FALSE(missing.motion.generic || missing.motion.flexible);
}

/// A FlexMotion file with `location` and `orientation` engine elements.
std::string flex(const std::string& location, const std::string& orientation) {
    return "<motion type=\"flexible\">\n" + location + "\n" + orientation + "\n</motion>\n";
}

constexpr const char* kVelocity = "<orientationengine type=\"velocity\"/>";
constexpr const char* kFixed =
    "<locationengine type=\"fixed\"><point>0,0,0</point></locationengine>";

TEST(MotionReaderErrors, WaypointRowsReportTheirOwnLine) {
    TempDir dir;
    const std::string text = flex(
        "<locationengine type=\"waypoints\">\n"
        "<data source=\"internal\" datetime=\"relative\" frame=\"scene\" delimiter=\",\">"
        "<![CDATA[\n"
        "0.0,-500,0,2000\n"
        "10.0,500,0,2x0\n"
        "10.0,500,0,2000\n"
        "5.0,500,0,2000\n"
        "20.0,500,0\n"
        "30.0;500;0;2000\n"
        "]]></data>\n"
        "</locationengine>",
        kVelocity);
    const Read read = read_text(dir, text, "w.motion");
    const std::string data = "motion/locationengine/data";
    EXPECT_EQ(read.diagnostics.error_count(), 4u) << dump(read.diagnostics);
    expect_diagnostic(read,
                      "row 2 field 4 \"2x0\" is not a number, expected t, x, y, z separated by "
                      "\",\"",
                      line_of(text, "2x0"), data);
    // Row 2 was bad, so row 3 follows row 1: fine. Row 4 goes back in time.
    expect_diagnostic(read,
                      "row 4 time 5 s is before row 3's 10 s, expected strictly increasing times",
                      line_of(text, "5.0,"), data);
    expect_diagnostic(read, "row 5 has 3 fields, expected 4 (t, x, y, z) separated by \",\"",
                      line_of(text, "20.0"), data);
    expect_diagnostic(read, "row 6 has 1 fields, expected 4", line_of(text, "30.0"), data);

    const Read duplicate = read_text(dir,
                                     flex("<locationengine type=\"waypoints\"><data><![CDATA[\n"
                                          "1,0,0,0\n"
                                          "1,1,0,0\n"
                                          "]]></data></locationengine>",
                                          kVelocity),
                                     "d.motion");
    expect_diagnostic(duplicate,
                      "row 2 has the same time (1 s) as row 1: duplicate times, expected "
                      "strictly increasing times",
                      4, data);
}

TEST(MotionReaderErrors, BadTableAttributes) {
    TempDir dir;
    const std::string data = "motion/locationengine/data";
    const auto read_data = [&](const std::string& attributes, const std::string& name) {
        return read_text(dir,
                         flex("<locationengine type=\"waypoints\">\n<data " + attributes +
                                  "><![CDATA[\n0,0,0,0\n]]></data></locationengine>",
                              kVelocity),
                         name);
    };
    expect_diagnostic(read_data("delimiter=\"ab\"", "a.motion"),
                      "delimiter \"ab\" is not one character other than a digit, letter, '.', "
                      "'+' or '-', expected e.g. \",\"",
                      3, data + "@delimiter");
    expect_diagnostic(read_data("delimiter=\"-\"", "b.motion"), "delimiter \"-\" is not one", 3,
                      data + "@delimiter");
    expect_diagnostic(read_data("source=\"stk_report\"", "c.motion"),
                      "data source \"stk_report\" is not supported yet, expected internal", 3,
                      data + "@source");
    expect_diagnostic(read_data("datetime=\"absolute\"", "d.motion"),
                      "absolute motion times need the tasks file's reference date", 3,
                      data + "@datetime");
    expect_diagnostic(read_data("frame=\"teme\"", "e.motion"),
                      "unknown waypoint frame \"teme\", expected scene, ecef or geodetic", 3,
                      data + "@frame");
    const Read geodetic = read_text(dir,
                                    flex("<locationengine type=\"waypoints\">\n"
                                         "<data frame=\"geodetic\"><![CDATA[\n"
                                         "0, 43, -78, 100\n"
                                         "1, 95, -78, 100\n"
                                         "]]></data></locationengine>",
                                         kVelocity),
                                    "f.motion");
    expect_diagnostic(geodetic, "row 2 latitude 95 is out of range, expected [-90, 90] degrees", 5,
                      data);
    const Read empty = read_text(dir,
                                 flex("<locationengine type=\"waypoints\">\n<data>  </data>"
                                      "</locationengine>",
                                      kVelocity),
                                 "g.motion");
    expect_diagnostic(empty, "no rows in <data>, expected lines of t, x, y, z", 3, data);
}

TEST(MotionReaderErrors, UnknownEnginesAndMissingElements) {
    TempDir dir;
    const Read unknown = read_text(
        dir, flex("<locationengine type=\"orbit\"/>", "<orientationengine type=\"tumble\"/>"),
        "u.motion");
    expect_diagnostic(unknown,
                      "unknown location engine type \"orbit\", expected waypoints, straight, "
                      "fixed or sgp4",
                      2, "motion/locationengine@type");
    expect_diagnostic(unknown,
                      "unknown orientation engine type \"tumble\", expected velocity, lookat, "
                      "euler, quaternions or spin",
                      3, "motion/orientationengine@type");

    const Read missing =
        read_text(dir, "<motion type=\"flexible\">\n<jitter/>\n</motion>\n", "m.motion");
    expect_diagnostic(missing, "missing required element <locationengine>", 1, "motion");
    expect_diagnostic(missing, "missing required element <orientationengine>", 1, "motion");
    expect_diagnostic(missing, "unknown element <jitter> ignored", 2, "motion/jitter",
                      Severity::warning);

    const Read untyped = read_text(dir, flex("<locationengine/>", kVelocity), "t.motion");
    expect_diagnostic(untyped,
                      "missing required attribute type, expected waypoints, straight, fixed or "
                      "sgp4",
                      2, "motion/locationengine");

    const Read parts = read_text(
        dir,
        flex("<locationengine type=\"straight\"><heading>x</heading></locationengine>",
             "<orientationengine type=\"lookat\"><up type=\"sideways\"/></orientationengine>"),
        "p.motion");
    expect_diagnostic(parts, "missing required element <velocity>", 2, "motion/locationengine");
    expect_diagnostic(parts, "missing required element <start>", 2, "motion/locationengine");
    expect_diagnostic(parts, "expected a number", 2, "motion/locationengine/heading");
    expect_diagnostic(parts, "missing required element <point> (the look-at target", 3,
                      "motion/orientationengine");
    expect_diagnostic(parts, "unknown <up> type \"sideways\", expected constant or velocity", 3,
                      "motion/orientationengine/up@type");

    const Read tables = read_text(
        dir, flex("<locationengine type=\"sgp4\"/>", "<orientationengine type=\"euler\"/>"),
        "e.motion");
    expect_diagnostic(tables, "missing required element <data> (the two-line element set)", 2,
                      "motion/locationengine");
    expect_diagnostic(tables, "missing required element <data> (the Euler angle table)", 3,
                      "motion/orientationengine");

    const Read tle = read_text(dir,
                               flex("<locationengine type=\"sgp4\"><data><tle1> </tle1>"
                                    "</data></locationengine>",
                                    kVelocity),
                               "l.motion");
    expect_diagnostic(tle, "missing required element <tle2>", 2, "motion/locationengine/data");
    expect_diagnostic(tle, "<tle1> is empty, expected a TLE line", 2,
                      "motion/locationengine/data/tle1");
}

TEST(MotionReaderErrors, BadDirectionsLocationsAndOrientationTables) {
    TempDir dir;
    const Read read = read_text(
        dir,
        flex("<locationengine type=\"fixed\"><location frame=\"scene\" type=\"ecef\">1,2,3"
             "</location></locationengine>",
             "<orientationengine type=\"velocity\"><constraint frame=\"geodetic\" "
             "vector=\"0,0,0\"/></orientationengine>"),
        "a.motion");
    expect_diagnostic(read, "@frame \"scene\" and @type \"ecef\" disagree", 2,
                      "motion/locationengine/location@type");
    expect_diagnostic(read, "unknown direction frame \"geodetic\", expected scene or ecef", 3,
                      "motion/orientationengine/constraint@frame");
    expect_diagnostic(read, "the vector is zero, expected a direction", 3,
                      "motion/orientationengine/constraint@vector");

    const Read point =
        read_text(dir,
                  flex("<locationengine type=\"fixed\"><point>1,2</point></locationengine>",
                       "<orientationengine type=\"velocity\"><constraint type=\"velocity\"/>"
                       "</orientationengine>"),
                  "b.motion");
    expect_diagnostic(point,
                      "\"1,2\" is not a location, expected <point> with <x>, <y>, <z> children, "
                      "or the text \"x, y, z\"",
                      2, "motion/locationengine/point");
    expect_diagnostic(point, "unknown <constraint> type \"velocity\", expected constant", 3,
                      "motion/orientationengine/constraint@type");

    const std::string quaternions =
        "<orientationengine type=\"quaternions\">\n<data scalar=\"middle\"><![CDATA[\n"
        "0, 0, 0, 0, 0\n"
        "]]></data></orientationengine>";
    const Read q = read_text(dir, flex(kFixed, quaternions), "q.motion");
    expect_diagnostic(q, "unknown scalar position \"middle\"", 4,
                      "motion/orientationengine/data@scalar");
    expect_diagnostic(q, "row 1 quaternion is zero, expected a rotation", 5,
                      "motion/orientationengine/data");

    const Read spin = read_text(dir,
                                flex(kFixed,
                                     "<orientationengine type=\"spin\"><axis>0,0,0</axis>"
                                     "</orientationengine>"),
                                "s.motion");
    expect_diagnostic(spin, "the spin axis is zero, expected a direction", 3,
                      "motion/orientationengine/axis");
    expect_diagnostic(spin, "missing required element <rate>", 3, "motion/orientationengine");
}

TEST(MotionReaderErrors, BadJitter) {
    TempDir dir;
    const std::string text = flex(kFixed, kVelocity) + "";
    const std::string jitter =
        "<motion type=\"flexible\">\n" + std::string(kFixed) + "\n" + kVelocity +
        "\n"
        "<orientationjitter angularunits=\"furlongs\">\n"
        "<xaxis type=\"brownian\"/>\n"
        "<yaxis type=\"uncorrelated\"><mean>1</mean></yaxis>\n"
        "<zaxis type=\"correlated\"/>\n"
        "<zaxis/>\n"
        "</orientationjitter>\n"
        "<locationjitter>\n"
        "<xaxis><psd frequencyunits=\"rpm\">\n"
        "<entry><frequency>2</frequency><magnitude>1</magnitude><phase>0</phase></entry>\n"
        "<entry><frequency>2</frequency><magnitude>1</magnitude></entry>\n"
        "<entry><frequency>1</frequency><magnitude>-1</magnitude></entry>\n"
        "</psd><psdfile>a.txt</psdfile></xaxis>\n"
        "<yaxis><psd><entry><frequency>1</frequency><magnitude>1</magnitude></entry></psd>"
        "</yaxis>\n"
        "</locationjitter>\n"
        "</motion>\n";
    const Read read = read_text(dir, jitter, "j.motion");
    const std::string oj = "motion/orientationjitter";
    const std::string lj = "motion/locationjitter";
    expect_diagnostic(read, "unknown angularunits \"furlongs\", expected degrees or radians", 4,
                      oj + "@angularunits");
    expect_diagnostic(read,
                      "unknown jitter type \"brownian\", expected correlated (psd), uncorrelated "
                      "(normal) or none",
                      5, oj + "/xaxis@type");
    expect_diagnostic(read, "missing required element <stddev>", 6, oj + "/yaxis");
    expect_diagnostic(read, "missing required element <psd> (a correlated jitter needs", 7,
                      oj + "/zaxis");
    expect_diagnostic(read, "<zaxis> given again (first at line 7)", 8, oj + "/zaxis");
    expect_diagnostic(read, "unknown frequencyunits \"rpm\", expected hertz", 11,
                      lj + "/xaxis/psd@frequencyunits");
    expect_diagnostic(read,
                      "entry 2 has the same frequency (2 Hz) as entry 1: duplicate frequencies", 13,
                      lj + "/xaxis/psd/entry");
    expect_diagnostic(read, "expected a number >= 0", 14, lj + "/xaxis/psd/entry/magnitude");
    expect_diagnostic(read,
                      "<phase> given in 1 of 3 entries, expected it in every entry or in none", 11,
                      lj + "/xaxis/psd");
    expect_diagnostic(read, "both <psd> and <psdfile> given", 15, lj + "/xaxis/psdfile");
    expect_diagnostic(read, "<psd> has 1 entries, expected at least 2", 16, lj + "/yaxis/psd");
}

}  // namespace motion_reader_test
}  // namespace glint::dirsig
