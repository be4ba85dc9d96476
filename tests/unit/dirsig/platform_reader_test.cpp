// SPDX-License-Identifier: Apache-2.0
// Tests of the `.platform` reader's tree: the minimal and two-instrument fixtures field by
// field (SI conversions, nesting, metadata, affine transforms, instrument properties), and
// the bad inputs of the file, the attachment tree, affine transforms, instruments and
// instrument properties, each checked for its message, line and element path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "glint/test/angles.h"
#include "platform_test_util.h"

namespace glint::test::plat {
namespace platform_reader_test {

using ::testing::HasSubstr;
using Severity = Diagnostic::Severity;

using glint::test::kDeg;

TEST(PlatformReader, MinimalFixtureFieldByField) {
    const Read read = read_fixture("minimal.platform");
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    EXPECT_EQ(read.diagnostics.warning_count(), 0u) << dump(read.diagnostics);
    const model::Platform& p = read.platform;
    EXPECT_EQ(p.file, read.file);
    EXPECT_TRUE(p.metadata.entries.empty());
    EXPECT_TRUE(p.clock_table.empty());
    ASSERT_EQ(p.attachments.size(), 1u);
    const model::Attachment& outer = p.attachments[0];
    EXPECT_TRUE(outer.transform.is_identity());
    EXPECT_EQ(outer.where.line, 3);
    EXPECT_EQ(outer.where.element, "platform/attachment");
    ASSERT_EQ(outer.mounts.size(), 1u);
    EXPECT_TRUE(outer.instruments.empty());
    const model::Mount& mount = outer.mounts[0];
    EXPECT_EQ(mount.name, "Belly");
    EXPECT_EQ(mount.type, model::MountType::static_mount);
    EXPECT_EQ(mount.type_text, "static");
    EXPECT_EQ(mount.rotation_order, "xyz");
    EXPECT_EQ(mount.rotation_rad, (std::array<double, 3>{0, 0, 0}));
    EXPECT_FALSE(mount.deviates.any());
    EXPECT_EQ(mount.where.element, "platform/attachment/mount[Belly]");
    ASSERT_EQ(mount.attachments.size(), 1u);
    ASSERT_EQ(mount.attachments[0].instruments.size(), 1u);
    const model::Instrument& cam = mount.attachments[0].instruments[0];
    EXPECT_EQ(cam.name, "Cam");
    EXPECT_EQ(cam.type, model::InstrumentType::generic);
    EXPECT_EQ(cam.type_text, "generic");
    ASSERT_TRUE(cam.properties.focal_length_m);
    EXPECT_DOUBLE_EQ(*cam.properties.focal_length_m, 0.05);  // 50 mm
    ASSERT_TRUE(cam.properties.aperture_diameter_m);
    EXPECT_DOUBLE_EQ(*cam.properties.aperture_diameter_m, 0.025);
    EXPECT_DOUBLE_EQ(cam.properties.aperture_throughput, 0.9);
    EXPECT_FALSE(cam.properties.focus_distance_m);
    EXPECT_FALSE(cam.properties.distortion);
    ASSERT_EQ(cam.focal_planes.size(), 1u);
    const model::FocalPlane& fp = cam.focal_planes[0];
    EXPECT_TRUE(fp.enabled);
    EXPECT_EQ(fp.name, "RGB");
    EXPECT_EQ(fp.where.element,
              "platform/attachment/mount[Belly]/attachment/instrument[Cam]/"
              "focalplane[RGB]");
    EXPECT_EQ(fp.capture_method.image_file.basename, "rgb");
    ASSERT_EQ(fp.capture_method.spectral_response.channels.size(), 1u);
    const model::DetectorArray& a = fp.detector_array;
    EXPECT_EQ(a.spatial_units, "microns");
    EXPECT_EQ(a.x_count, 64u);
    EXPECT_EQ(a.y_count, 48u);
    EXPECT_DOUBLE_EQ(a.x_size_m, 5e-6);  // 5 microns
    EXPECT_DOUBLE_EQ(a.y_size_m, 5e-6);
    EXPECT_DOUBLE_EQ(a.x_spacing_m, 5e-6);
    EXPECT_DOUBLE_EQ(a.y_spacing_m, 5e-6);
    EXPECT_EQ(a.x_offset_m, 0.0);
    EXPECT_FALSE(a.x_flip);
    EXPECT_FALSE(a.y_flip);
    EXPECT_FALSE(a.rolling_line_time_s);
    EXPECT_EQ(a.clock.type, model::ClockType::independent);
    EXPECT_EQ(a.clock.temporal_units, "hertz");
    EXPECT_DOUBLE_EQ(a.clock.rate_hz, 10.0);
    EXPECT_EQ(a.clock.offset_s, 0.0);
    EXPECT_EQ(a.clock.where.line, 36);
    ASSERT_EQ(fp.truth_collections.size(), 1u);
    EXPECT_TRUE(fp.truth_collections[0].enabled);
    EXPECT_EQ(fp.truth_collections[0].image_file.basename, "rgb_truth");
    ASSERT_EQ(fp.truth_collections[0].collectors.size(), 1u);
    EXPECT_EQ(fp.truth_collections[0].collectors[0].name, "Material");

    const auto list = model::list_instruments(p);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0].instrument, &cam);
    ASSERT_EQ(list[0].attachments.size(), 2u);
    EXPECT_EQ(list[0].attachments[0], &outer);
    EXPECT_EQ(list[0].attachments[1], &mount.attachments[0]);
    ASSERT_EQ(list[0].mounts.size(), 1u);
    EXPECT_EQ(list[0].mounts[0], &mount);
}

