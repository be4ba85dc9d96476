// SPDX-License-Identifier: Apache-2.0
// Tests of the derived quantities: F# and G# against the formula of the DIRSIG5 BasicPlatform
// manual (its example instrument: 1140 mm focal length, 0.09 m aperture), pixel IFOV, the
// bandpass grid, and the channel shapes against their analytic integrals.
#include "glint/model/derived.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace glint::model {
namespace derived_test {

InstrumentProperties manual_example(double throughput = 1.0) {
    InstrumentProperties p;
    p.focal_length_m = 1140e-3;
    p.aperture_diameter_m = 0.09;
    p.aperture_throughput = throughput;
    return p;
}

Bandpass bandpass(double min_um, double max_um, double delta_um) {
    Bandpass b;
    b.min_um = min_um;
    b.max_um = max_um;
    b.delta_um = delta_um;
    b.count = static_cast<std::size_t>(std::lround((max_um - min_um) / delta_um)) + 1;
    b.spectral_units = "microns";
    return b;
}

Channel shaped(ChannelShape shape, double center_um, double width_um) {
    Channel c;
    c.name = "c";
    c.shape = shape;
    c.center_um = center_um;
    c.width_um = width_um;
    return c;
}

TEST(FNumber, IsFocalLengthOverAperture) {
    const std::optional<double> f = f_number(manual_example());
    ASSERT_TRUE(f.has_value());
    EXPECT_NEAR(*f, 1.14 / 0.09, 1e-12);  // 12.666…
}

TEST(FNumber, NeedsBothLengths) {
    InstrumentProperties p = manual_example();
    p.aperture_diameter_m.reset();
    EXPECT_FALSE(f_number(p).has_value());
    EXPECT_FALSE(g_number(p).has_value());
    p = manual_example();
    p.focal_length_m.reset();
    EXPECT_FALSE(f_number(p).has_value());
    p = manual_example();
    p.aperture_diameter_m = 0.0;
    EXPECT_FALSE(f_number(p).has_value());
}

TEST(GNumber, MatchesTheManualsFormulaForItsExample) {
    const double f = 1.14 / 0.09;
    const double expected = (1.0 + 4.0 * f * f) / (1.0 * std::numbers::pi);
    const std::optional<double> g = g_number(manual_example());
    ASSERT_TRUE(g.has_value());
    EXPECT_DOUBLE_EQ(*g, expected);
    EXPECT_NEAR(*g, 204.6025, 1e-4);  // (1 + 4·12.6667²)/π
}

TEST(GNumber, ScalesWithOneOverThroughput) {
    const double g1 = *g_number(manual_example(1.0));
    const double g08 = *g_number(manual_example(0.8));
    EXPECT_DOUBLE_EQ(g08, g1 / 0.8);
    EXPECT_FALSE(g_number(manual_example(0.0)).has_value());
}

TEST(PixelIfov, IsPitchOverFocalLength) {
    InstrumentProperties p;
    p.focal_length_m = 0.05;
    DetectorArray a;
    a.x_spacing_m = 5e-6;
    a.y_spacing_m = 10e-6;
    const auto ifov = pixel_ifov_rad(p, a);
    ASSERT_TRUE(ifov.has_value());
    EXPECT_DOUBLE_EQ((*ifov)[0], 1e-4);
    EXPECT_DOUBLE_EQ((*ifov)[1], 2e-4);
    p.focal_length_m.reset();
    EXPECT_FALSE(pixel_ifov_rad(p, a).has_value());
}

TEST(BandpassGrid, HasMaxMinusMinOverDeltaPlusOneSamples) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.4, 0.8, 0.01));
    EXPECT_EQ(grid.size(), 41u);  // the manual's console output
    EXPECT_DOUBLE_EQ(grid.min_um(), 0.4);
    EXPECT_NEAR(grid.max_um(), 0.8, 1e-12);
}

TEST(BandpassGrid, InvalidBandpassThrowsAnInputError) {
    Bandpass b = bandpass(0.4, 0.8, 0.01);
    b.delta_um = 0.0;
    b.where = {"x.platform", 12, "bandpass"};
    try {
        (void)bandpass_grid(b);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_EQ(e.context().line, 12);
    }
}

