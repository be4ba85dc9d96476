// SPDX-License-Identifier: Apache-2.0
// resolve_detection: values from the model and the overrides, the requirements of the DIRSIG5
// BasicPlatform manual (simple capture, aperture, non-zero integration time), ranges, CFA
// mappings and the output data type; each bad input names what is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "detect_test_support.h"
#include "glint/core/error.h"

namespace glint::detect {
namespace settings_test {

using ::testing::HasSubstr;

/// The message of the error resolving `fp` throws, which must be of `category` (usage for
/// a bad command-line value, input for a bad model).
std::string error_of(const model::FocalPlane& fp, const model::InstrumentProperties& props,
                     const DetectorOverrides& o = {},
                     ErrorCategory category = ErrorCategory::input) {
    try {
        resolve_detection(fp, props, o, 1);
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), category) << e.what();
        return e.what();
    }
    return "(no error)";
}

TEST(Settings, FromTheModel) {
    const DetectionSettings s =
        resolve_detection(test::focal_plane(), test::properties_with_aperture(), {}, 42);
    ASSERT_TRUE(s.detector.has_value());
    EXPECT_EQ(s.seed, 42u);
    EXPECT_EQ(s.detector->quantum_efficiency, 0.8);
    EXPECT_EQ(s.detector->read_noise_e, 20);
    EXPECT_EQ(s.detector->bit_depth, 12);
    EXPECT_DOUBLE_EQ(s.detector->pixel_area_m2, 1e-10);
    EXPECT_DOUBLE_EQ(s.detector->gain_dn_per_e(), 4095.0 / 1e5);
    EXPECT_EQ(s.data_type, io::EnviDataType::uint16);
    EXPECT_EQ(s.output, DetectOutput::counts);
    EXPECT_TRUE(s.noise);
    EXPECT_FALSE(s.cfa.has_value());
    EXPECT_EQ(s.tdi_stages, 1u);
}

TEST(Settings, OverridesWin) {
    DetectorOverrides o;
    o.quantum_efficiency = 0.5;
    o.read_noise_e = 3;
    o.dark_current_density_a_per_m2 = 0;
    o.min_electrons = -100;  // an offset below zero is allowed from the command line
    o.max_electrons = 900;
    o.bit_depth = 10;
    o.integration_time_s = 0.5;
    o.data_type = io::EnviDataType::float32;
    o.scale_resolution = 2;  // 8 × 6 → 16 × 12 elements over the same extent
    const DetectionSettings s =
        resolve_detection(test::focal_plane(), test::properties_with_aperture(), o, 1);
    EXPECT_EQ(s.detector->quantum_efficiency, 0.5);
    EXPECT_EQ(s.detector->read_noise_e, 3);
    EXPECT_EQ(s.detector->min_electrons, -100);
    EXPECT_EQ(s.detector->bit_depth, 10);
    EXPECT_EQ(s.detector->integration_time_s, 0.5);
    EXPECT_DOUBLE_EQ(s.detector->pixel_area_m2, 0.25e-10);
    EXPECT_EQ(s.data_type, io::EnviDataType::float32);
    o.data_type.reset();
    o.electrons = true;
    EXPECT_EQ(
        resolve_detection(test::focal_plane(), test::properties_with_aperture(), o, 1).data_type,
        io::EnviDataType::float64);
}

TEST(Settings, ManualRequirements) {
    model::FocalPlane fp = test::focal_plane();
    EXPECT_THAT(error_of(fp, {}), HasSubstr("needs <aperturediameter>"));
    fp.capture_method.temporal_integration.time_s = 0;
    EXPECT_THAT(error_of(fp, test::properties_with_aperture()),
                HasSubstr("needs a non-zero integration time"));
    DetectorOverrides time;
    time.integration_time_s = 0.0;
    EXPECT_THAT(
        error_of(test::focal_plane(), test::properties_with_aperture(), time, ErrorCategory::usage),
        HasSubstr("--integration-time is 0"));
    model::FocalPlane raw = test::focal_plane();
    raw.capture_method.type = model::CaptureMethodType::raw;
    EXPECT_THAT(error_of(raw, test::properties_with_aperture()), HasSubstr("type simple"));
}