TEST(PlatformReader, TwoInstrumentsFixtureFieldByField) {
    const Read read = read_fixture("two_instruments.platform");
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    EXPECT_EQ(read.diagnostics.warning_count(), 0u) << dump(read.diagnostics);
    const model::Platform& p = read.platform;

    // Metadata in file order, CDATA unwrapped, an empty value kept.
    ASSERT_EQ(p.metadata.entries.size(), 4u);
    EXPECT_EQ(p.metadata.entries[0].first, "Author(s)");
    EXPECT_EQ(p.metadata.entries[0].second, "glint test suite");
    EXPECT_EQ(p.metadata.entries[2].first, "Name");
    EXPECT_EQ(p.metadata.entries[2].second, "TwoCameras");
    EXPECT_EQ(p.metadata.entries[3].first, "Organization");
    EXPECT_EQ(p.metadata.entries[3].second, "");

    ASSERT_EQ(p.attachments.size(), 2u);
    const model::AffineTransform& t = p.attachments[0].transform;
    EXPECT_FALSE(t.is_identity());
    EXPECT_EQ(t.translation_m, (std::array<double, 3>{1.5, -0.25, 0.1}));
    EXPECT_EQ(t.rotation_rad, (std::array<double, 3>{0, 0, 0}));
    EXPECT_FALSE(t.matrix);
    EXPECT_EQ(t.where.element, "platform/attachment/affinetransform");
    EXPECT_TRUE(p.attachments[1].transform.is_identity());

    const model::Mount& gimbal = p.attachments[0].mounts.at(0);
    EXPECT_EQ(gimbal.name, "Gimbal");
    EXPECT_EQ(gimbal.rotation_order, "zyx");
    EXPECT_DOUBLE_EQ(gimbal.rotation_rad[0], 0.0);
    EXPECT_DOUBLE_EQ(gimbal.rotation_rad[1], -30 * kDeg);
    EXPECT_DOUBLE_EQ(gimbal.rotation_rad[2], std::numbers::pi / 2);
    const model::Mount& tilt = gimbal.attachments.at(0).mounts.at(0);
    EXPECT_EQ(tilt.name, "Tilt");
    EXPECT_DOUBLE_EQ(tilt.rotation_rad[0], 0.1);  // radians kept
    EXPECT_EQ(tilt.where.element, "platform/attachment/mount[Gimbal]/attachment/mount[Tilt]");

    const model::Instrument& wide = tilt.attachments.at(0).instruments.at(0);
    EXPECT_EQ(wide.name, "Wide");
    EXPECT_DOUBLE_EQ(*wide.properties.focal_length_m, 0.035);
    EXPECT_DOUBLE_EQ(wide.properties.aperture_throughput, 0.8);
    ASSERT_EQ(wide.focal_planes.size(), 2u);
    const model::FocalPlane& vis = wide.focal_planes[0];
    EXPECT_TRUE(vis.enabled);
    EXPECT_EQ(vis.name, "VIS");
    const model::DetectorArray& a = vis.detector_array;
    EXPECT_EQ(a.spatial_units, "millimeters");
    EXPECT_EQ(a.x_count, 320u);
    EXPECT_EQ(a.y_count, 240u);
    EXPECT_DOUBLE_EQ(a.x_size_m, 8e-6);
    EXPECT_DOUBLE_EQ(a.y_size_m, 9e-6);
    EXPECT_DOUBLE_EQ(a.x_spacing_m, 1e-5);
    EXPECT_DOUBLE_EQ(a.y_spacing_m, 1e-5);
    EXPECT_DOUBLE_EQ(a.x_offset_m, 5e-4);
    EXPECT_DOUBLE_EQ(a.y_offset_m, -2.5e-4);
    EXPECT_TRUE(a.x_flip);
    EXPECT_FALSE(a.y_flip);
    EXPECT_DOUBLE_EQ(a.clock.rate_hz, 2.0);
    EXPECT_DOUBLE_EQ(a.clock.offset_s, 0.25);
    const model::FocalPlane& nir = wide.focal_planes[1];
    EXPECT_FALSE(nir.enabled);
    EXPECT_EQ(nir.name, "NIR");
    // Sizes default to the spacing; offsets and flips to 0.
    EXPECT_DOUBLE_EQ(nir.detector_array.x_size_m, 20e-6);
    EXPECT_DOUBLE_EQ(nir.detector_array.y_size_m, 20e-6);
    EXPECT_EQ(nir.detector_array.x_offset_m, 0.0);
    EXPECT_FALSE(nir.detector_array.y_flip);

    const model::Instrument& narrow =
        p.attachments[1].mounts.at(0).attachments.at(0).instruments.at(0);
    EXPECT_EQ(narrow.name, "Narrow");
    EXPECT_DOUBLE_EQ(*narrow.properties.focal_length_m, 0.3);
    EXPECT_DOUBLE_EQ(*narrow.properties.aperture_diameter_m, 0.1);
    EXPECT_DOUBLE_EQ(narrow.properties.aperture_throughput, 1.0);  // default
    EXPECT_DOUBLE_EQ(*narrow.properties.focus_distance_m, 2500.0);
    ASSERT_TRUE(narrow.properties.distortion);
    EXPECT_DOUBLE_EQ(narrow.properties.distortion->k1, 0.01);
    EXPECT_DOUBLE_EQ(narrow.properties.distortion->k2, -0.002);
    EXPECT_DOUBLE_EQ(narrow.properties.distortion->k3, 0.0);
    EXPECT_DOUBLE_EQ(narrow.properties.distortion->p1, 0.0005);
    EXPECT_DOUBLE_EQ(narrow.properties.distortion->p2, -0.0001);
    EXPECT_DOUBLE_EQ(narrow.focal_planes.at(0).detector_array.x_size_m, 6.5e-6);

    // Document order: Wide (two mounts deep), then Narrow.
    const auto list = model::list_instruments(p);
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0].instrument, &wide);
    ASSERT_EQ(list[0].mounts.size(), 2u);
    EXPECT_EQ(list[0].mounts[0], &gimbal);
    EXPECT_EQ(list[0].mounts[1], &tilt);
    ASSERT_EQ(list[0].attachments.size(), 3u);
    EXPECT_EQ(list[0].attachments[0], &p.attachments[0]);
    EXPECT_EQ(list[1].instrument, &narrow);
    EXPECT_EQ(list[1].attachments.size(), 2u);
    EXPECT_EQ(list[1].attachments[0], &p.attachments[1]);
}