TEST(ChannelResponse, GaussianHasPeakOneHalfAtHalfWidthAndTheAnalyticIntegral) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.30, 0.80, 0.0005));
    const Channel c = shaped(ChannelShape::gaussian, 0.55, 0.04);
    const std::vector<double> r = channel_response(c, grid);
    ASSERT_EQ(r.size(), grid.size());
    // 0.55 is sample 500, 0.57 (= centre + FWHM/2) sample 540.
    EXPECT_NEAR(r[500], 1.0, 1e-12);
    EXPECT_NEAR(r[540], 0.5, 1e-9);
    EXPECT_NEAR(r[460], 0.5, 1e-9);
    const double expected = 0.04 * std::sqrt(std::numbers::pi / (4.0 * std::numbers::ln2));
    EXPECT_NEAR(channel_integral_um(c, grid), expected, 1e-9);
}

TEST(ChannelResponse, TophatIntegralIsItsWidth) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.40, 0.70, 0.01));
    const Channel c = shaped(ChannelShape::tophat, 0.55, 0.10);
    const std::vector<double> r = channel_response(c, grid);
    EXPECT_DOUBLE_EQ(r[15], 1.0);   // 0.55
    EXPECT_NEAR(r[10], 0.5, 1e-9);  // 0.50, the lower edge
    EXPECT_NEAR(r[20], 0.5, 1e-9);  // 0.60, the upper edge
    EXPECT_DOUBLE_EQ(r[9], 0.0);
    EXPECT_DOUBLE_EQ(r[21], 0.0);
    EXPECT_NEAR(channel_integral_um(c, grid), 0.10, 1e-12);
}

TEST(ChannelResponse, TophatEdgesBetweenSamplesGiveTheCoveredFraction) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.40, 0.70, 0.01));
    const Channel c = shaped(ChannelShape::tophat, 0.5525, 0.05);  // edges 0.5275, 0.5775
    const std::vector<double> r = channel_response(c, grid);
    EXPECT_DOUBLE_EQ(r[12], 0.0);    // 0.52: cell [0.515, 0.525]
    EXPECT_NEAR(r[13], 0.75, 1e-9);  // 0.53: cell [0.525, 0.535], 3/4 covered
    EXPECT_DOUBLE_EQ(r[15], 1.0);    // 0.55
    EXPECT_NEAR(r[18], 0.25, 1e-9);  // 0.58: cell [0.575, 0.585], 1/4 covered
    EXPECT_DOUBLE_EQ(r[19], 0.0);
    EXPECT_NEAR(channel_integral_um(c, grid), 0.05, 1e-12);
}

TEST(ChannelResponse, TophatFillingTheBandpassIntegratesToTheBandpassWidth) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.40, 0.90, 0.01));
    const Channel c = shaped(ChannelShape::tophat, 0.65, 0.5);  // edges on the grid ends
    const std::vector<double> r = channel_response(c, grid);
    EXPECT_DOUBLE_EQ(r.front(), 1.0);
    EXPECT_DOUBLE_EQ(r.back(), 1.0);
    EXPECT_NEAR(channel_integral_um(c, grid), 0.5, 1e-12);
    // Wider than the bandpass: only the part inside counts.
    EXPECT_NEAR(channel_integral_um(shaped(ChannelShape::tophat, 0.65, 2.0), grid), 0.5, 1e-12);
}

TEST(ChannelResponse, TriangleIntegralIsHalfItsWidth) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.40, 0.70, 0.01));
    const Channel c = shaped(ChannelShape::triangle, 0.55, 0.10);
    const std::vector<double> r = channel_response(c, grid);
    EXPECT_DOUBLE_EQ(r[15], 1.0);
    EXPECT_NEAR(r[13], 0.6, 1e-12);  // 0.53: 1 − 0.02/0.05
    EXPECT_NEAR(r[10], 0.0, 1e-12);
    EXPECT_NEAR(channel_integral_um(c, grid), 0.05, 1e-12);
}

