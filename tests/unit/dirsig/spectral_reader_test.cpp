// SPDX-License-Identifier: Apache-2.0
// Tests of the spectral-response reader (lib/dirsig/src/spectral_reader.cpp): bandpass
// units and sample counts, every channel shape and attribute, channel patterns, the
// whole-response checks, and every bad input with its message, line and element path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "capture_test_util.h"
#include "glint/model/spectral_response.h"

namespace glint::test {
namespace spectral_reader_test {

using model::ChannelPatternKind;
using model::ChannelShape;

std::string bandpass(const std::string& min, const std::string& max, const std::string& delta,
                     const std::string& units = "") {
    const std::string attribute = units.empty() ? "" : " spectralunits=\"" + units + "\"";
    return "<bandpass" + attribute + ">\n<minimum>" + min + "</minimum>\n<maximum>" + max +
           "</maximum>\n<delta>" + delta + "</delta>\n</bandpass>";
}

/// A focal plane whose capture has the given spectral response body.
CaptureRead read_spectral(const std::string& body, const std::string& type = "simple") {
    return read_focal_plane("<focalplane name=\"F\">\n" +
                            capture_xml("", body, "type=\"" + type + "\" name=\"C\"") +
                            "</focalplane>");
}

constexpr const char* kPath = "focalplane[F]/capturemethod[C]/spectralresponse";

// ---- good input -----------------------------------------------------------------------------

TEST(SpectralReader, BandpassInMicronsIsTheDefault) {
    const auto read = read_spectral(std::string(kBandpass) + kOneChannel);
    ASSERT_TRUE(clean(read));
    const auto& b = read.capture.spectral_response.bandpass;
    EXPECT_EQ(b.spectral_units, "microns");
    EXPECT_DOUBLE_EQ(b.min_um, 0.4);
    EXPECT_DOUBLE_EQ(b.max_um, 0.7);
    EXPECT_DOUBLE_EQ(b.delta_um, 0.01);
    EXPECT_EQ(b.count, 31u);
    EXPECT_EQ(b.where.element, std::string(kPath) + "/bandpass");
}

TEST(SpectralReader, ManualExampleBandpassHas41Samples) {
    const auto read = read_spectral(bandpass("0.4", "0.8", "0.01", "microns") + kOneChannel);
    ASSERT_TRUE(clean(read));
    EXPECT_EQ(read.capture.spectral_response.bandpass.count, 41u);
}

TEST(SpectralReader, EveryUnitSpelling) {
    for (const char* unit : {"microns", "micrometers", "um", "Microns"}) {
        const auto read = read_spectral(bandpass("0.4", "0.7", "0.005", unit) + kOneChannel);
        EXPECT_TRUE(clean(read)) << unit;
        EXPECT_EQ(read.capture.spectral_response.bandpass.count, 61u) << unit;
        EXPECT_DOUBLE_EQ(read.capture.spectral_response.bandpass.max_um, 0.7) << unit;
    }
    for (const char* unit : {"nanometers", "nm"}) {
        const auto read = read_spectral(
            bandpass("400", "700", "5", unit) +
            "<channellist><channel name=\"G\"><center>550</center><width>40</width></channel>"
            "</channellist>");
        EXPECT_TRUE(clean(read)) << unit;
        const auto& response = read.capture.spectral_response;
        EXPECT_DOUBLE_EQ(response.bandpass.min_um, 0.4) << unit;
        EXPECT_DOUBLE_EQ(response.bandpass.max_um, 0.7) << unit;
        EXPECT_DOUBLE_EQ(response.bandpass.delta_um, 0.005) << unit;
        EXPECT_EQ(response.bandpass.count, 61u) << unit;
        EXPECT_DOUBLE_EQ(response.channels[0].center_um, 0.55) << unit;
        EXPECT_DOUBLE_EQ(response.channels[0].width_um, 0.04) << unit;
    }
}

TEST(SpectralReader, ChannelAttributesAndDefaults) {
    const auto read = read_spectral(
        std::string(kBandpass) +
        "<channellist>\n"
        "<channel name=\"A\"><center>0.5</center><width>0.02</width></channel>\n"
        "<channel bias=\"-0.5\" gain=\"2.5\" name=\"B\" normalize=\"true\" shape=\"tophat\">"
        "<center>0.6</center><width>0.1</width>"
        "<polarizer type=\"none\"/><dataoutput type=\"total\"/></channel>\n"
        "<channel name=\"C\" shape=\"Triangle\" normalize=\"0\"><center>0.45</center>"
        "<width>0.03</width></channel>\n"
        "</channellist>");
    ASSERT_TRUE(clean(read));
    const auto& channels = read.capture.spectral_response.channels;
    ASSERT_EQ(channels.size(), 3u);
    EXPECT_EQ(channels[0].name, "A");
    EXPECT_EQ(channels[0].shape, ChannelShape::gaussian);
    EXPECT_FALSE(channels[0].normalize);
    EXPECT_EQ(channels[0].gain, 1.0);
    EXPECT_EQ(channels[0].bias, 0.0);
    EXPECT_EQ(channels[0].polarizer, "none");
    EXPECT_EQ(channels[0].data_output, "total");
    EXPECT_DOUBLE_EQ(channels[0].center_um, 0.5);
    EXPECT_DOUBLE_EQ(channels[0].width_um, 0.02);
    EXPECT_TRUE(channels[0].table_wavelength_um.empty());
    EXPECT_EQ(channels[0].where.element, std::string(kPath) + "/channellist/channel[A]");
    EXPECT_EQ(channels[1].shape, ChannelShape::tophat);
    EXPECT_TRUE(channels[1].normalize);
    EXPECT_EQ(channels[1].gain, 2.5);
    EXPECT_EQ(channels[1].bias, -0.5);
    EXPECT_EQ(channels[2].shape, ChannelShape::triangle);
    EXPECT_FALSE(channels[2].normalize);
    EXPECT_DOUBLE_EQ(channels[2].width_um, 0.03);
}

TEST(SpectralReader, TabulatedChannelInNanometers) {
    const auto read =
        read_spectral(bandpass("400", "700", "10", "nm") +
                      "<channellist><channel name=\"T\" shape=\"tabulated\">\n"
                      "<entry><spectralpoint>420</spectralpoint><value>0</value></entry>\n"
                      "<entry><spectralpoint>450.5</spectralpoint><value>0.75</value></entry>\n"
                      "<entry><spectralpoint>480</spectralpoint><value>1</value></entry>\n"
                      "</channel></channellist>");
    ASSERT_TRUE(clean(read));
    const auto& channel = read.capture.spectral_response.channels.at(0);
    EXPECT_EQ(channel.shape, ChannelShape::tabulated);
    ASSERT_EQ(channel.table_wavelength_um.size(), 3u);
    EXPECT_DOUBLE_EQ(channel.table_wavelength_um[0], 0.42);
    EXPECT_DOUBLE_EQ(channel.table_wavelength_um[1], 0.4505);
    EXPECT_DOUBLE_EQ(channel.table_wavelength_um[2], 0.48);
    EXPECT_EQ(channel.table_value, (std::vector<double>{0.0, 0.75, 1.0}));
}

TEST(SpectralReader, BayerAndTrueSensePatterns) {
    auto read = read_spectral(
        std::string(kBandpass) +
        "<channellist><channel name=\"R\"><center>0.65</center><width>0.05</width></channel>"
        "<channel name=\"G\"><center>0.55</center><width>0.05</width></channel>"
        "<channel name=\"B\"><center>0.45</center><width>0.05</width></channel></channellist>\n"
        "<channelpattern name=\"bayer\"><mapping filtername=\"red\" channelname=\"R\"/>"
        "<mapping filtername=\"Green\" channelname=\"G\"/>"
        "<mapping filtername=\"blue\" channelname=\"B\"/></channelpattern>");
    ASSERT_TRUE(clean(read));
    ASSERT_TRUE(read.capture.spectral_response.pattern.has_value());
    const auto& bayer = *read.capture.spectral_response.pattern;
    EXPECT_EQ(bayer.kind, ChannelPatternKind::bayer);
    EXPECT_EQ(bayer.channel_for("red"), "R");
    EXPECT_EQ(bayer.channel_for("green"), "G");
    EXPECT_EQ(bayer.channel_for("blue"), "B");
    EXPECT_EQ(bayer.channel_for("pan"), std::nullopt);

    read = read_spectral(
        std::string(kBandpass) +
        "<channellist><channel name=\"P\" shape=\"tophat\"><center>0.55</center><width>0.3"
        "</width></channel><channel name=\"R\"><center>0.65</center><width>0.05</width>"
        "</channel><channel name=\"G\"><center>0.55</center><width>0.05</width></channel>"
        "<channel name=\"B\"><center>0.45</center><width>0.05</width></channel></channellist>\n"
        "<channelpattern name=\"truesense\"><mapping filtername=\"pan\" channelname=\"P\"/>"
        "<mapping filtername=\"red\" channelname=\"R\"/><mapping filtername=\"green\" "
        "channelname=\"G\"/><mapping filtername=\"blue\" channelname=\"B\"/></channelpattern>");
    ASSERT_TRUE(clean(read));
    const auto& truesense = *read.capture.spectral_response.pattern;
    EXPECT_EQ(truesense.kind, ChannelPatternKind::truesense);
    EXPECT_EQ(truesense.mappings.size(), 4u);
    EXPECT_EQ(truesense.channel_for("pan"), "P");
}

TEST(SpectralReader, RectangularIsTheTophat) {
    // DIRSIG's own notebooks write shape="rectangular": the same box as "tophat".
    const auto read = read_spectral(std::string(kBandpass) +
                                    "<channellist><channel name=\"R\" shape=\"rectangular\">"
                                    "<center>0.55</center><width>0.1</width></channel>"
                                    "</channellist>");
    ASSERT_TRUE(clean(read));
    const model::Channel& channel = read.capture.spectral_response.channels.at(0);
    EXPECT_EQ(channel.shape, ChannelShape::tophat);
    EXPECT_EQ(channel.center_um, 0.55);
    EXPECT_EQ(channel.width_um, 0.1);
}

TEST(SpectralReader, ChannelCentreJustOutsideTheBandpassIsAWarning) {
    // Real AVIRIS files put channel #1 (0.3734 µm, FWHM 0.0099) below a 0.38 µm bandpass.
    const auto read = read_spectral(
        bandpass("0.38", "2.5", "0.001") +
        "<channellist>\n<channel name=\"Channel #1\"><center>0.3734</center><width>0.0099"
        "</width></channel>\n</channellist>");
    EXPECT_EQ(read.diagnostics.error_count(), 0u);
    EXPECT_TRUE(has_warning(read,
                            "center 0.3734 microns lies outside the bandpass 0.38–2.5 microns; "
                            "only the part of its response inside the bandpass is used",
                            "<channel name",
                            std::string(kPath) + "/channellist/channel[Channel #1]"));
}

TEST(SpectralReader, PolarizationIsKeptAndWarnedAbout) {
    const auto read = read_spectral(
        std::string(kBandpass) +
        "<channellist><channel name=\"G\"><center>0.55</center><width>0.04</width>\n"
        "<polarizer type=\"linear\"/>\n<dataoutput type=\"stokes\"/>\n</channel></channellist>");
    EXPECT_EQ(read.diagnostics.error_count(), 0u);
    EXPECT_EQ(read.capture.spectral_response.channels[0].polarizer, "linear");
    EXPECT_EQ(read.capture.spectral_response.channels[0].data_output, "stokes");
    const std::string channel = std::string(kPath) + "/channellist/channel[G]";
    EXPECT_TRUE(has_warning(read, "type 'linear': polarization is not modelled", "<polarizer",
                            channel + "/polarizer@type"));
    EXPECT_TRUE(has_warning(read, "type 'stokes': polarization is not modelled", "<dataoutput",
                            channel + "/dataoutput@type"));
}

// ---- bad input --------------------------------------------------------------------------------

TEST(SpectralReader, HundredThousandSamplesAreAccepted) {
    // One more is refused (SpectralReaderBadInput, Bandpass100001Samples).
    EXPECT_TRUE(clean(read_spectral(bandpass("0.4", "1.39999", "0.00001") + kOneChannel)));
}

/// A spectral response body (in a capture of `type`) and one error it must give, on the line
/// of `anchor` with element path kPath + `element`.
struct SpectralErrorCase {
    std::string name;
    std::string body;
    std::string message;
    std::string anchor;
    std::string element;
    std::string type = "simple";
    std::optional<std::size_t> errors = std::nullopt;  ///< the read's error count, when checked
    bool bandpass_refused = false;                     ///< the bandpass keeps no samples
};

class SpectralReaderBadInput : public ::testing::TestWithParam<SpectralErrorCase> {};

TEST_P(SpectralReaderBadInput, MessageLineAndElement) {
    const SpectralErrorCase& c = GetParam();
    const auto read = read_spectral(c.body, c.type);
    EXPECT_TRUE(has_error(read, c.message, c.anchor, std::string(kPath) + c.element));
    if (c.errors) {
        EXPECT_EQ(read.diagnostics.error_count(), *c.errors);
    }
    if (c.bandpass_refused) {
        EXPECT_EQ(read.capture.spectral_response.bandpass.count, 0u);
    }
}

std::vector<SpectralErrorCase> spectral_errors() {
    const std::string band = kBandpass;
    const std::string bad_bandpass = bandpass("zero", "0.7", "-0.01", "furlongs") + kOneChannel;
    const std::string attributes = band +
                                   "<channellist>\n"
                                   "<channel shape=\"square\"><center>0.5</center></channel>\n"
                                   "<channel name=\" \" normalize=\"perhaps\" gain=\"x\"><center>"
                                   "0.5</center><width>0.01</width></channel>\n"
                                   "</channellist>";
    const std::string gaussian =
        band +
        "<channellist>\n<channel name=\"G\">\n<center>green</center>\n<width>-0.04</width>\n"
        "</channel>\n<channel name=\"H\">\n</channel>\n</channellist>";
    const std::string outside =
        band +
        "<channellist>\n"
        "<channel name=\"NIR\"><center>0.85</center><width>0.05</width></channel>\n"
        "<channel name=\"Box\" shape=\"tophat\"><center>0.3</center><width>0.1</width>"
        "</channel>\n"
        "<channel name=\"Table\" shape=\"tabulated\"><entry><spectralpoint>0.8</spectralpoint>"
        "<value>1</value></entry><entry><spectralpoint>0.9</spectralpoint><value>1</value>"
        "</entry></channel>\n"
        "</channellist>";
    const std::string list = "/channellist";
    return {
        // bandpass
        {"DeltaThatDoesNotDivideTheRange", bandpass("0.4", "0.7", "0.07") + kOneChannel,
         "bandpass delta 0.07 does not divide the range 0.4–0.7 microns (4 steps would need "
         "delta 0.075), expected a delta that divides maximum − minimum",
         "<delta>", "/bandpass/delta", "simple", std::nullopt, true},
        {"BillionSampleBandpassIsRefusedBeforeAllocation",
         bandpass("0.4", "1.4", "1e-9") + kOneChannel,
         "bandpass 0.4–1.4 microns at delta 1e-09 has 1000000001 samples, expected at most "
         "100000",
         "<delta>", "/bandpass/delta", "simple", std::nullopt, true},
        // A huge range is refused the same way (no overflow of the count).
        {"HugeRangeIsRefusedWithoutOverflow", bandpass("1", "1e300", "1e-300") + kOneChannel,
         "has more than 10^18 samples, expected at most 100000", "<delta>", "/bandpass/delta"},
        {"Bandpass100001Samples", bandpass("0.4", "1.4", "0.00001") + kOneChannel,
         "has 100001 samples", "<delta>", "/bandpass/delta"},
        {"MaximumBelowMinimum", bandpass("0.7", "0.4", "0.01") + kOneChannel,
         "maximum 0.4 microns is not above minimum 0.7 microns, expected minimum < maximum",
         "<maximum>", "/bandpass/maximum"},
        {"MinimumNotANumber", bad_bandpass, "expected a number > 0, got \"zero\"", "<minimum>",
         "/bandpass/minimum"},
        {"NegativeDelta", bad_bandpass, "expected a number > 0, got \"-0.01\"", "<delta>",
         "/bandpass/delta"},
        {"UnknownSpectralUnits", bad_bandpass,
         "expected one of microns, micrometers, um, nanometers, nm, got \"furlongs\"", "<bandpass",
         "/bandpass@spectralunits"},
        {"BandpassWithoutDelta", std::string("<bandpass>\n</bandpass>") + kOneChannel,
         "missing required element <delta>", "<bandpass>", "/bandpass"},
        {"NoBandpass", kOneChannel, "missing required element <bandpass>", "<spectralresponse>",
         ""},
        // channels
        {"SimpleCaptureNeedsAChannel", band,
         "no channel, expected at least one <channel> in <channellist>", "<spectralresponse>", ""},
        {"ChannelWithoutName", attributes, "missing required attribute name", "<channel shape",
         list + "/channel"},
        {"UnknownChannelShape", attributes,
         "expected one of gaussian, tabulated, tophat, rectangular, triangle, got \"square\"",
         "<channel shape", list + "/channel@shape"},
        {"EmptyChannelName", attributes, "channel name is empty, expected a name",
         "<channel name=\" \"", list + "/channel[ ]@name"},
        {"NormalizeNotABoolean", attributes, "expected a boolean", "<channel name=\" \"",
         list + "/channel[ ]@normalize"},
        {"GainNotANumber", attributes, "expected a number, got \"x\"", "<channel name=\" \"",
         list + "/channel[ ]@gain"},
        {"GaussianCentreNotANumber", gaussian, "expected a number, got \"green\"", "<center>",
         list + "/channel[G]/center"},
        {"GaussianNegativeWidth", gaussian, "expected a number > 0, got \"-0.04\"", "<width>",
         list + "/channel[G]/width"},
        {"GaussianWithoutCentre", gaussian, "missing required element <center>",
         "<channel name=\"H\"", list + "/channel[H]"},
        {"GaussianWithoutWidth", gaussian, "missing required element <width>",
         "<channel name=\"H\"", list + "/channel[H]"},
        {"ChannelCentreOutsideTheBandpass", outside,
         "center 0.85 microns lies outside the bandpass 0.4–0.7 microns and its response does "
         "not reach into it, expected a center inside the bandpass",
         "<channel name=\"NIR\"", list + "/channel[NIR]"},
        {"TophatCentreOutsideTheBandpass", outside,
         "center 0.3 microns lies outside the bandpass 0.4–0.7 microns", "<channel name=\"Box\"",
         list + "/channel[Box]"},
        {"TabulatedResponseOutsideTheBandpass", outside,
         "tabulated response 0.8–0.9 microns lies outside the bandpass 0.4–0.7 microns",
         "<channel name=\"Table\"", list + "/channel[Table]"},
        {"ChannelCentreOutsideANanometreBandpass",
         bandpass("400", "700", "5", "nanometers") +
             "<channellist>\n<channel name=\"UV\"><center>300</center><width>10</width>"
             "</channel>\n</channellist>",
         "center 300 nanometers lies outside the bandpass 400–700 nanometers",
         "<channel name=\"UV\"", list + "/channel[UV]"},
        {"DuplicateChannelNames",
         band + "<channellist>\n"
                "<channel name=\"G\"><center>0.55</center><width>0.04</width></channel>\n"
                "<channel name=\"G\"><center>0.56</center><width>0.04</width></channel>\n"
                "</channellist>",
         "duplicate channel name 'G' (first at line 6), expected unique names",
         "<channel name=\"G\"><center>0.56", list + "/channel[G]", "simple", 1},
        // patterns
        {"PatternOnARawCapture",
         band + kOneChannel +
             "<channelpattern name=\"bayer\">"
             "<mapping filtername=\"red\" channelname=\"G\"/>"
             "<mapping filtername=\"green\" channelname=\"G\"/>"
             "<mapping filtername=\"blue\" channelname=\"G\"/>"
             "</channelpattern>",
         "a channel pattern needs capturemethod type simple, expected no <channelpattern> in a "
         "raw capture",
         "<channelpattern", "/channelpattern[bayer]", "raw", 1},
    };
}

INSTANTIATE_TEST_SUITE_P(SpectralReader, SpectralReaderBadInput,
                         ::testing::ValuesIn(spectral_errors()),
                         [](const ::testing::TestParamInfo<SpectralErrorCase>& test_case) {
                             return test_case.param.name;
                         });

TEST(SpectralReaderErrors, TabulatedValues) {
    const auto read = read_spectral(
        std::string(kBandpass) +
        "<channellist>\n"
        "<channel name=\"One\" shape=\"tabulated\">\n"
        "<entry><spectralpoint>0.5</spectralpoint><value>1</value></entry>\n</channel>\n"
        "<channel name=\"Order\" shape=\"tabulated\">\n"
        "<entry><spectralpoint>0.6</spectralpoint><value>1</value></entry>\n"
        "<entry><spectralpoint>0.5</spectralpoint><value>1</value></entry>\n</channel>\n"
        "<channel name=\"Negative\" shape=\"tabulated\">\n"
        "<entry><spectralpoint>0.5</spectralpoint><value>-1</value></entry>\n"
        "<entry><spectralpoint>0.6</spectralpoint><value>1</value></entry>\n</channel>\n"
        "<channel name=\"Zero\" shape=\"tabulated\" normalize=\"true\">\n"
        "<entry><spectralpoint>0.5</spectralpoint><value>0</value></entry>\n"
        "<entry><spectralpoint>0.6</spectralpoint><value>0</value></entry>\n</channel>\n"
        "</channellist>");
    const std::string list = std::string(kPath) + "/channellist";
    EXPECT_TRUE(has_error(read, "tabulated channel has 1 <entry>, expected at least 2",
                          "<channel name=\"One\"", list + "/channel[One]"));
    EXPECT_TRUE(has_error(read,
                          "spectralpoint 0.5 does not increase (previous 0.6), expected "
                          "strictly increasing points",
                          "<entry><spectralpoint>0.5</spectralpoint><value>1</value></entry>\n"
                          "</channel>\n<channel name=\"Neg",
                          list + "/channel[Order]/entry/spectralpoint"));
    EXPECT_TRUE(has_error(read, "expected a number >= 0, got \"-1\"", "<value>-1",
                          list + "/channel[Negative]/entry/value"));
    EXPECT_TRUE(has_error(read, "tabulated response is zero everywhere and cannot be normalized",
                          "<channel name=\"Zero\"", list + "/channel[Zero]"));
    EXPECT_EQ(read.diagnostics.error_count(), 4u);
}

TEST(SpectralReaderErrors, PatternProblems) {
    const std::string channels =
        "<channellist><channel name=\"R\"><center>0.65</center><width>0.05</width></channel>"
        "<channel name=\"G\"><center>0.55</center><width>0.05</width></channel></channellist>\n";
    auto read = read_spectral(std::string(kBandpass) + channels +
                              "<channelpattern name=\"bayer\">\n"
                              "<mapping filtername=\"red\" channelname=\"R\"/>\n"
                              "<mapping filtername=\"green\" channelname=\"G\"/>\n"
                              "<mapping filtername=\"green\" channelname=\"R\"/>\n"
                              "<mapping filtername=\"yellow\" channelname=\"G\"/>\n"
                              "<mapping filtername=\"blue\" channelname=\"Blue\"/>\n"
                              "<mapping channelname=\"G\"/>\n"
                              "</channelpattern>");
    const std::string pattern = std::string(kPath) + "/channelpattern[bayer]";
    EXPECT_TRUE(has_error(read, "filter 'green' is mapped 2 times, expected exactly once",
                          "<channelpattern", pattern));
    EXPECT_TRUE(has_error(read,
                          "filter 'yellow' is not a filter of the bayer pattern, expected red, "
                          "green or blue",
                          "yellow", pattern + "/mapping@filtername"));
    EXPECT_TRUE(has_error(read,
                          "filter 'blue' is mapped to channel 'Blue', which is not in the "
                          "channel list",
                          "<channelpattern", pattern));
    EXPECT_TRUE(has_error(read, "missing required attribute filtername", "<mapping channelname",
                          pattern + "/mapping"));
    EXPECT_EQ(read.diagnostics.error_count(), 4u);

    read = read_spectral(std::string(kBandpass) + channels +
                         "<channelpattern name=\"truesense\">\n"
                         "<mapping filtername=\"red\" channelname=\"R\"/>\n"
                         "<mapping filtername=\"green\" channelname=\"G\"/>\n"
                         "</channelpattern>");
    const std::string truesense = std::string(kPath) + "/channelpattern[truesense]";
    EXPECT_TRUE(has_error(read, "filter 'pan' of the truesense pattern is not mapped",
                          "<channelpattern", truesense));
    EXPECT_TRUE(has_error(read, "filter 'blue' of the truesense pattern is not mapped",
                          "<channelpattern", truesense));

    read = read_spectral(std::string(kBandpass) + channels + "<channelpattern name=\"xtrans\"/>");
    EXPECT_TRUE(has_error(read, "expected one of bayer, truesense, got \"xtrans\"",
                          "<channelpattern", std::string(kPath) + "/channelpattern[xtrans]@name"));
    EXPECT_FALSE(read.capture.spectral_response.pattern.has_value());
}

TEST(ChannelPattern, ChannelFor) {
    model::ChannelPattern pattern;
    EXPECT_EQ(pattern.channel_for("red"), std::nullopt);
    pattern.mappings = {{"red", "R"}, {"green", "G"}};
    EXPECT_EQ(pattern.channel_for("green"), "G");
    EXPECT_EQ(pattern.channel_for("Green"), std::nullopt);  // filter names are lower case
}

// ---- the generated spectral platforms through read_platform ---------------------------

nlohmann::json spectral_dump(const std::string& name) {
    std::ifstream in(std::filesystem::path(GLINT_SOURCE_DIR) / "data" / "spectral_responses" /
                     name);
    return nlohmann::json::parse(in);
}

TEST(SpectralPlatforms, Aviris224GaussianChannels) {
    const auto read = read_platform_fixture("aviris.platform");
    EXPECT_EQ(read.diagnostics.error_count(), 0u) << list_diagnostics(read.diagnostics);
    // Channel #1 (0.3734 µm) lies just below the 0.38 µm bandpass, as in the real file.
    ASSERT_EQ(read.diagnostics.warning_count(), 1u) << list_diagnostics(read.diagnostics);
    EXPECT_NE(read.diagnostics.items()[0].message.find("center 0.3734 microns lies outside"),
              std::string::npos);
    const auto planes = focal_planes(read.platform);
    ASSERT_EQ(planes.size(), 1u);
    const auto& response = planes[0]->capture_method.spectral_response;
    EXPECT_DOUBLE_EQ(response.bandpass.min_um, 0.38);
    EXPECT_DOUBLE_EQ(response.bandpass.max_um, 2.5);
    EXPECT_DOUBLE_EQ(response.bandpass.delta_um, 0.001);
    EXPECT_EQ(response.bandpass.count, 2121u);
    const auto dump = spectral_dump("aviris_spectralresponse.json");
    const auto& expected = dump.at("channellist");
    ASSERT_EQ(response.channels.size(), 224u);
    ASSERT_EQ(expected.size(), 224u);
    for (std::size_t i = 0; i < 224; ++i) {
        const auto& channel = response.channels[i];
        EXPECT_EQ(channel.name, expected[i].at("name").get<std::string>());
        EXPECT_EQ(channel.shape, ChannelShape::gaussian);
        EXPECT_TRUE(channel.normalize);
        EXPECT_EQ(channel.gain, 1.0);
        EXPECT_EQ(channel.bias, 0.0);
        EXPECT_EQ(channel.center_um, expected[i].at("center").get<double>()) << channel.name;
        EXPECT_EQ(channel.width_um, expected[i].at("width").get<double>()) << channel.name;
    }
    EXPECT_EQ(response.channels.front().center_um, 0.3734);
    EXPECT_EQ(response.channels.back().name, "Channel #224");
    EXPECT_EQ(response.channels.back().center_um, 2.4934);
    EXPECT_EQ(response.channels.back().width_um, 0.0117);
}

TEST(SpectralPlatforms, SuperDoveTabulatedChannelsInNanometers) {
    const auto read = read_platform_fixture("superdove.platform");
    EXPECT_TRUE(read.diagnostics.items().empty()) << list_diagnostics(read.diagnostics);
    const auto planes = focal_planes(read.platform);
    ASSERT_EQ(planes.size(), 1u);
    const auto& response = planes[0]->capture_method.spectral_response;
    EXPECT_EQ(response.bandpass.spectral_units, "nanometers");
    EXPECT_DOUBLE_EQ(response.bandpass.min_um, 0.425);
    EXPECT_DOUBLE_EQ(response.bandpass.max_um, 0.895);
    EXPECT_DOUBLE_EQ(response.bandpass.delta_um, 0.001);
    EXPECT_EQ(response.bandpass.count, 471u);
    const auto dump = spectral_dump("planet_superdove_640x480_spectralresponse.json");
    const auto& expected = dump.at("channellist");
    ASSERT_EQ(response.channels.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) {
        const auto& channel = response.channels[i];
        EXPECT_EQ(channel.name, expected[i].at("name").get<std::string>());
        EXPECT_EQ(channel.shape, ChannelShape::tabulated);
        EXPECT_TRUE(channel.normalize);
        const auto points = expected[i].at("spectralpoints").get<std::vector<double>>();
        const auto values = expected[i].at("values").get<std::vector<double>>();
        ASSERT_EQ(channel.table_wavelength_um.size(), points.size()) << channel.name;
        for (std::size_t k = 0; k < points.size(); ++k) {
            EXPECT_DOUBLE_EQ(channel.table_wavelength_um[k], points[k] * 1e-3);
        }
        EXPECT_EQ(channel.table_value, values) << channel.name;
    }
    EXPECT_EQ(response.channels.front().name, "Coastal Blue");
    EXPECT_EQ(response.channels.back().name, "NIR");
}

TEST(SpectralPlatforms, NanometerBandpassIsConvertedToMicrometres) {
    const auto read = read_platform_fixture("nanometers.platform");
    EXPECT_TRUE(read.diagnostics.items().empty()) << list_diagnostics(read.diagnostics);
    const auto planes = focal_planes(read.platform);
    ASSERT_EQ(planes.size(), 1u);
    const auto& capture = planes[0]->capture_method;
    EXPECT_EQ(capture.image_file.flux_units, model::FluxUnits::milliwatts);
    const auto& response = capture.spectral_response;
    EXPECT_EQ(response.bandpass.spectral_units, "nanometers");
    EXPECT_DOUBLE_EQ(response.bandpass.min_um, 0.4);
    EXPECT_DOUBLE_EQ(response.bandpass.max_um, 0.7);
    EXPECT_DOUBLE_EQ(response.bandpass.delta_um, 0.005);
    EXPECT_EQ(response.bandpass.count, 61u);
    ASSERT_EQ(response.channels.size(), 3u);
    EXPECT_DOUBLE_EQ(response.channels[0].center_um, 0.64);
    EXPECT_DOUBLE_EQ(response.channels[0].width_um, 0.04);
    EXPECT_DOUBLE_EQ(response.channels[1].center_um, 0.55);
    const auto& blue = response.channels[2];
    EXPECT_EQ(blue.shape, ChannelShape::tabulated);
    ASSERT_EQ(blue.table_wavelength_um.size(), 3u);
    EXPECT_DOUBLE_EQ(blue.table_wavelength_um[0], 0.4);
    EXPECT_DOUBLE_EQ(blue.table_wavelength_um[1], 0.45);
    EXPECT_DOUBLE_EQ(blue.table_wavelength_um[2], 0.5);
    EXPECT_EQ(blue.table_value, (std::vector<double>{0.1, 0.9, 0.2}));
}

}  // namespace spectral_reader_test
}  // namespace glint::test