// ---- the file ------------------------------------------------------------------------------

TEST(PlatformReader, MalformedXmlNamesTheLine) {
    TempDir dir;
    const std::string text =
        "<platform>\n<clocktable/>\n<attachment>\n<mount name=\"M\">\n"
        "</attachment>\n</platform>\n";
    const Read read = read_text(dir, text);
    ASSERT_EQ(read.diagnostics.error_count(), 1u) << dump(read.diagnostics);
    const Diagnostic& d = read.diagnostics.items()[0];
    EXPECT_THAT(d.message, HasSubstr("malformed XML"));
    EXPECT_EQ(d.where.file, read.file);
    EXPECT_THAT(d.message, HasSubstr("<mount>"));  // the element left open
    EXPECT_EQ(d.where.line, 4) << d.text();
    EXPECT_TRUE(read.platform.attachments.empty());
}

TEST(PlatformReader, MissingFileIsAnErrorNotAThrow) {
    Diagnostics diagnostics;
    const model::Platform p =
        dirsig::read_platform("/nonexistent/glint/x.platform", options(), diagnostics);
    ASSERT_EQ(diagnostics.error_count(), 1u);
    EXPECT_EQ(diagnostics.items()[0].where.file, "/nonexistent/glint/x.platform");
    EXPECT_THAT(diagnostics.items()[0].message, HasSubstr("cannot open"));
    EXPECT_TRUE(p.attachments.empty());
}

