// SPDX-License-Identifier: Apache-2.0
// CFA layouts and mosaicking: every pixel of a mosaic carries the channel its filter names,
// for the Bayer pattern in all four phases and for TrueSense, through the pass-through chain
// and through the detector model (no noise).
#include "glint/detect/cfa.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "detect_test_support.h"

namespace glint::detect {
namespace cfa_test {

/// The layout as text, one row per line, filters as R, G, B, P.
std::string drawing(CfaPattern pattern, BayerPhase phase, std::size_t size) {
    std::string text;
    for (std::size_t r = 0; r < size; ++r) {
        for (std::size_t c = 0; c < size; ++c) {
            const char* letters = "RGBP";
            text += letters[static_cast<int>(cfa_filter_at(pattern, phase, r, c))];
        }
        text += '\n';
    }
    return text;
}

TEST(Cfa, BayerPhasesAsDocumented) {
    EXPECT_EQ(drawing(CfaPattern::bayer, BayerPhase::rggb, 4), "RGRG\nGBGB\nRGRG\nGBGB\n");
    EXPECT_EQ(drawing(CfaPattern::bayer, BayerPhase::grbg, 2), "GR\nBG\n");
    EXPECT_EQ(drawing(CfaPattern::bayer, BayerPhase::gbrg, 2), "GB\nRG\n");
    EXPECT_EQ(drawing(CfaPattern::bayer, BayerPhase::bggr, 2), "BG\nGR\n");
}

TEST(Cfa, TrueSenseAsDocumented) {
    EXPECT_EQ(drawing(CfaPattern::truesense, BayerPhase::rggb, 4), "PGPR\nGPRP\nPBPG\nBPGP\n");
    // Half the pixels are panchromatic, a quarter green, an eighth each red and blue.
    int counts[4] = {0, 0, 0, 0};
    for (std::size_t r = 0; r < 8; ++r) {
        for (std::size_t c = 0; c < 8; ++c) {
            ++counts[static_cast<int>(
                cfa_filter_at(CfaPattern::truesense, BayerPhase::rggb, r, c))];
        }
    }
    EXPECT_EQ(counts[static_cast<int>(CfaFilter::pan)], 32);
    EXPECT_EQ(counts[static_cast<int>(CfaFilter::green)], 16);
    EXPECT_EQ(counts[static_cast<int>(CfaFilter::red)], 8);
    EXPECT_EQ(counts[static_cast<int>(CfaFilter::blue)], 8);
}

TEST(Cfa, NamesRoundTrip) {
    for (BayerPhase p : {BayerPhase::rggb, BayerPhase::grbg, BayerPhase::gbrg, BayerPhase::bggr}) {
        EXPECT_EQ(bayer_phase_from_name(bayer_phase_name(p)), p);
    }
    EXPECT_EQ(bayer_phase_from_name("BGGR"), BayerPhase::bggr);
    EXPECT_FALSE(bayer_phase_from_name("rgbg").has_value());
    EXPECT_EQ(cfa_pattern_from_name("TrueSense"), CfaPattern::truesense);
    EXPECT_EQ(cfa_filter_from_name("Pan"), CfaFilter::pan);
    EXPECT_EQ(cfa_filters(CfaPattern::bayer).size(), 3u);
    EXPECT_EQ(cfa_filters(CfaPattern::truesense).size(), 4u);
}

/// Runs a mosaic over a W × H image whose channel c holds the value 1000 (c + 1) + pixel
/// index, and checks that each output pixel is its filter's channel's value.
void check_mosaic(const DetectionSettings& s, std::size_t width, std::size_t height,
                  const std::function<double(double)>& transfer) {
    const DetectionChain chain(s, width);
    const std::size_t channels = s.channels();
    std::vector<double> in(width * channels);
    std::vector<double> out(width);
    for (std::size_t y = 0; y < height; ++y) {
        for (std::size_t x = 0; x < width; ++x) {
            for (std::size_t c = 0; c < channels; ++c) {
                in[x * channels + c] = 1000.0 * static_cast<double>(c + 1) + y * width + x;
            }
        }
        chain.process_line({3, y}, in, out);
        for (std::size_t x = 0; x < width; ++x) {
            const CfaFilter f = cfa_filter_at(s.cfa->pattern, s.cfa->phase, y, x);
            const int c = s.cfa->channel_of_filter[static_cast<std::size_t>(f)];
            ASSERT_EQ(out[x], transfer(in[x * channels + static_cast<std::size_t>(c)]))
                << cfa_pattern_name(s.cfa->pattern) << " " << bayer_phase_name(s.cfa->phase) << " ("
                << y << ", " << x << ") " << cfa_filter_name(f);
        }
    }
}

TEST(Cfa, EveryPixelCarriesItsFiltersChannel) {
    // Channels listed in an order unlike the filters', so a wrong mapping shows.
    model::FocalPlane bayer = test::focal_plane({"BlueChannel", "RedChannel", "GreenChannel"});
    bayer.capture_method.spectral_response.pattern = model::ChannelPattern{
        model::ChannelPatternKind::bayer,
        {{"red", "RedChannel"}, {"green", "GreenChannel"}, {"blue", "BlueChannel"}},
        {}};
    bayer.capture_method.detector_model.reset();
    for (BayerPhase phase :
         {BayerPhase::rggb, BayerPhase::grbg, BayerPhase::gbrg, BayerPhase::bggr}) {
        DetectorOverrides o;
        o.bayer_phase = phase;
        const DetectionSettings s = resolve_detection(bayer, {}, o, 1);
        ASSERT_TRUE(s.cfa.has_value());
        EXPECT_EQ(s.output_bands(), 1u);
        check_mosaic(s, 7, 5, [](double v) { return v; });
    }
    model::FocalPlane truesense =
        test::focal_plane({"GreenChannel", "PanChannel", "BlueChannel", "RedChannel"});
    truesense.capture_method.spectral_response.pattern =
        model::ChannelPattern{model::ChannelPatternKind::truesense,
                              {{"pan", "PanChannel"},
                               {"red", "RedChannel"},
                               {"green", "GreenChannel"},
                               {"blue", "BlueChannel"}},
                              {}};
    truesense.capture_method.detector_model.reset();
    check_mosaic(resolve_detection(truesense, {}, {}, 1), 9, 9, [](double v) { return v; });
}

TEST(Cfa, MosaicThroughTheDetectorModel) {
    model::FocalPlane fp = test::focal_plane({"Red", "Green", "Blue"});
    DetectorOverrides o;
    o.mosaic = MosaicChoice::bayer;  // filters found by channel name
    o.bayer_phase = BayerPhase::gbrg;
    o.no_noise = true;
    o.electrons = true;
    const DetectionSettings s = resolve_detection(fp, test::properties_with_aperture(), o, 1);
    const double per_fluence = 1e-6 * 0.8;  // 10 µm pixel (cm²) × QE
    const double dark = s.detector->dark_electrons(1);
    check_mosaic(s, 6, 4, [&](double v) { return v * per_fluence + dark; });
}

}  // namespace cfa_test
}  // namespace glint::detect