TEST(ChannelResponse, TabulatedInterpolatesLinearlyAndIsZeroOutside) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.40, 0.70, 0.01));
    Channel c;
    c.name = "t";
    c.shape = ChannelShape::tabulated;
    c.table_wavelength_um = {0.50, 0.55, 0.60};
    c.table_value = {0.0, 1.0, 0.5};
    const std::vector<double> r = channel_response(c, grid);
    EXPECT_NEAR(r[15], 1.0, 1e-12);  // 0.55
    EXPECT_NEAR(r[12], 0.4, 1e-12);  // 0.52
    EXPECT_NEAR(r[18], 0.7, 1e-12);  // 0.58
    EXPECT_DOUBLE_EQ(r[5], 0.0);     // 0.45
    EXPECT_DOUBLE_EQ(r[25], 0.0);    // 0.65
    // The table's end points count even where the grid misses them by rounding
    // (0.4 + 20 × 0.01 > 0.6): ramp 0.025 + 0.0375, plus the drop to 0 over one step.
    EXPECT_NEAR(r[20], 0.5, 1e-12);  // 0.60
    EXPECT_NEAR(channel_integral_um(c, grid), 0.025 + 0.0375 + 0.0025, 1e-12);
}

TEST(ChannelResponse, ResponsesExcludeGainAndBias) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.40, 0.70, 0.01));
    Channel c = shaped(ChannelShape::tophat, 0.55, 0.10);
    c.gain = 3.0;
    c.bias = 2.0;
    EXPECT_NEAR(channel_integral_um(c, grid), 0.10, 1e-12);
}

TEST(ChannelResponse, InvalidWidthOrTableThrowsAtTheChannel) {
    const SpectralGrid grid = bandpass_grid(bandpass(0.40, 0.70, 0.01));
    for (ChannelShape shape :
         {ChannelShape::gaussian, ChannelShape::tophat, ChannelShape::triangle}) {
        Channel c = shaped(shape, 0.55, 0.0);
        c.where = {"x.platform", 7, "channel[c]"};
        EXPECT_THROW((void)channel_response(c, grid), Error);
    }
    Channel t;
    t.shape = ChannelShape::tabulated;
    EXPECT_THROW((void)channel_response(t, grid), Error);
    t.table_wavelength_um = {0.6, 0.5};
    t.table_value = {1.0, 1.0};
    EXPECT_THROW((void)channel_response(t, grid), Error);
}

}  // namespace derived_test
}  // namespace glint::model

namespace glint::model {
namespace derived_test {

// The ENVI wavelength and fwhm of each channel shape: a gaussian's width is its FWHM, a box's
// its full width, a triangle's half its base; a table's centroid and half-peak width are
// exact for a piecewise-linear response (a symmetric triangle table: centre 0.55, FWHM 0.05).
TEST(ChannelCenterAndFwhm, FollowEachShape) {
    Channel c;
    c.center_um = 0.55;
    c.width_um = 0.1;
    c.shape = ChannelShape::gaussian;
    EXPECT_EQ(channel_center_um(c), 0.55);
    EXPECT_EQ(channel_fwhm_um(c), 0.1);
    c.shape = ChannelShape::tophat;
    EXPECT_EQ(channel_fwhm_um(c), 0.1);
    c.shape = ChannelShape::triangle;
    EXPECT_EQ(channel_fwhm_um(c), 0.05);
    c.shape = ChannelShape::tabulated;
    c.table_wavelength_um = {0.50, 0.55, 0.60};
    c.table_value = {0.0, 1.0, 0.0};
    EXPECT_NEAR(channel_center_um(c), 0.55, 1e-15);
    EXPECT_NEAR(channel_fwhm_um(c), 0.05, 1e-15);
    // Skewed: ∫λR/∫R of a right triangle 0.5 → 0.6 rising is 0.5 + 2/3 · 0.1.
    c.table_wavelength_um = {0.50, 0.60};
    c.table_value = {0.0, 1.0};
    EXPECT_NEAR(channel_center_um(c), 0.5 + 0.2 / 3.0, 1e-15);
    EXPECT_NEAR(channel_fwhm_um(c), 0.05, 1e-15);
}

}  // namespace derived_test
}  // namespace glint::model