TEST(PlatformReader, WrongRootElement) {
    TempDir dir;
    const Read read = read_text(dir, "\n<tasklist/>\n");
    ASSERT_EQ(read.diagnostics.error_count(), 1u);
    EXPECT_THAT(read.diagnostics.items()[0].message,
                HasSubstr("expected root element <platform>, got <tasklist>"));
    EXPECT_EQ(read.diagnostics.items()[0].where.line, 2);
}

TEST(PlatformReader, UnknownElementsWarnOncePerElement) {
    TempDir dir;
    const std::string text =
        "<platform>\n<clocktable/>\n<gizmo/>\n<attachment>\n"
        "<affinetransform/>\n<widget/>\n" +
        std::string("<mount name=\"M\" type=\"static\"><sprocket/></mount>\n") +
        "</attachment>\n</platform>\n";
    const Read read = read_text(dir, text);
    EXPECT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    EXPECT_EQ(count(read.diagnostics, "unknown element", Severity::warning), 3u)
        << dump(read.diagnostics);
    expect_diagnostic(read, "unknown element <gizmo> ignored", 3, "platform/gizmo",
                      Severity::warning);
    expect_diagnostic(read, "unknown element <widget> ignored", 6, "platform/attachment/widget",
                      Severity::warning);
    expect_diagnostic(read, "unknown element <sprocket> ignored", 7,
                      "platform/attachment/mount[M]/sprocket", Severity::warning);
}

TEST(PlatformReader, EmptyPlatformAndEmptyAttachmentWarn) {
    TempDir dir;
    const Read none = read_text(dir, "<platform>\n<clocktable/>\n</platform>\n");
    EXPECT_FALSE(none.diagnostics.has_errors());
    expect_diagnostic(none, "platform has no <attachment>", 1, "platform", Severity::warning);
    const Read empty = read_text(
        dir, "<platform>\n<attachment>\n<affinetransform/>\n</attachment>\n</platform>\n");
    EXPECT_FALSE(empty.diagnostics.has_errors());
    expect_diagnostic(empty, "attachment holds no mount and no instrument", 2,
                      "platform/attachment", Severity::warning);
}

