// SPDX-License-Identifier: Apache-2.0
// Tests of the capture-method reader (lib/dirsig/src/capture_reader.cpp): every child of
// <capturemethod> field by field with its defaults, the extras written in <focalplane>, the
// focal-plane checks, and every bad input with its message, line and element path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "capture_test_util.h"

namespace glint::test {
namespace capture_reader_test {

using model::AreaUnits;
using model::CaptureMethodType;
using model::FluxUnits;
using model::ImageSchedule;
using model::ProcessingSchedule;

// ---- defaults and good values -----------------------------------------------------------

TEST(CaptureReader, MinimalCaptureHasEveryDefault) {
    const auto read = read_capture(
        "<capturemethod>\n"
        "<imagefile><basename>out</basename></imagefile>\n"
        "<spectralresponse>" +
        std::string(kBandpass) + kOneChannel + "</spectralresponse>\n</capturemethod>");
    ASSERT_TRUE(clean(read));
    const auto& c = read.capture;
    EXPECT_EQ(c.type, CaptureMethodType::simple);
    EXPECT_EQ(c.name, "");
    EXPECT_EQ(c.where.line, 1);
    EXPECT_EQ(c.where.element, "capturemethod");
    EXPECT_EQ(c.sample_strategy.type, "central");
    EXPECT_EQ(c.sample_strategy.hypersampling_multiplier, 1.0);
    EXPECT_EQ(c.image_file.basename, "out");
    EXPECT_EQ(c.image_file.extension, "img");
    EXPECT_EQ(c.image_file.schedule, ImageSchedule::simulation);
    EXPECT_EQ(c.image_file.datatype, 5);
    EXPECT_EQ(c.image_file.area_units, AreaUnits::cm2);
    EXPECT_EQ(c.image_file.flux_units, FluxUnits::watts);
    EXPECT_EQ(c.image_file.where.line, 2);
    EXPECT_FALSE(c.spatial_response.has_value());
    EXPECT_EQ(c.temporal_integration.time_s, 0.0);
    EXPECT_EQ(c.temporal_integration.samples, 1);
    EXPECT_FALSE(c.temporal_integration.tdi);
    EXPECT_FALSE(c.detector_model.has_value());
    EXPECT_FALSE(c.convergence.has_value());
    EXPECT_FALSE(c.psf.has_value());
    EXPECT_TRUE(c.active_area_image.empty());
    EXPECT_TRUE(c.processing.empty());
    ASSERT_EQ(c.spectral_response.channels.size(), 1u);
    EXPECT_FALSE(c.spectral_response.pattern.has_value());
}

TEST(CaptureReader, TypeAndName) {
    auto read = read_capture(capture_xml("", "", "type=\"RAW\" name=\" Raw one \""));
    EXPECT_EQ(read.capture.type, CaptureMethodType::raw);
    EXPECT_TRUE(clean(read));
    EXPECT_EQ(read.capture.name, "Raw one");
    // A lidar capture writes a BIN file: no spectral response is required, but its range
    // gate and its file's basename are; the extension defaults to bin.
    read = read_capture(
        "<capturemethod type=\"lidar\"><imagefile><basename>pulses</basename></imagefile>"
        "<signalgate><start>6e-6</start><stop>7.5e-6</stop>"
        "<binwidth>1e-9</binwidth><samplespertimebin>2</samplespertimebin></signalgate>"
        "</capturemethod>");
    EXPECT_EQ(read.capture.type, CaptureMethodType::lidar);
    // Several samples per bin: the one warning says the BIN layout glint writes is a reading.
    EXPECT_EQ(read.diagnostics.error_count(), 0u) << list_diagnostics(read.diagnostics);
    ASSERT_EQ(read.diagnostics.warning_count(), 1u) << list_diagnostics(read.diagnostics);
    EXPECT_EQ(read.diagnostics.items().at(0).message,
              "samplespertimebin 2: the BIN file holds 1 + bins x 2 values per pixel; published "
              "BIN readers disagree on this layout (docs/lidar-bin.md, \"Pixel order\")");
    EXPECT_EQ(read.capture.image_file.basename, "pulses");
    EXPECT_EQ(read.capture.image_file.extension, "bin");
    ASSERT_TRUE(read.capture.signal_gate);
    EXPECT_EQ(read.capture.signal_gate->start_s, 6e-6);
    EXPECT_EQ(read.capture.signal_gate->stop_s, 7.5e-6);
    EXPECT_EQ(read.capture.signal_gate->bin_count(), 1500u);
    EXPECT_EQ(read.capture.signal_gate->samples_per_bin, 2u);
}

struct GateCase {
    const char* name;
    const char* gate;
    const char* message;
    const char* element;  ///< where the error is (all on line 1)
};

class LidarGateErrors : public ::testing::TestWithParam<GateCase> {};

TEST_P(LidarGateErrors, OneErrorAtTheElement) {
    const GateCase& c = GetParam();
    const auto read = read_capture(std::string("<capturemethod type=\"lidar\"><imagefile>"
                                               "<basename>l</basename></imagefile>") +
                                   c.gate + "</capturemethod>");
    EXPECT_EQ(read.diagnostics.error_count(), 1u) << list_diagnostics(read.diagnostics);
    EXPECT_TRUE(has_error(read, c.message, "<capturemethod", c.element));
}

INSTANTIATE_TEST_SUITE_P(
    CaptureReader, LidarGateErrors,
    ::testing::Values(
        GateCase{"NoGate", "",
                 "a lidar capture needs a <signalgate> (the range gate: <start>, <stop> and "
                 "<binwidth> in s after the pulse)",
                 "capturemethod"},
        GateCase{"StopBeforeStart",
                 "<signalgate><start>7e-6</start><stop>6e-6</stop><binwidth>1e-9</binwidth>"
                 "</signalgate>",
                 "the gate stops at 6e-06 s, expected after its start (7e-06 s)",
                 "capturemethod/signalgate/stop"},
        GateCase{"ZeroBinWidth",
                 "<signalgate><start>6e-6</start><stop>7e-6</stop><binwidth>0</binwidth>"
                 "</signalgate>",
                 "expected a number > 0, got \"0\"", "capturemethod/signalgate/binwidth"},
        GateCase{"BinsNotWhole",
                 "<signalgate><start>0</start><stop>1e-6</stop><binwidth>3e-9</binwidth>"
                 "</signalgate>",
                 "the 1e-06 s gate holds 333.3333333333333 bins of 3e-09 s, expected a whole "
                 "number up to 10^7",
                 "capturemethod/signalgate/binwidth"}),
    [](const ::testing::TestParamInfo<GateCase>& param_info) {
        return std::string(param_info.param.name);
    });

TEST(CaptureReader, RawNeedsNoChannels) {
    const auto read = read_capture(capture_xml("", kBandpass, "type=\"raw\""));
    EXPECT_TRUE(clean(read));
    EXPECT_TRUE(read.capture.spectral_response.channels.empty());
    EXPECT_EQ(read.capture.spectral_response.bandpass.count, 31u);
}

TEST(CaptureReader, RawRefusesTdi) {
    // A raw capture is for an external detection model: TDI accumulation, which glint applies
    // in its detection, needs a simple capture (a pattern: SpectralReaderBadInput).
    const std::string raw = "type=\"raw\" name=\"R\"";
    const auto read = read_focal_plane(
        "<focalplane name=\"F\">\n" +
        capture_xml("<temporalintegration tdi=\"true\"><time>0.01</time></temporalintegration>",
                    kBandpass, raw) +
        "</focalplane>");
    EXPECT_TRUE(has_error(read, "tdi=\"true\" needs capturemethod type simple",
                          "<temporalintegration",
                          "focalplane[F]/capturemethod[R]/temporalintegration"));
}

TEST(CaptureReader, SampleStrategy) {
    const auto read =
        read_capture(capture_xml("<samplestrategy type=\"central\"><hypersamplingmultiplier>50000"
                                 "</hypersamplingmultiplier></samplestrategy>"));
    EXPECT_TRUE(clean(read));
    EXPECT_EQ(read.capture.sample_strategy.type, "central");
    EXPECT_EQ(read.capture.sample_strategy.hypersampling_multiplier, 50000.0);
}

TEST(CaptureReader, ImageFileEveryField) {
    const auto read = read_capture(
        "<capturemethod>\n"
        "<imagefile areaunits=\"m2\" fluxunits=\"photonspersecond\">\n"
        "<basename> frames </basename><extension>dat</extension>\n"
        "<schedule>capture</schedule><datatype>12</datatype></imagefile>\n"
        "<spectralresponse>" +
        std::string(kBandpass) + kOneChannel + "</spectralresponse>\n</capturemethod>");
    ASSERT_TRUE(clean(read));
    const auto& f = read.capture.image_file;
    EXPECT_EQ(f.basename, "frames");
    EXPECT_EQ(f.extension, "dat");
    EXPECT_EQ(f.schedule, ImageSchedule::capture);
    EXPECT_EQ(f.datatype, 12);
    EXPECT_EQ(f.area_units, AreaUnits::m2);
    EXPECT_EQ(f.flux_units, FluxUnits::photons_per_second);
}

TEST(CaptureReader, EveryUnitAndScheduleName) {
    const std::pair<const char*, FluxUnits> fluxes[] = {
        {"watts", FluxUnits::watts},
        {"milliwatts", FluxUnits::milliwatts},
        {"microwatts", FluxUnits::microwatts},
        {"photonspersecond", FluxUnits::photons_per_second},
        {"ElectronsPerSecond", FluxUnits::electrons_per_second},
    };
    for (const auto& [name, flux] : fluxes) {
        const auto xml = "<imagefile fluxunits=\"" + std::string(name) +
                         "\" areaunits=\"CM2\"><basename>x</basename></imagefile>";
        const auto doc = io::XmlDocument::parse(xml, kCaptureFile);
        Diagnostics diagnostics;
        const auto file = dirsig::detail::read_image_file(doc.root(), true, diagnostics);
        EXPECT_EQ(diagnostics.items().size(), 0u) << name;
        EXPECT_EQ(file.flux_units, flux) << name;
        EXPECT_EQ(file.area_units, AreaUnits::cm2);
    }
    const std::pair<const char*, ImageSchedule> schedules[] = {
        {"simulation", ImageSchedule::simulation},
        {"task", ImageSchedule::task},
        {"capture", ImageSchedule::capture},
    };
    for (const auto& [name, schedule] : schedules) {
        const auto xml = "<imagefile><basename>x</basename><schedule>" + std::string(name) +
                         "</schedule></imagefile>";
        const auto doc = io::XmlDocument::parse(xml, kCaptureFile);
        Diagnostics diagnostics;
        const auto file = dirsig::detail::read_image_file(doc.root(), true, diagnostics);
        EXPECT_FALSE(diagnostics.has_errors()) << name;
        EXPECT_EQ(file.schedule, schedule) << name;
    }
    for (const int datatype : {1, 2, 3, 4, 5, 12, 13, 14, 15}) {
        const auto xml = "<imagefile><basename>x</basename><datatype>" + std::to_string(datatype) +
                         "</datatype></imagefile>";
        const auto doc = io::XmlDocument::parse(xml, kCaptureFile);
        Diagnostics diagnostics;
        EXPECT_EQ(dirsig::detail::read_image_file(doc.root(), true, diagnostics).datatype,
                  datatype);
        EXPECT_FALSE(diagnostics.has_errors());
    }
}

TEST(CaptureReader, TruthImageFileWarnsAboutRadiometricUnits) {
    const std::string xml =
        "<imagefile areaunits=\"m2\">\n<basename>truth</basename><schedule>task</schedule>"
        "</imagefile>";
    const auto doc = io::XmlDocument::parse(xml, kCaptureFile);
    CaptureRead read;
    read.xml = xml;
    const auto file = dirsig::detail::read_image_file(doc.root(), false, read.diagnostics);
    EXPECT_EQ(file.basename, "truth");
    EXPECT_EQ(file.schedule, ImageSchedule::task);
    EXPECT_EQ(file.area_units, AreaUnits::cm2);
    EXPECT_EQ(read.diagnostics.error_count(), 0u);
    EXPECT_TRUE(has_warning(
        read, "areaunits does not apply to a truth image or a lidar BIN file and is ignored",
        "<imagefile", "imagefile@areaunits"));
}

TEST(CaptureReader, SpatialResponseIsParsedAndWarnedAboutOnce) {
    const auto read = read_capture(
        capture_xml("<spatialresponse spatialsampling=\"subsamples\" spectralunits=\"microns\" "
                    "xsubelements=\"2\" ysubelements=\"3\">\n"
                    "<entry type=\"uniform\"><spectralpoint>0.4</spectralpoint><xwidth>1</xwidth>"
                    "<ywidth>0.5</ywidth><totalweight>1</totalweight></entry>\n"
                    "<entry type=\"uniform\"><spectralpoint>0.6</spectralpoint></entry>\n"
                    "</spatialresponse>"));
    EXPECT_EQ(read.diagnostics.error_count(), 0u);
    ASSERT_EQ(read.diagnostics.warning_count(), 1u);
    EXPECT_TRUE(has_warning(read,
                            "<spatialresponse> is a DIRSIG4 setting; glint samples pixel areas "
                            "as DIRSIG5 does and ignores it",
                            "<spatialresponse", "capturemethod[C]/spatialresponse"));
    ASSERT_TRUE(read.capture.spatial_response.has_value());
    const auto& s = *read.capture.spatial_response;
    EXPECT_EQ(s.spatial_sampling, "subsamples");
    EXPECT_EQ(s.spectral_units, "microns");
    EXPECT_EQ(s.x_sub_elements, 2);
    EXPECT_EQ(s.y_sub_elements, 3);
    ASSERT_EQ(s.entries.size(), 2u);
    EXPECT_EQ(s.entries[0].type, "uniform");
    EXPECT_EQ(s.entries[0].spectral_point, 0.4);
    EXPECT_EQ(s.entries[0].y_width, 0.5);
    EXPECT_EQ(s.entries[1].spectral_point, 0.6);
    EXPECT_EQ(s.entries[1].x_width, 1.0);
    EXPECT_EQ(s.entries[1].total_weight, 1.0);
}

TEST(CaptureReader, TemporalIntegration) {
    auto read = read_capture(
        capture_xml("<temporalintegration tdi=\"true\"><time>2.0e-05</time><samples>1</samples>"
                    "</temporalintegration>"));
    EXPECT_TRUE(clean(read));
    EXPECT_TRUE(read.capture.temporal_integration.tdi);
    EXPECT_EQ(read.capture.temporal_integration.time_s, 2.0e-5);
    EXPECT_EQ(read.capture.temporal_integration.samples, 1);

    read = read_capture(
        capture_xml("<temporalintegration>\n<time>0.005</time>\n<samples>10</samples>\n"
                    "</temporalintegration>"));
    EXPECT_EQ(read.diagnostics.error_count(), 0u);
    EXPECT_FALSE(read.capture.temporal_integration.tdi);
    EXPECT_EQ(read.capture.temporal_integration.samples, 10);
    EXPECT_TRUE(has_warning(read, "samples 10: DIRSIG5-style sampling ignores the DIRSIG4",
                            "<samples>", "capturemethod[C]/temporalintegration/samples"));
}

TEST(CaptureReader, DetectorModel) {
    auto read = read_capture(capture_xml(
        "<detectormodel><quantumefficiency>0.80</quantumefficiency><readnoise>60</readnoise>"
        "<darkcurrentdensity>1e-05</darkcurrentdensity><minelectrons>0</minelectrons>"
        "<maxelectrons>100e03</maxelectrons><bitdepth>12</bitdepth></detectormodel>"));
    EXPECT_TRUE(clean(read));
    ASSERT_TRUE(read.capture.detector_model.has_value());
    const auto& d = *read.capture.detector_model;
    EXPECT_EQ(d.quantum_efficiency, 0.8);
    EXPECT_EQ(d.read_noise_e, 60.0);
    EXPECT_EQ(d.dark_current_density_a_per_m2, 1e-5);
    EXPECT_EQ(d.min_electrons, 0.0);
    EXPECT_EQ(d.max_electrons, 1e5);
    EXPECT_EQ(d.bit_depth, 12);

    // readnoise and darkcurrentdensity default to 0.
    read = read_capture(capture_xml(
        "<detectormodel><quantumefficiency>1</quantumefficiency><minelectrons>10"
        "</minelectrons><maxelectrons>20</maxelectrons><bitdepth>1</bitdepth></detectormodel>"));
    EXPECT_TRUE(clean(read));
    EXPECT_EQ(read.capture.detector_model->read_noise_e, 0.0);
    EXPECT_EQ(read.capture.detector_model->dark_current_density_a_per_m2, 0.0);
    EXPECT_EQ(read.capture.detector_model->bit_depth, 1);
}

TEST(CaptureReader, ConvergencePsfActiveArea) {
    const auto read = read_capture(
        capture_xml("<convergence><minimumsamples>250</minimumsamples><maximumsamples>750"
                    "</maximumsamples><threshold>1.0e-08</threshold></convergence>\n"
                    "<psf><width>3.8</width></psf>\n"
                    "<activearea><image>masks/pixel_mask.png</image></activearea>"));
    EXPECT_TRUE(clean(read));
    ASSERT_TRUE(read.capture.convergence.has_value());
    EXPECT_EQ(read.capture.convergence->minimum_samples, 250);
    EXPECT_EQ(read.capture.convergence->maximum_samples, 750);
    EXPECT_EQ(read.capture.convergence->threshold, 1e-8);
    ASSERT_TRUE(read.capture.psf.has_value());
    EXPECT_EQ(read.capture.psf->width_px, 3.8);
    EXPECT_TRUE(read.capture.psf->image.empty());
    EXPECT_EQ(read.capture.active_area_image.text, "masks/pixel_mask.png");
    EXPECT_EQ(read.capture.active_area_image.resolved,
              std::filesystem::path("/data/platforms/masks/pixel_mask.png"));
}

TEST(CaptureReader, PsfImageAndScale) {
    const auto read =
        read_capture(capture_xml("<psf><image>../psf/airy.png</image><scale>10</scale></psf>"));
    EXPECT_TRUE(clean(read));
    ASSERT_TRUE(read.capture.psf.has_value());
    EXPECT_FALSE(read.capture.psf->width_px.has_value());
    EXPECT_EQ(read.capture.psf->image.text, "../psf/airy.png");
    EXPECT_EQ(read.capture.psf->image.resolved, std::filesystem::path("/data/psf/airy.png"));
    EXPECT_EQ(read.capture.psf->scale_px, 10.0);
}

TEST(CaptureReader, ProcessingTasksEverySchedule) {
    const std::pair<const char*, ProcessingSchedule> schedules[] = {
        {"collection_started", ProcessingSchedule::collection_started},
        {"task_started", ProcessingSchedule::task_started},
        {"capture_started", ProcessingSchedule::capture_started},
        {"capture_completed", ProcessingSchedule::capture_completed},
        {"task_completed", ProcessingSchedule::task_completed},
        {"collection_completed", ProcessingSchedule::collection_completed},
    };
    std::string tasks = "<processing>\n";
    for (const auto& [name, schedule] : schedules) {
        tasks += "<task schedule=\"" + std::string(name) + "\"><program>p_" + name +
                 "</program></task>\n";
    }
    tasks +=
        "<task schedule=\"capture_completed\"><message>Running demosaic algorithm</message>"
        "<program>demosaic</program><argument>--pattern=truesense</argument>"
        "<argument>--input_filename=$$IMG_BASENAME$$.img</argument>"
        "<removefile>true</removefile></task>\n</processing>";
    const auto read = read_capture(capture_xml(tasks));
    // glint-render runs them (glint/process/processing_runner.h): nothing to say.
    EXPECT_EQ(read.diagnostics.error_count(), 0u) << list_diagnostics(read.diagnostics);
    EXPECT_EQ(read.diagnostics.warning_count(), 0u) << list_diagnostics(read.diagnostics);
    const auto& p = read.capture.processing;
    ASSERT_EQ(p.size(), 7u);
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(p[i].schedule, schedules[i].second);
        EXPECT_EQ(p[i].program, std::string("p_") + schedules[i].first);
        EXPECT_EQ(p[i].message, "");
        EXPECT_TRUE(p[i].arguments.empty());
        EXPECT_FALSE(p[i].remove_file);
    }
    EXPECT_EQ(p[6].message, "Running demosaic algorithm");
    EXPECT_EQ(p[6].program, "demosaic");
    EXPECT_EQ(p[6].arguments, (std::vector<std::string>{"--pattern=truesense",
                                                        "--input_filename=$$IMG_BASENAME$$.img"}));
    EXPECT_TRUE(p[6].remove_file);
    EXPECT_EQ(p[6].where.line, line_of(read.xml, "<task schedule=\"capture_completed\"><message"));
}

TEST(CaptureReader, ExtrasDirectlyInTheFocalPlane) {
    const auto read = read_focal_plane(
        "<focalplane name=\"F\">\n" + capture_xml("") +
        "<psf><image>airy.png</image><scale>10</scale></psf>\n"
        "<activearea><image>mask.png</image></activearea>\n"
        "<convergence><minimumsamples>10</minimumsamples><maximumsamples>10</maximumsamples>"
        "<threshold>0</threshold></convergence>\n"
        "<processing><task schedule=\"task_started\"><program>logger</program></task>"
        "</processing>\n"
        "<detectormodel><quantumefficiency>0.5</quantumefficiency><minelectrons>0"
        "</minelectrons><maxelectrons>1000</maxelectrons><bitdepth>10</bitdepth>"
        "</detectormodel>\n</focalplane>");
    EXPECT_EQ(read.diagnostics.error_count(), 0u) << list_diagnostics(read.diagnostics);
    EXPECT_EQ(read.diagnostics.warning_count(), 0u) << list_diagnostics(read.diagnostics);
    const auto& c = read.capture;
    ASSERT_TRUE(c.psf.has_value());
    EXPECT_EQ(c.psf->image.resolved, std::filesystem::path("/data/platforms/airy.png"));
    EXPECT_EQ(c.active_area_image.resolved, std::filesystem::path("/data/platforms/mask.png"));
    ASSERT_TRUE(c.convergence.has_value());
    EXPECT_EQ(c.convergence->maximum_samples, 10);
    ASSERT_EQ(c.processing.size(), 1u);
    EXPECT_EQ(c.processing[0].schedule, ProcessingSchedule::task_started);
    ASSERT_TRUE(c.detector_model.has_value());
    EXPECT_EQ(c.detector_model->bit_depth, 10);
    EXPECT_EQ(c.detector_model->where.element, "focalplane[F]/detectormodel");
}

TEST(CaptureReader, TdiFocalPlaneIsValid) {
    const auto read =
        read_focal_plane("<focalplane name=\"F\">\n" +
                             capture_xml("<temporalintegration tdi=\"true\"><time>2e-5</time>"
                                         "</temporalintegration>") +
                             "</focalplane>",
                         12);
    EXPECT_TRUE(clean(read));
    EXPECT_TRUE(read.capture.temporal_integration.tdi);
}

// ---- bad input: message, line and element path --------------------------------------------

TEST(CaptureReaderErrors, UnknownCaptureType) {
    const auto read = read_capture(capture_xml("", "", "type=\"fancy\""));
    EXPECT_TRUE(has_error(read, "expected one of simple, raw, lidar, got \"fancy\"",
                          "<capturemethod", "capturemethod@type"));
}

TEST(CaptureReaderErrors, UnknownChildIsOneWarningEach) {
    const auto read = read_capture(capture_xml("<gainresponse/>\n<outputmethod/>"));
    EXPECT_EQ(read.diagnostics.error_count(), 0u);
    EXPECT_EQ(read.diagnostics.warning_count(), 2u);
    EXPECT_TRUE(has_warning(read, "unknown element <gainresponse> ignored", "<gainresponse",
                            "capturemethod[C]/gainresponse"));
    EXPECT_TRUE(has_warning(read, "unknown element <outputmethod> ignored", "<outputmethod",
                            "capturemethod[C]/outputmethod"));
}

TEST(CaptureReaderErrors, RepeatedChild) {
    const auto read =
        read_capture(capture_xml("<psf><width>1</width></psf>\n<psf><width>2</width></psf>"));
    EXPECT_TRUE(has_error(read, "<psf> given again (first at line 7), expected at most one",
                          "<psf><width>2", "capturemethod[C]/psf"));
    EXPECT_EQ(read.capture.psf->width_px, 1.0);
}

TEST(CaptureReaderErrors, MissingImageFileAndSpectralResponse) {
    const auto read = read_capture("<capturemethod type=\"simple\">\n</capturemethod>");
    EXPECT_TRUE(
        has_error(read, "missing required element <imagefile>", "<capturemethod", "capturemethod"));
    EXPECT_TRUE(has_error(read, "missing required element <spectralresponse>", "<capturemethod",
                          "capturemethod"));
}

TEST(CaptureReaderErrors, ImageFileProblems) {
    const auto read = read_capture(
        "<capturemethod>\n"
        "<imagefile areaunits=\"mm2\" fluxunits=\"lumens\">\n"
        "<basename></basename>\n"
        "<extension/>\n"
        "<schedule>weekly</schedule>\n"
        "<datatype>7</datatype>\n"
        "</imagefile>\n"
        "<spectralresponse>" +
        std::string(kBandpass) + kOneChannel + "</spectralresponse>\n</capturemethod>");
    EXPECT_TRUE(has_error(read, "expected one of cm2, m2, got \"mm2\"", "<imagefile",
                          "capturemethod/imagefile@areaunits"));
    EXPECT_TRUE(has_error(read,
                          "expected one of watts, milliwatts, microwatts, photonspersecond, "
                          "electronspersecond, got \"lumens\"",
                          "<imagefile", "capturemethod/imagefile@fluxunits"));
    EXPECT_TRUE(has_error(read, "basename is empty, expected a file name", "<basename>",
                          "capturemethod/imagefile/basename"));
    EXPECT_TRUE(has_error(read, "extension is empty, expected a file extension", "<extension/>",
                          "capturemethod/imagefile/extension"));
    EXPECT_TRUE(has_error(read, "expected one of simulation, task, capture, got \"weekly\"",
                          "<schedule>", "capturemethod/imagefile/schedule"));
    EXPECT_TRUE(has_error(read,
                          "datatype 7 is not a supported ENVI data type, expected 1, 2, 3, 4, "
                          "5, 12, 13, 14 or 15",
                          "<datatype>", "capturemethod/imagefile/datatype"));
    EXPECT_EQ(read.diagnostics.error_count(), 6u);  // every problem, not just the first
    EXPECT_EQ(read.capture.image_file.datatype, 5);
}

TEST(CaptureReaderErrors, MissingBasename) {
    const auto read = read_capture(
        "<capturemethod>\n<imagefile><extension>img</extension></imagefile>\n"
        "<spectralresponse>" +
        std::string(kBandpass) + kOneChannel + "</spectralresponse>\n</capturemethod>");
    EXPECT_TRUE(has_error(read, "missing required element <basename>", "<imagefile>",
                          "capturemethod/imagefile"));
}

TEST(CaptureReaderErrors, OutputNamesThatCouldLeaveTheOutputFolder) {
    // Each of these would put the image outside --output_folder (or give it an
    // unprintable name): refused where it is written, for radiometric and truth images.
    const std::pair<const char*, const char*> cases[] = {
        {"<basename>../../escaped</basename>", "<basename> \"../../escaped\" contains '/'"},
        {"<basename>a\\b</basename>", "<basename> \"a\\\\b\" contains '\\'"},
        {"<basename>..</basename>", "<basename> \"..\" contains '..'"},
        {"<basename>x&#9;y</basename>", "<basename> \"x\\ty\" contains the control character 0x09"},
        {"<basename>x</basename><extension>img/../../x</extension>",
         "<extension> \"img/../../x\" contains '/'"},
    };
    for (const bool radiometric : {true, false}) {
        for (const auto& [children, message] : cases) {
            const std::string xml = "<imagefile>\n" + std::string(children) + "\n</imagefile>";
            const auto doc = io::XmlDocument::parse(xml, kCaptureFile);
            CaptureRead read;
            read.xml = xml;
            const auto file =
                dirsig::detail::read_image_file(doc.root(), radiometric, read.diagnostics);
            EXPECT_EQ(read.diagnostics.error_count(), 1u) << children;
            ASSERT_FALSE(read.diagnostics.items().empty()) << children;
            const auto& item = read.diagnostics.items().front();
            EXPECT_NE(item.message.find(message), std::string::npos) << item.message;
            EXPECT_EQ(item.where.line, 2) << children;
            EXPECT_EQ(item.where.file, kCaptureFile);
            EXPECT_EQ(file.basename.find('/'), std::string::npos);
            EXPECT_EQ(file.extension.find('/'), std::string::npos);
        }
    }
}

TEST(CaptureReaderErrors, HypersamplingBelowOne) {
    const auto read = read_capture(
        capture_xml("<samplestrategy><hypersamplingmultiplier>0.5</hypersamplingmultiplier>"
                    "</samplestrategy>"));
    EXPECT_TRUE(has_error(read, "got \"0.5\"", "<samplestrategy",
                          "capturemethod[C]/samplestrategy/hypersamplingmultiplier"));
}

TEST(CaptureReaderErrors, TemporalIntegrationValues) {
    const auto read = read_capture(
        capture_xml("<temporalintegration tdi=\"maybe\">\n<time>-1</time>\n<samples>0</samples>\n"
                    "</temporalintegration>"));
    EXPECT_TRUE(has_error(read, "expected a boolean (true, false, yes, no, 1 or 0), got \"maybe\"",
                          "<temporalintegration", "capturemethod[C]/temporalintegration@tdi"));
    EXPECT_TRUE(has_error(read, "expected a number >= 0, got \"-1\"", "<time>",
                          "capturemethod[C]/temporalintegration/time"));
    EXPECT_TRUE(
        has_error(read, "got \"0\"", "<samples>", "capturemethod[C]/temporalintegration/samples"));
}

TEST(CaptureReaderErrors, DetectorModelValues) {
    const auto read =
        read_capture(capture_xml("<detectormodel>\n"
                                 "<quantumefficiency>1.5</quantumefficiency>\n"
                                 "<readnoise>abc</readnoise>\n"
                                 "<darkcurrentdensity>-1e-5</darkcurrentdensity>\n"
                                 "<minelectrons>1000</minelectrons>\n"
                                 "<maxelectrons>100</maxelectrons>\n"
                                 "<bitdepth>0</bitdepth>\n"
                                 "</detectormodel>"));
    const std::string at = "capturemethod[C]/detectormodel/";
    EXPECT_TRUE(has_error(read, "expected a number in [0, 1], got \"1.5\"", "<quantumefficiency>",
                          at + "quantumefficiency"));
    EXPECT_TRUE(
        has_error(read, "expected a number >= 0, got \"abc\"", "<readnoise>", at + "readnoise"));
    EXPECT_TRUE(has_error(read, "expected a number >= 0, got \"-1e-5\"", "<darkcurrentdensity>",
                          at + "darkcurrentdensity"));
    EXPECT_TRUE(has_error(read, "minelectrons (1000) must be less than maxelectrons (100)",
                          "<maxelectrons>", at + "maxelectrons"));
    EXPECT_TRUE(has_error(read, "expected an integer in [1, 32], got \"0\"", "<bitdepth>",
                          at + "bitdepth"));
    EXPECT_EQ(read.diagnostics.error_count(), 5u);
}

TEST(CaptureReaderErrors, BitDepth33AndEqualElectrons) {
    const auto read =
        read_capture(capture_xml("<detectormodel><quantumefficiency>1</quantumefficiency>\n"
                                 "<minelectrons>5</minelectrons><maxelectrons>5</maxelectrons>\n"
                                 "<bitdepth>33</bitdepth></detectormodel>"));
    EXPECT_TRUE(has_error(read, "expected an integer in [1, 32], got \"33\"", "<bitdepth>",
                          "capturemethod[C]/detectormodel/bitdepth"));
    EXPECT_TRUE(has_error(read, "minelectrons (5) must be less than maxelectrons (5)",
                          "<maxelectrons>", "capturemethod[C]/detectormodel/maxelectrons"));
}

TEST(CaptureReaderErrors, DetectorModelMissingRequired) {
    const auto read = read_capture(capture_xml("<detectormodel>\n</detectormodel>"));
    for (const char* name : {"quantumefficiency", "minelectrons", "maxelectrons", "bitdepth"}) {
        EXPECT_TRUE(has_error(read, "missing required element <" + std::string(name) + ">",
                              "<detectormodel>", "capturemethod[C]/detectormodel"));
    }
}

TEST(CaptureReaderErrors, ConvergenceValues) {
    const auto read = read_capture(capture_xml(
        "<convergence>\n<minimumsamples>750</minimumsamples>\n"
        "<maximumsamples>250</maximumsamples>\n<threshold>-1</threshold>\n</convergence>"));
    EXPECT_TRUE(has_error(read,
                          "maximumsamples (250) is below minimumsamples (750), expected "
                          "maximumsamples >= minimumsamples",
                          "<maximumsamples>", "capturemethod[C]/convergence/maximumsamples"));
    EXPECT_TRUE(has_error(read, "expected a number >= 0, got \"-1\"", "<threshold>",
                          "capturemethod[C]/convergence/threshold"));
    const auto zero = read_capture(capture_xml(
        "<convergence><minimumsamples>0</minimumsamples><maximumsamples>1</maximumsamples>"
        "<threshold>0</threshold></convergence>"));
    EXPECT_TRUE(has_error(zero, "got \"0\"", "<convergence>",
                          "capturemethod[C]/convergence/minimumsamples"));
}

TEST(CaptureReaderErrors, PsfWidthAndImage) {
    auto read =
        read_capture(capture_xml("<psf>\n<width>3.8</width>\n<image>airy.png</image>\n</psf>"));
    EXPECT_TRUE(has_error(read, "both <width> and <image>/<scale> given, expected either <width>",
                          "<psf>", "capturemethod[C]/psf"));
    read = read_capture(capture_xml("<psf>\n</psf>"));
    EXPECT_TRUE(
        has_error(read, "neither <width> nor <image> given", "<psf>", "capturemethod[C]/psf"));
    read = read_capture(capture_xml("<psf>\n<image>airy.png</image>\n</psf>"));
    EXPECT_TRUE(
        has_error(read, "missing required element <scale>", "<psf>", "capturemethod[C]/psf"));
    read = read_capture(capture_xml("<psf>\n<scale>10</scale>\n</psf>"));
    EXPECT_TRUE(
        has_error(read, "missing required element <image>", "<psf>", "capturemethod[C]/psf"));
    read = read_capture(capture_xml("<psf>\n<width>0</width>\n</psf>"));
    EXPECT_TRUE(has_error(read, "expected a number > 0, got \"0\"", "<width>0</width>",
                          "capturemethod[C]/psf/width"));
    read = read_capture(capture_xml("<psf>\n<image>a.png</image>\n<scale>-2</scale>\n</psf>"));
    EXPECT_TRUE(has_error(read, "expected a number > 0, got \"-2\"", "<scale>",
                          "capturemethod[C]/psf/scale"));
}

TEST(CaptureReaderErrors, ActiveAreaWithoutImage) {
    auto read = read_capture(capture_xml("<activearea>\n</activearea>"));
    EXPECT_TRUE(has_error(read, "missing required element <image>", "<activearea>",
                          "capturemethod[C]/activearea"));
    read = read_capture(capture_xml("<activearea>\n<image> </image>\n</activearea>"));
    EXPECT_TRUE(has_error(read, "image is empty, expected a file name", "<image>",
                          "capturemethod[C]/activearea/image"));
}

TEST(CaptureReaderErrors, ProcessingTasks) {
    const auto read = read_capture(
        capture_xml("<processing>\n"
                    "<task schedule=\"capture_ended\"><program>a</program></task>\n"
                    "<task><program>b</program></task>\n"
                    "<task schedule=\"task_started\"><message>no program</message></task>\n"
                    "<task schedule=\"task_started\"><program> </program></task>\n"
                    "<task schedule=\"capture_completed\"><program>c</program>\n"
                    "<argument>--out file.img</argument>\n"
                    "<removefile>sometimes</removefile></task>\n"
                    "</processing>"));
    const std::string at = "capturemethod[C]/processing/task";
    EXPECT_TRUE(has_error(read,
                          "expected one of collection_started, task_started, capture_started, "
                          "capture_completed, task_completed, collection_completed, got "
                          "\"capture_ended\"",
                          "capture_ended", at + "@schedule"));
    EXPECT_TRUE(has_error(read, "missing required attribute schedule", "<task><program>b", at));
    EXPECT_TRUE(has_error(read, "missing required element <program>", "no program", at));
    EXPECT_TRUE(has_error(read, "program is empty, expected the name or path of a program",
                          "<program> </program>", at + "/program"));
    EXPECT_TRUE(has_error(read,
                          "argument '--out file.img' contains whitespace, expected a single "
                          "argument without whitespace",
                          "<argument>", at + "/argument"));
    EXPECT_TRUE(has_error(read, "expected a boolean", "<removefile>", at + "/removefile"));
    EXPECT_EQ(read.diagnostics.error_count(), 6u);
}

TEST(CaptureReaderErrors, ExtraGivenInBothPlaces) {
    const auto read = read_focal_plane(
        "<focalplane name=\"F\">\n" +
        capture_xml("<psf><width>1</width></psf>\n"
                    "<convergence><minimumsamples>1</minimumsamples><maximumsamples>2"
                    "</maximumsamples><threshold>0</threshold></convergence>") +
        "<psf><width>2</width></psf>\n"
        "<convergence><minimumsamples>1</minimumsamples><maximumsamples>2</maximumsamples>"
        "<threshold>0</threshold></convergence>\n"
        "</focalplane>");
    EXPECT_TRUE(has_error(read,
                          "<psf> is given both in <capturemethod> (line 8) and in "
                          "<focalplane>, expected one of the two",
                          "<psf><width>2", "focalplane[F]/psf"));
    EXPECT_TRUE(has_error(read, "<convergence> is given both in <capturemethod> (line 9)",
                          "<convergence><minimumsamples>1</minimumsamples><maximumsamples>2"
                          "</maximumsamples><threshold>0</threshold></convergence>\n</f",
                          "focalplane[F]/convergence"));
    EXPECT_EQ(read.capture.psf->width_px, 1.0);
}

TEST(CaptureReaderErrors, TdiNeedsTimeAndStages) {
    auto read = read_focal_plane(
        "<focalplane name=\"F\">\n" +
            capture_xml("<temporalintegration tdi=\"true\">\n</temporalintegration>") +
            "</focalplane>",
        1);
    EXPECT_TRUE(has_error(read, "tdi=\"true\" needs an integration time, expected <time> > 0",
                          "<temporalintegration",
                          "focalplane[F]/capturemethod[C]/"
                          "temporalintegration"));
    EXPECT_TRUE(has_error(read,
                          "tdi=\"true\" uses the array's rows as TDI stages, expected "
                          "<yelementcount> > 1 in <detectorarray> (it is 1)",
                          "<temporalintegration",
                          "focalplane[F]/capturemethod[C]/temporalintegration"));
}

TEST(CaptureReaderErrors, DetectorModelNeedsSimpleCapture) {
    const auto read = read_focal_plane(
        "<focalplane name=\"F\">\n" +
        capture_xml("<detectormodel><quantumefficiency>1</quantumefficiency><minelectrons>0"
                    "</minelectrons><maxelectrons>10</maxelectrons><bitdepth>8</bitdepth>"
                    "</detectormodel>",
                    kBandpass, "type=\"raw\" name=\"C\"") +
        "</focalplane>");
    EXPECT_TRUE(has_error(read,
                          "the detector model needs capturemethod type simple, expected no "
                          "<detectormodel> in a raw capture",
                          "<detectormodel>", "focalplane[F]/capturemethod[C]/detectormodel"));
}

TEST(CaptureReaderErrors, DetectorModelIgnoresUnits) {
    const auto read = read_focal_plane(
        "<focalplane name=\"F\">\n"
        "<capturemethod name=\"C\">\n"
        "<imagefile fluxunits=\"milliwatts\"><basename>x</basename></imagefile>\n"
        "<spectralresponse>" +
        std::string(kBandpass) + kOneChannel +
        "</spectralresponse>\n"
        "<detectormodel><quantumefficiency>1</quantumefficiency><minelectrons>0"
        "</minelectrons><maxelectrons>10</maxelectrons><bitdepth>8</bitdepth>"
        "</detectormodel>\n</capturemethod>\n</focalplane>");
    EXPECT_EQ(read.diagnostics.error_count(), 0u);
    EXPECT_TRUE(has_warning(read, "areaunits and fluxunits are ignored when the detector model",
                            "<imagefile", "focalplane[F]/capturemethod[C]/imagefile"));
}

// ---- the capture_full.platform fixture through dirsig::read_platform -----------------------

std::string fixture_text(const std::string& name) {
    std::ifstream in(std::filesystem::path(GLINT_TEST_DATA_DIR) / "platform" / name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(CaptureFullPlatform, EveryChildFieldByField) {
    const auto read = read_platform_fixture("capture_full.platform");
    const auto dir = std::filesystem::path(GLINT_TEST_DATA_DIR) / "platform";
    EXPECT_EQ(read.diagnostics.error_count(), 0u) << list_diagnostics(read.diagnostics);
    // The one warning: the DIRSIG4 spatial response is ignored (the two <processing> blocks,
    // Bayer's and TrueSense's, are run by glint-render).
    ASSERT_EQ(read.diagnostics.warning_count(), 1u) << list_diagnostics(read.diagnostics);
    const auto& warning = read.diagnostics.items().front();
    EXPECT_EQ(warning.where.line,
              line_of(fixture_text("capture_full.platform"), "<spatialresponse"));
    EXPECT_EQ(warning.where.element,
              "platform/attachment/mount[Belly]/attachment/instrument[Camera]/"
              "focalplane[Bayer]/capturemethod[Simple]/spatialresponse");

    const auto planes = focal_planes(read.platform);
    ASSERT_EQ(planes.size(), 4u);

    // Bayer: sample strategy, image units, CFA, spatial response, extras in the capture.
    const auto& bayer = planes[0]->capture_method;
    EXPECT_EQ(planes[0]->name, "Bayer");
    EXPECT_EQ(bayer.type, CaptureMethodType::simple);
    EXPECT_EQ(bayer.name, "Simple");
    EXPECT_EQ(bayer.sample_strategy.hypersampling_multiplier, 100.0);
    EXPECT_EQ(bayer.image_file.basename, "bayer");
    EXPECT_EQ(bayer.image_file.extension, "dat");
    EXPECT_EQ(bayer.image_file.schedule, ImageSchedule::capture);
    EXPECT_EQ(bayer.image_file.datatype, 12);
    EXPECT_EQ(bayer.image_file.area_units, AreaUnits::m2);
    EXPECT_EQ(bayer.image_file.flux_units, FluxUnits::photons_per_second);
    const auto& response = bayer.spectral_response;
    EXPECT_EQ(response.bandpass.count, 31u);
    ASSERT_EQ(response.channels.size(), 3u);
    EXPECT_EQ(response.channels[0].shape, model::ChannelShape::gaussian);
    EXPECT_EQ(response.channels[1].shape, model::ChannelShape::tophat);
    EXPECT_EQ(response.channels[1].gain, 2.0);
    EXPECT_EQ(response.channels[1].bias, 0.5);
    EXPECT_TRUE(response.channels[1].normalize);
    EXPECT_EQ(response.channels[2].shape, model::ChannelShape::triangle);
    EXPECT_DOUBLE_EQ(response.channels[2].width_um, 0.06);
    ASSERT_TRUE(response.pattern.has_value());
    EXPECT_EQ(response.pattern->kind, model::ChannelPatternKind::bayer);
    EXPECT_EQ(response.pattern->channel_for("green"), "GreenChannel");
    ASSERT_TRUE(bayer.spatial_response.has_value());
    EXPECT_EQ(bayer.spatial_response->x_sub_elements, 2);
    EXPECT_EQ(bayer.spatial_response->y_sub_elements, 3);
    EXPECT_EQ(bayer.spatial_response->entries.size(), 1u);
    EXPECT_EQ(bayer.temporal_integration.time_s, 0.001);
    EXPECT_FALSE(bayer.temporal_integration.tdi);
    ASSERT_TRUE(bayer.convergence.has_value());
    EXPECT_EQ(bayer.convergence->minimum_samples, 250);
    EXPECT_EQ(bayer.convergence->maximum_samples, 750);
    EXPECT_EQ(bayer.convergence->threshold, 1e-8);
    ASSERT_TRUE(bayer.psf.has_value());
    EXPECT_EQ(bayer.psf->width_px, 3.8);
    EXPECT_EQ(bayer.active_area_image.resolved, dir / "masks/pixel_mask.png");
    ASSERT_EQ(bayer.processing.size(), 2u);
    EXPECT_EQ(bayer.processing[0].schedule, ProcessingSchedule::capture_completed);
    EXPECT_TRUE(bayer.processing[0].remove_file);
    EXPECT_EQ(bayer.processing[1].schedule, ProcessingSchedule::collection_completed);
    EXPECT_EQ(bayer.processing[1].arguments, (std::vector<std::string>{"-y", "-framerate", "15"}));

    // TrueSense: image-file defaults, tabulated pan, extras directly in the focal plane.
    const auto& truesense = planes[1]->capture_method;
    EXPECT_EQ(truesense.image_file.basename, "truesense");
    EXPECT_EQ(truesense.image_file.extension, "img");
    EXPECT_EQ(truesense.image_file.schedule, ImageSchedule::simulation);
    EXPECT_EQ(truesense.image_file.datatype, 5);
    EXPECT_EQ(truesense.image_file.area_units, AreaUnits::cm2);
    EXPECT_EQ(truesense.image_file.flux_units, FluxUnits::watts);
    EXPECT_EQ(truesense.spectral_response.bandpass.spectral_units, "microns");
    EXPECT_EQ(truesense.spectral_response.bandpass.count, 41u);
    ASSERT_EQ(truesense.spectral_response.channels.size(), 4u);
    const auto& pan = truesense.spectral_response.channels[0];
    EXPECT_EQ(pan.shape, model::ChannelShape::tabulated);
    EXPECT_EQ(pan.table_wavelength_um, (std::vector<double>{0.40, 0.45, 0.75, 0.80}));
    EXPECT_EQ(pan.table_value, (std::vector<double>{0, 0.8, 0.9, 0}));
    ASSERT_TRUE(truesense.spectral_response.pattern.has_value());
    EXPECT_EQ(truesense.spectral_response.pattern->kind, model::ChannelPatternKind::truesense);
    EXPECT_EQ(truesense.spectral_response.pattern->channel_for("pan"), "PanChannel");
    ASSERT_TRUE(truesense.psf.has_value());
    EXPECT_FALSE(truesense.psf->width_px.has_value());
    EXPECT_EQ(truesense.psf->image.resolved, dir / "airy_psf.png");
    EXPECT_EQ(truesense.psf->scale_px, 10.0);
    EXPECT_EQ(truesense.active_area_image.resolved, std::filesystem::path("/masks/diamond.png"));
    ASSERT_TRUE(truesense.convergence.has_value());
    EXPECT_EQ(truesense.convergence->minimum_samples, 10);
    EXPECT_EQ(truesense.convergence->threshold, 0.0);
    ASSERT_EQ(truesense.processing.size(), 4u);
    EXPECT_EQ(truesense.processing[0].schedule, ProcessingSchedule::collection_started);
    EXPECT_EQ(truesense.processing[0].message, "collection started");
    EXPECT_EQ(truesense.processing[1].schedule, ProcessingSchedule::task_started);
    EXPECT_EQ(truesense.processing[2].schedule, ProcessingSchedule::capture_started);
    EXPECT_FALSE(truesense.processing[2].remove_file);
    EXPECT_EQ(truesense.processing[3].schedule, ProcessingSchedule::task_completed);
    EXPECT_EQ(truesense.processing[3].arguments, std::vector<std::string>{"$$IMG_BASENAME$$"});

    // TDI: 12 stages, integration time, detector model.
    const auto& tdi = planes[2]->capture_method;
    EXPECT_EQ(planes[2]->detector_array.y_count, 12u);
    EXPECT_TRUE(tdi.temporal_integration.tdi);
    EXPECT_EQ(tdi.temporal_integration.time_s, 2e-5);
    EXPECT_EQ(tdi.image_file.schedule, ImageSchedule::task);
    ASSERT_TRUE(tdi.detector_model.has_value());
    EXPECT_EQ(tdi.detector_model->quantum_efficiency, 0.8);
    EXPECT_EQ(tdi.detector_model->read_noise_e, 20.0);
    EXPECT_EQ(tdi.detector_model->dark_current_density_a_per_m2, 8e-7);
    EXPECT_EQ(tdi.detector_model->min_electrons, 0.0);
    EXPECT_EQ(tdi.detector_model->max_electrons, 1000.0);
    EXPECT_EQ(tdi.detector_model->bit_depth, 12);
    EXPECT_EQ(tdi.spectral_response.channels.at(0).shape, model::ChannelShape::tophat);

    // Raw: 0.40–2.50 µm at 0.01 is 211 samples (the blog's example); no channels needed.
    const auto& raw = planes[3]->capture_method;
    EXPECT_FALSE(planes[3]->enabled);
    EXPECT_EQ(raw.type, CaptureMethodType::raw);
    EXPECT_EQ(raw.spectral_response.bandpass.count, 211u);
    EXPECT_TRUE(raw.spectral_response.channels.empty());
    EXPECT_EQ(raw.image_file.flux_units, FluxUnits::microwatts);
    EXPECT_EQ(raw.image_file.datatype, 4);
}

}  // namespace capture_reader_test
}  // namespace glint::test
