// SPDX-License-Identifier: Apache-2.0
// Tests of `convert`: ENVI → TIFF(float) → ENVI round trip, stretch numbers in PNG outputs,
// band selection, default types and bands, and the refusals (overwrite, bad options,
// malformed input) that must leave no output behind.
#include "glint/app_envi/convert.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "glint/core/error.h"
#include "glint/io/image.h"
#include "test_util.h"

namespace glint::app_envi {
namespace convert_test {

namespace fs = std::filesystem;
using ConvertTest = testing::TempDirTest;

double ramp(std::size_t x, std::size_t y, std::size_t b) {
    return 0.25 * double(x) - 3.0 * double(y) + 100.0 * double(b) + 0.125;
}

ConvertOptions options_for(const fs::path& in, const fs::path& out) {
    ConvertOptions o;
    o.input = in;
    o.output = out;
    return o;
}

TEST_F(ConvertTest, EnviTiffFloatEnviRoundTrip) {
    io::EnviHeader header;
    header.band_names = {"a", "b", "c"};
    const auto cube = write_cube("cube.img", 7, 5, 3, io::EnviDataType::float32, ramp, header);
    ConvertOptions to_tiff = options_for(cube, path("cube.tif"));
    to_tiff.bit_depth = 32;
    const ConvertResult r1 = convert_file(to_tiff, m_ctx);
    EXPECT_TRUE(r1.limits.empty());  // float output: values unchanged
    EXPECT_EQ(r1.stored_type, "float");
    const ConvertResult r2 = convert_file(options_for(path("cube.tif"), path("back.img")), m_ctx);
    EXPECT_EQ(r2.stored_type, "float32");

    io::EnviHeader h1;
    io::EnviHeader h2;
    const auto original = io::read_envi_bip(cube, &h1);
    const auto back = io::read_envi_bip(path("back.img"), &h2);
    EXPECT_EQ(h2.samples, 7u);
    EXPECT_EQ(h2.lines, 5u);
    EXPECT_EQ(h2.bands, 3u);
    EXPECT_EQ(h2.data_type, io::EnviDataType::float32);
    EXPECT_EQ(original, back);
    EXPECT_EQ(h2.find_extra("glint tool"), "glint-envi convert");
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ConvertTest, EnviExrKeepsBandNamesAsChannels) {
    io::EnviHeader header;
    header.band_names = {"red", "nir"};
    const auto cube = write_cube("cube.img", 4, 3, 2, io::EnviDataType::float32, ramp, header);
    ConvertOptions o = options_for(cube, path("cube.exr"));
    o.bands = {0, 1};
    convert_file(o, m_ctx);
    convert_file(options_for(path("cube.exr"), path("back.img")), m_ctx);
    io::EnviHeader back;
    const auto values = io::read_envi_bip(path("back.img"), &back);
    EXPECT_EQ(back.band_names, (std::vector<std::string>{"red", "nir"}));
    EXPECT_EQ(values, io::read_envi_bip(cube, nullptr));
}

TEST_F(ConvertTest, DefaultMinMaxStretchToPng) {
    // One band, values 0..9 along x: min 0 → 0, max 9 → 255, 3 → round(255/3) = 85.
    const auto cube = write_cube("g.img", 10, 2, 1, io::EnviDataType::float64,
                                 [](std::size_t x, std::size_t, std::size_t) { return double(x); });
    const ConvertResult r = convert_file(options_for(cube, path("g.png")), m_ctx);
    ASSERT_EQ(r.limits.size(), 1u);
    EXPECT_EQ(r.limits[0].low, 0.0);
    EXPECT_EQ(r.limits[0].high, 9.0);
    const io::Image png = io::read_image(path("g.png"));
    EXPECT_EQ(png.info.channels, 1u);
    EXPECT_EQ(png.info.sample_type, io::SampleType::uint8);
    for (std::size_t x = 0; x < 10; ++x) {
        EXPECT_EQ(png.at(x, 1, 0), std::round(255.0 * double(x) / 9.0)) << x;
    }
}

TEST_F(ConvertTest, PercentStretchJointAndPerBand) {
    // Band 0 holds 0..99, band 1 holds 1000..1099 (one value per pixel, 100 x 1).
    const auto cube = write_cube(
        "p.img", 100, 1, 2, io::EnviDataType::float32,
        [](std::size_t x, std::size_t, std::size_t b) { return double(x) + 1000.0 * double(b); });
    ConvertOptions o = options_for(cube, path("p.png"));
    o.bands = {0, 1, 1};
    o.percent = 2.0;
    o.per_band = true;
    ConvertResult r = convert_file(o, m_ctx);
    ASSERT_EQ(r.limits.size(), 3u);
    // n = 100, q = 0.02: ranks 1 and 98.
    EXPECT_EQ(r.limits[0].low, 1.0);
    EXPECT_EQ(r.limits[0].high, 98.0);
    EXPECT_EQ(r.limits[1].low, 1001.0);
    EXPECT_EQ(r.limits[1].high, 1098.0);
    io::Image png = io::read_image(path("p.png"));
    EXPECT_EQ(png.at(0, 0, 0), 0.0);     // clipped below
    EXPECT_EQ(png.at(99, 0, 0), 255.0);  // clipped above
    EXPECT_EQ(png.at(50, 0, 0), std::round(255.0 * 49.0 / 97.0));
    EXPECT_EQ(png.at(50, 0, 1), std::round(255.0 * 49.0 / 97.0));

    // Joint: the set is the selected channels 0, 1, 1 (band 1 counted once per channel),
    // 300 values: 0..99, then 1000, 1000, 1001, 1001, ... Ranks floor(0.02 * 299) = 5 → 5
    // and ceil(0.98 * 299) = 294 → 1000 + (294 - 100) / 2 = 1097.
    fs::remove(path("p.png"));
    o.per_band = false;
    r = convert_file(o, m_ctx);
    EXPECT_EQ(r.limits[0].low, 5.0);
    EXPECT_EQ(r.limits[0].high, 1097.0);
    EXPECT_EQ(r.limits[2].low, 5.0);
}

TEST_F(ConvertTest, FixedStretchGammaAnd16Bit) {
    const auto cube = write_cube("f.img", 3, 1, 1, io::EnviDataType::float64,
                                 [](std::size_t x, std::size_t, std::size_t) {
                                     return std::vector<double>{-1.0, 0.25, 2.0}[x];
                                 });
    ConvertOptions o = options_for(cube, path("f.png"));
    o.min = 0.0;
    o.max = 1.0;
    o.gamma = 2.0;
    o.bit_depth = 16;
    convert_file(o, m_ctx);
    const io::Image png = io::read_image(path("f.png"));
    EXPECT_EQ(png.info.sample_type, io::SampleType::uint16);
    EXPECT_EQ(png.at(0, 0, 0), 0.0);
    EXPECT_EQ(png.at(1, 0, 0), std::round(65535.0 * 0.5));  // 0.25^(1/2)
    EXPECT_EQ(png.at(2, 0, 0), 65535.0);
}

TEST_F(ConvertTest, BandSelection) {
    const auto cube =
        write_cube("s.img", 4, 2, 3, io::EnviDataType::uint8,
                   [](std::size_t x, std::size_t, std::size_t b) { return double(10 * b + x); });
    ConvertOptions one = options_for(cube, path("one.tif"));
    one.band = 2;
    one.raw = true;
    convert_file(one, m_ctx);
    io::Image tif = io::read_image(path("one.tif"));
    ASSERT_EQ(tif.info.channels, 1u);
    EXPECT_EQ(tif.at(3, 1, 0), 23.0);

    ConvertOptions swap = options_for(cube, path("swap.img"));
    swap.bands = {2, 0};
    const ConvertResult r = convert_file(swap, m_ctx);
    EXPECT_EQ(r.stored_type, "uint8");
    io::EnviHeader h;
    const auto values = io::read_envi_bip(path("swap.img"), &h);
    ASSERT_EQ(h.bands, 2u);
    EXPECT_EQ(values[0], 20.0);
    EXPECT_EQ(values[1], 0.0);
    EXPECT_EQ(values[2 * 3 + 0], 23.0);

    ConvertOptions bad = options_for(cube, path("bad.png"));
    bad.band = 3;
    try {
        convert_file(bad, m_ctx);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_NE(std::string(e.what()).find("band 3 does not exist"), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(path("bad.png")));
}

TEST_F(ConvertTest, DefaultRgbBandsByWavelength) {
    io::EnviHeader header;
    header.wavelength_units = "Nanometers";
    header.wavelength = {400, 460, 550, 640, 800};
    const auto cube = write_cube("w.img", 2, 2, 5, io::EnviDataType::float32, ramp, header);
    const ConvertResult r = convert_file(options_for(cube, path("w.png")), m_ctx);
    EXPECT_EQ(r.bands, (std::vector<std::size_t>{3, 2, 1}));
}

TEST_F(ConvertTest, ImageTypesMapToEnviTypes) {
    std::vector<double> pixels(6 * 4 * 3);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = double(i * 1000 % 65536);
    io::ImageWriteOptions w;
    w.format = io::ImageFormat::png;
    w.pixel_type = io::PixelType::uint16;
    io::write_image(path("in16.png"), 6, 4, 3, pixels, w);
    const ConvertResult r = convert_file(options_for(path("in16.png"), path("o16.img")), m_ctx);
    EXPECT_EQ(r.stored_type, "uint16");
    io::EnviHeader h;
    EXPECT_EQ(io::read_envi_bip(path("o16.img"), &h), pixels);
    EXPECT_EQ(h.band_names, (std::vector<std::string>{"R", "G", "B"}));

    w.format = io::ImageFormat::exr;
    w.pixel_type = io::PixelType::half;
    std::vector<double> halves(6 * 4 * 3, 0.5);
    io::write_image(path("h.exr"), 6, 4, 3, halves, w);
    ConvertOptions o = options_for(path("h.exr"), path("h.img"));
    EXPECT_EQ(convert_file(o, m_ctx).stored_type, "float32");
    o.output = path("h64.img");
    o.data_type = io::EnviDataType::float64;
    EXPECT_EQ(convert_file(o, m_ctx).stored_type, "float64");
}

TEST_F(ConvertTest, RefusalsLeaveNoOutput) {
    const auto cube = write_cube("c.img", 2, 2, 1, io::EnviDataType::uint8,
                                 [](std::size_t, std::size_t, std::size_t) { return 1.0; });
    auto expect_usage = [&](const ConvertOptions& o, const std::string& needle) {
        testing::expect_usage_error([&] { convert_file(o, m_ctx); }, needle);
    };
    expect_usage(options_for(cube, cube), "refusing to overwrite input");
    expect_usage(options_for(cube, path("c.img.hdr")), "cannot tell the output format");
    ConvertOptions o = options_for(cube, path("o.png"));
    o.percent = 60;
    expect_usage(o, "--percent");
    o = options_for(cube, path("o.png"));
    o.min = 1;
    expect_usage(o, "--min and --max");
    o = options_for(cube, path("o.img"));
    o.percent = 2;
    expect_usage(o, "ENVI outputs keep the values");
    o = options_for(cube, path("o.jpg"));
    o.bit_depth = 16;
    expect_usage(o, "cannot store a bit depth of 16");
    o = options_for(cube, path("o.png"));
    o.format = "gif";
    expect_usage(o, "unknown output format");

    std::ofstream(path("bad.img.hdr")) << "ENVI\nsamples = 2\nlines = 2\nbands = 1\n"
                                          "data type = 99\n";
    std::ofstream(path("bad.img")) << "abcd";
    EXPECT_THROW(convert_file(options_for(path("bad.img"), path("bad.png")), m_ctx), Error);
    EXPECT_FALSE(fs::exists(path("o.png")));
    EXPECT_FALSE(fs::exists(path("bad.png")));
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ConvertTest, CancelledRunLeavesNothing) {
    const auto cube = write_cube("c.img", 8, 8, 1, io::EnviDataType::uint8,
                                 [](std::size_t, std::size_t, std::size_t) { return 1.0; });
    m_ctx.cancel.cancel();
    try {
        convert_file(options_for(cube, path("c.png")), m_ctx);
        FAIL() << "expected cancellation";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::cancelled);
    }
    EXPECT_FALSE(fs::exists(path("c.png")));
    EXPECT_TRUE(temporaries().empty());
}

}  // namespace convert_test
}  // namespace glint::app_envi