TEST(PlatformReader, PlatformLevelJitterIsWarnedNotUsed) {
    TempDir dir;
    const std::string text =
        "<platform>\n<rotationdeviates><xrotation type=\"normal\"><stddev>1</stddev>"
        "</xrotation></rotationdeviates>\n<locationdeviates/>\n</platform>\n";
    const Read read = read_text(dir, text);
    EXPECT_FALSE(read.diagnostics.has_errors());
    expect_diagnostic(read, "platform-level <rotationdeviates> (vehicle jitter) is not supported",
                      2, "platform/rotationdeviates", Severity::warning);
    EXPECT_EQ(count(read.diagnostics, "locationdeviates", Severity::warning), 0u);
}

TEST(PlatformReader, MetadataEntryWithoutName) {
    TempDir dir;
    const Read read = read_text(dir,
                                "<platform>\n<metadata>\n<entry><value>x</value></entry>\n"
                                "</metadata>\n</platform>\n");
    expect_diagnostic(read, "missing required element <name>", 3, "platform/metadata/entry");
}

// ---- affine transforms ---------------------------------------------------------------------

std::string attachment_with(const std::string& transform) {
    return "<platform>\n<attachment>\n" + transform +
           "\n<mount name=\"M\" type=\"static\"/>\n</attachment>\n</platform>\n";
}

TEST(PlatformReader, AffineTransformRotationsAndSpellings) {
    TempDir dir;
    const Read read = read_text(
        dir, attachment_with("<affinetransform angularunits=\"degrees\" rotationorder=\"ZXY\">"
                             "<xtranslation>1</xtranslation><ztranslate>-2</ztranslate>"
                             "<xrotate>90</xrotate><zrotation>45</zrotation></affinetransform>"));
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    const model::AffineTransform& t = read.platform.attachments.at(0).transform;
    EXPECT_EQ(t.translation_m, (std::array<double, 3>{1, 0, -2}));
    EXPECT_DOUBLE_EQ(t.rotation_rad[0], std::numbers::pi / 2);
    EXPECT_DOUBLE_EQ(t.rotation_rad[2], std::numbers::pi / 4);
    EXPECT_EQ(t.rotation_order, "zxy");
    EXPECT_FALSE(t.is_identity());
}

TEST(PlatformReader, AffineTransformRadiansAndMatrix) {
    TempDir dir;
    const Read rad = read_text(
        dir, attachment_with("<affinetransform angularunits=\"radians\"><yrotate>0.25</yrotate>"
                             "</affinetransform>"));
    ASSERT_FALSE(rad.diagnostics.has_errors()) << dump(rad.diagnostics);
    EXPECT_DOUBLE_EQ(rad.platform.attachments.at(0).transform.rotation_rad[1], 0.25);

    const Read matrix =
        read_text(dir, attachment_with("<affinetransform><matrix>1 0 0 2\n0 1 0 3,0 0 1 4, 0 0 0 1"
                                       "</matrix></affinetransform>"));
    ASSERT_FALSE(matrix.diagnostics.has_errors()) << dump(matrix.diagnostics);
    const auto& m = matrix.platform.attachments.at(0).transform.matrix;
    ASSERT_TRUE(m);
    EXPECT_EQ((*m)[3], 2.0);
    EXPECT_EQ((*m)[7], 3.0);
    EXPECT_EQ((*m)[11], 4.0);
    EXPECT_FALSE(matrix.platform.attachments.at(0).transform.is_identity());

    const Read identity = read_text(
        dir, attachment_with("<affinetransform><matrix>1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1</matrix>"
                             "</affinetransform>"));
    ASSERT_FALSE(identity.diagnostics.has_errors());
    EXPECT_TRUE(identity.platform.attachments.at(0).transform.is_identity());
}