TEST(Settings, RangesAreChecked) {
    const auto props = test::properties_with_aperture();
    for (int bits : {0, 40}) {
        DetectorOverrides o;
        o.bit_depth = bits;
        EXPECT_THAT(
            error_of(test::focal_plane(), props, o, ErrorCategory::usage),
            HasSubstr("--bit-depth " + std::to_string(bits) + " is invalid, expected 1 to 32"));
    }
    model::FocalPlane fp = test::focal_plane();
    fp.capture_method.detector_model->bit_depth = 40;
    EXPECT_THAT(error_of(fp, props), HasSubstr("<bitdepth> 40 is invalid"));
    DetectorOverrides equal;
    equal.min_electrons = 500;
    equal.max_electrons = 500;
    EXPECT_THAT(error_of(test::focal_plane(), props, equal, ErrorCategory::usage),
                HasSubstr("--min-electrons 500 must be less than --max-electrons 500"));
    DetectorOverrides above;
    above.min_electrons = 2e5;  // above the model's maxelectrons 1e5
    EXPECT_THAT(error_of(test::focal_plane(), props, above, ErrorCategory::usage),
                HasSubstr("--min-electrons 2e+05 must be less than <maxelectrons> 1e+05"));
    DetectorOverrides qe;
    qe.quantum_efficiency = 1.5;
    EXPECT_THAT(error_of(test::focal_plane(), props, qe, ErrorCategory::usage),
                HasSubstr("--qe 1.5 is invalid"));
    DetectorOverrides noise;
    noise.read_noise_e = -1;
    EXPECT_THAT(error_of(test::focal_plane(), props, noise, ErrorCategory::usage),
                HasSubstr("--read-noise -1"));
}

TEST(Settings, MosaicFiltersMustMapToChannels) {
    const auto props = test::properties_with_aperture();
    DetectorOverrides o;
    o.mosaic = MosaicChoice::truesense;
    // Red, Green, Blue exist but no channel is named after "pan".
    EXPECT_THAT(error_of(test::focal_plane({"Red", "Green", "Blue"}), props, o),
                HasSubstr("no channel of focal plane \"Frame\" is named after the pan filter"));
    o.mosaic = MosaicChoice::bayer;
    const DetectionSettings s =
        resolve_detection(test::focal_plane({"BlueBand", "red", "GreenBand"}), props, o, 1);
    EXPECT_EQ(s.cfa->channel_of_filter[static_cast<int>(CfaFilter::red)], 1);
    EXPECT_EQ(s.cfa->channel_of_filter[static_cast<int>(CfaFilter::green)], 2);
    EXPECT_EQ(s.cfa->channel_of_filter[static_cast<int>(CfaFilter::blue)], 0);
    // A <channelpattern> naming a channel the focal plane lacks.
    model::FocalPlane fp = test::focal_plane({"R", "G", "B"});
    fp.capture_method.spectral_response.pattern = model::ChannelPattern{
        model::ChannelPatternKind::bayer, {{"red", "R"}, {"green", "G"}, {"blue", "Blue"}}, {}};
    EXPECT_THAT(error_of(fp, props),
                HasSubstr("the blue filter maps to channel \"Blue\", which focal plane \"Frame\" "
                          "does not have"));
    DetectorOverrides none;
    none.mosaic = MosaicChoice::none;
    EXPECT_FALSE(resolve_detection(fp, props, none, 1).cfa.has_value());
}

TEST(Settings, NothingToDetect) {
    model::FocalPlane fp = test::focal_plane();
    fp.capture_method.detector_model.reset();
    EXPECT_THAT(error_of(fp, {}), HasSubstr("has nothing to detect"));
    DetectorOverrides partial;
    partial.read_noise_e = 5;
    EXPECT_THAT(error_of(fp, test::properties_with_aperture(), partial),
                HasSubstr("has no <detectormodel>: add one to the .platform or give --qe, "
                          "--min-electrons, --max-electrons, --bit-depth"));
    DetectorOverrides full = partial;
    full.quantum_efficiency = 1;
    full.min_electrons = 0;
    full.max_electrons = 1000;
    full.bit_depth = 8;
    EXPECT_TRUE(resolve_detection(fp, test::properties_with_aperture(), full, 1).detector);
    model::FocalPlane tdi = fp;
    tdi.capture_method.temporal_integration.tdi = true;
    tdi.detector_array.y_count = 1;
    EXPECT_THAT(error_of(tdi, {}), HasSubstr("needs <yelementcount> > 1"));
    model::FocalPlane rgb = test::focal_plane({"red", "green", "blue"});
    rgb.capture_method.detector_model.reset();
    DetectorOverrides electrons;
    electrons.electrons = true;
    electrons.mosaic = MosaicChoice::bayer;
    EXPECT_THAT(error_of(rgb, {}, electrons), HasSubstr("--electrons needs a detector model"));
}

TEST(Settings, ImageDataTypeTakesRealEnviCodesOnly) {
    model::ImageFile image;
    image.where = {"x.platform", 12, "imagefile"};
    for (const int code : {1, 2, 3, 4, 5, 12, 13, 14, 15}) {
        image.datatype = code;
        EXPECT_EQ(static_cast<int>(image_data_type(image)), code);
    }
    for (const int code : {0, 6, 7, 9, 99}) {
        image.datatype = code;
        try {
            image_data_type(image);
            ADD_FAILURE() << code;
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::input);
            EXPECT_EQ(std::string(e.what()),
                      "x.platform:12: imagefile: <datatype> " + std::to_string(code) +
                          " is not a real ENVI data type (1, 2, 3, 4, 5, 12, 13, 14, 15)");
        }
    }
}

}  // namespace settings_test
}  // namespace glint::detect