TEST(PlatformReader, AffineTransformErrors) {
    TempDir dir;
    const std::string text = attachment_with(
        "<affinetransform angularunits=\"grads\" rotationorder=\"xxz\">\n"
        "<xtranslate>1</xtranslate>\n<xtranslation>2</xtranslation>\n"
        "<yrotate>ten</yrotate>\n"
        "<matrix>1 0 0 0 0 1 0 0 0 0 1 0 0 0 0</matrix>\n</affinetransform>");
    const Read read = read_text(dir, text);
    const std::string at = "platform/attachment/affinetransform";
    expect_diagnostic(read, "unknown angularunits \"grads\", expected degrees or radians", 3,
                      at + "@angularunits");
    expect_diagnostic(read,
                      "rotationorder \"xxz\" is not a permutation of xyz, expected xyz, xzy, "
                      "yxz, yzx, zxy or zyx",
                      3, at + "@rotationorder");
    expect_diagnostic(read, "both <xtranslate> and <xtranslation> given", 5, at + "/xtranslation");
    expect_diagnostic(read, "expected a number, got \"ten\"", 6, at + "/yrotate");
    expect_diagnostic(read, "<matrix> given together with translations or rotations", 7,
                      at + "/matrix");
    expect_diagnostic(read, "matrix has 15 values, expected 16 (a row-major 4x4 matrix)", 7,
                      at + "/matrix");

    const Read row = read_text(
        dir, attachment_with("<affinetransform><matrix>1 0 0 0 0 1 0 0 0 0 1 0 0 0 1 1</matrix>"
                             "</affinetransform>"));
    expect_diagnostic(row, "matrix last row is 0 0 1 1, expected 0 0 0 1 (an affine transform)", 3,
                      "platform/attachment/affinetransform/matrix");
    const Read junk = read_text(
        dir, attachment_with("<affinetransform><matrix>1 0 x</matrix></affinetransform>"));
    expect_diagnostic(junk, "\"x\" is not a number, expected 16 numbers", 3,
                      "platform/attachment/affinetransform/matrix");
    const Read two = read_text(dir, attachment_with("<affinetransform/>\n<affinetransform/>"));
    expect_diagnostic(two, "more than one <affinetransform> in an <attachment>", 4,
                      "platform/attachment/affinetransform");
}

// ---- instruments ----------------------------------------------------------------------------

TEST(PlatformReader, InstrumentTypesAndVariants) {
    TempDir dir;
    const Read read = read_text(
        dir, with_instrument("<instrument name=\"A\" type=\"Data_Recorder\"/>\n"
                             "<instrument name=\"B\" type=\"data recorder\"/>\n"
                             "<instrument name=\"C\" type=\"lidar\"><transmitter>"
                             "<wavelength>1.064</wavelength><pulseenergy>1e-3</pulseenergy>"
                             "<pulseduration>5e-9</pulseduration><beamdivergence>1e-3"
                             "</beamdivergence></transmitter></instrument>\n"
                             "<instrument name=\"D\"><properties><focallength>10</focallength>"
                             "</properties></instrument>"));
    ASSERT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    const auto& list = read.platform.attachments.at(0).instruments;
    ASSERT_EQ(list.size(), 4u);
    EXPECT_EQ(list[0].type, model::InstrumentType::data_recorder);
    EXPECT_EQ(list[0].type_text, "Data_Recorder");
    EXPECT_EQ(list[1].type, model::InstrumentType::data_recorder);
    EXPECT_EQ(list[2].type, model::InstrumentType::lidar);
    ASSERT_TRUE(list[2].transmitter);
    EXPECT_EQ(list[2].transmitter->wavelength_um, 1.064);
    EXPECT_EQ(list[2].transmitter->pulse_energy_j, 1e-3);
    EXPECT_EQ(list[2].transmitter->pulse_duration_s, 5e-9);
    EXPECT_EQ(list[2].transmitter->beam_divergence_rad, 1e-3);
    EXPECT_TRUE(list[2].transmitter->pulse_shape_file.empty());  // Gaussian
    EXPECT_EQ(list[3].type, model::InstrumentType::generic);     // default
    EXPECT_EQ(list[3].type_text, "generic");
    // The lidar and the generic camera without focal planes capture nothing: warned.
    EXPECT_EQ(count(read.diagnostics, "instrument has no <focalplane>", Severity::warning), 2u);
}

TEST(PlatformReader, UnknownInstrumentType) {
    TempDir dir;
    const Read read = read_text(dir, with_instrument("<instrument name=\"Cam\" type=\"laser\"/>"));
    expect_diagnostic(read,
                      "unknown instrument type \"laser\", expected generic, lidar or "
                      "datarecorder",
                      5, std::string(kInstrumentPath) + "@type");
}

TEST(PlatformReader, GenericInstrumentNeedsFocalLength) {
    TempDir dir;
    const Read none =
        read_text(dir, with_instrument("<instrument name=\"Cam\" type=\"generic\"/>"));
    expect_diagnostic(none, "missing required element <properties>", 5, kInstrumentPath);
    const Read missing =
        read_text(dir, with_instrument("<instrument name=\"Cam\">\n<properties>\n"
                                       "<aperturediameter>0.1</aperturediameter>\n</properties>\n"
                                       "</instrument>"));
    expect_diagnostic(missing, "missing required element <focallength>", 6,
                      std::string(kInstrumentPath) + "/properties");
    // A lidar or data recorder may go without; a lidar needs its transmitter instead.
    const Read lidar =
        read_text(dir, with_instrument("<instrument name=\"L\" type=\"lidar\"><properties/>"
                                       "</instrument>"));
    expect_diagnostic(lidar,
                      "a lidar instrument needs a <transmitter> (its laser: wavelength, pulse "
                      "energy and duration, beam divergence)",
                      5, std::string("platform/attachment/instrument[L]"));
}

TEST(PlatformReader, InstrumentPropertyErrors) {
    TempDir dir;
    const std::string text = with_instrument(
        "<instrument name=\"Cam\">\n<properties>\n"
        "<focallength>fifty</focallength>\n"
        "<aperturethroughput>1.5</aperturethroughput>\n"
        "<focusdistance>100</focusdistance>\n"
        "<distortion><k1>x</k1></distortion>\n"
        "</properties>\n</instrument>");
    const Read read = read_text(dir, text);
    const std::string at = std::string(kInstrumentPath) + "/properties";
    expect_diagnostic(read, "expected a number > 0, got \"fifty\"", line_of(text, "<focallength>"),
                      at + "/focallength");
    expect_diagnostic(read, "expected a number in (0, 1], got \"1.5\"",
                      line_of(text, "<aperturethroughput>"), at + "/aperturethroughput");
    expect_diagnostic(read, "<focusdistance> given without <aperturediameter>",
                      line_of(text, "<focusdistance>"), at + "/focusdistance");
    expect_diagnostic(read, "expected a number, got \"x\"", line_of(text, "<k1>"),
                      at + "/distortion/k1");
    // Only one problem for the unreadable focal length: it was given, so not "missing".
    EXPECT_EQ(count(read.diagnostics, "focallength"), 0u) << dump(read.diagnostics);
}

TEST(PlatformReader, NegativeAndZeroPropertiesRejected) {
    TempDir dir;
    const std::string text = with_instrument(
        "<instrument name=\"Cam\">\n<properties>\n<focallength>-5</focallength>\n"
        "<aperturediameter>0</aperturediameter>\n<aperturethroughput>0</aperturethroughput>\n"
        "</properties>\n</instrument>");
    const Read read = read_text(dir, text);
    const std::string at = std::string(kInstrumentPath) + "/properties";
    expect_diagnostic(read, "expected a number > 0, got \"-5\"", 7, at + "/focallength");
    expect_diagnostic(read, "expected a number > 0, got \"0\"", 8, at + "/aperturediameter");
    expect_diagnostic(read, "expected a number in (0, 1], got \"0\"", 9,
                      at + "/aperturethroughput");
    EXPECT_EQ(read.diagnostics.error_count(), 3u) << dump(read.diagnostics);
}

TEST(PlatformReader, InstrumentExtrasWarnNeverFail) {
    TempDir dir;
    const std::string text = with_instrument(
        "<instrument name=\"Cam\" type=\"generic\">\n"
        "<properties spatialunits=\"meters\"><focallength>50</focallength>"
        "<magnification>2</magnification></properties>\n"
        "<frame type=\"ascii\" enabled=\"true\"/>\n<options><maxbounces>3</maxbounces></options>\n"
        "<output/>\n<sparkle/>\n</instrument>");
    const Read read = read_text(dir, text);
    EXPECT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    expect_diagnostic(read, "<frame> is parsed but not used yet", 7,
                      std::string(kInstrumentPath) + "/frame", Severity::warning);
    expect_diagnostic(read, "<options> is parsed but not used yet", 8,
                      std::string(kInstrumentPath) + "/options", Severity::warning);
    expect_diagnostic(read, "<output> is parsed but not used yet", 9,
                      std::string(kInstrumentPath) + "/output", Severity::warning);
    expect_diagnostic(read, "<magnification> is parsed but not used yet", 6,
                      std::string(kInstrumentPath) + "/properties/magnification",
                      Severity::warning);
    expect_diagnostic(read, "spatialunits=\"meters\" ignored: focallength is read in mm", 6,
                      std::string(kInstrumentPath) + "/properties@spatialunits", Severity::warning);
    expect_diagnostic(read, "unknown element <sparkle> ignored", 10,
                      std::string(kInstrumentPath) + "/sparkle", Severity::warning);
    // The focal length stays in mm whatever spatialunits says.
    EXPECT_DOUBLE_EQ(*read.platform.attachments.at(0).instruments.at(0).properties.focal_length_m,
                     0.05);
}

// ---- focal planes ---------------------------------------------------------------------------

TEST(PlatformReader, FocalPlaneNeedsCaptureMethodAndDetectorArray) {
    TempDir dir;
    const Read read = read_text(dir, with_focal_plane("<truthcollection/>"));
    expect_diagnostic(read, "missing required element <capturemethod>", 7, kFocalPlanePath);
    expect_diagnostic(read, "missing required element <detectorarray>", 7, kFocalPlanePath);
}

TEST(PlatformReader, FocalPlaneEnabledMustBeBoolean) {
    TempDir dir;
    const std::string text = with_instrument(
        "<instrument name=\"Cam\"><properties><focallength>50</focallength></properties>\n"
        "<focalplane name=\"FP\" enabled=\"maybe\">\n" +
        std::string(kCapture) + kDetector + "</focalplane>\n</instrument>");
    const Read read = read_text(dir, text);
    expect_diagnostic(read, "expected a boolean (true, false, yes, no, 1 or 0), got \"maybe\"", 6,
                      std::string(kFocalPlanePath) + "@enabled");
}

TEST(PlatformReader, FocalPlaneExtrasAreNotUnknown) {
    TempDir dir;
    const Read read =
        read_text(dir, with_focal_plane(std::string(kCapture) + kDetector +
                                        "<psf><width>0.5</width></psf>\n<unobtainium/>"));
    EXPECT_FALSE(read.diagnostics.has_errors()) << dump(read.diagnostics);
    EXPECT_EQ(count(read.diagnostics, "unknown element <psf>", Severity::warning), 0u);
    EXPECT_EQ(count(read.diagnostics, "unknown element <unobtainium>", Severity::warning), 1u);
    const auto& capture =
        read.platform.attachments.at(0).instruments.at(0).focal_planes.at(0).capture_method;
    ASSERT_TRUE(capture.psf);
    EXPECT_DOUBLE_EQ(*capture.psf->width_px, 0.5);
}

TEST(PlatformReader, EveryErrorOfAFileIsReported) {
    TempDir dir;
    const std::string text = with_instrument(
        "<instrument name=\"Cam\" type=\"camera\"/>\n"
        "<mount name=\"M\" type=\"spinning\"/>\n"
        "<instrument name=\"Cam2\"><properties><focallength>0</focallength></properties>"
        "</instrument>");
    const Read read = read_text(dir, text);
    EXPECT_EQ(read.diagnostics.error_count(), 3u) << dump(read.diagnostics);
}

}  // namespace platform_reader_test
}  // namespace glint::test::plat
