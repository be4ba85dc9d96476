// SPDX-License-Identifier: Apache-2.0
// Tests of the index colour map: distinct, bright, deterministic label colours and black no
// data; which bands count as index bands; `convert` drawing a truth-like index band (labels
// with NaN, `glint band units`), its refusals, and no data left out of a grey stretch.
#include "glint/app_envi/colormap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "glint/app_envi/convert.h"
#include "glint/io/image.h"
#include "test_util.h"

namespace glint::app_envi {
namespace colormap_test {

namespace fs = std::filesystem;
using ColormapTest = testing::TempDirTest;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::array<int, 3> bytes_of(const std::array<double, 3>& rgb) {
    return {int(std::lround(255 * rgb[0])), int(std::lround(255 * rgb[1])),
            int(std::lround(255 * rgb[2]))};
}

TEST(IndexColour, DistinctBrightAndSeparated) {
    std::set<std::array<int, 3>> seen;
    for (int k = -1024; k < 4096; ++k) {
        const auto rgb = index_colour(k);
        EXPECT_GE(*std::max_element(rgb.begin(), rgb.end()), 0.6 - 1e-12) << k;
        EXPECT_TRUE(seen.insert(bytes_of(rgb)).second) << "8-bit colour repeated at " << k;
    }
    // The first labels of a scene are far apart in RGB.
    for (int a = 0; a < 32; ++a) {
        for (int b = a + 1; b < 32; ++b) {
            const auto p = index_colour(a);
            const auto q = index_colour(b);
            const double d = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
            EXPECT_GT(d, 0.15) << a << " vs " << b;
        }
    }
}

TEST(IndexColour, DependsOnTheRoundedValueOnly) {
    EXPECT_EQ(index_colour(3.0), index_colour(3.2));
    EXPECT_EQ(index_colour(-7.0), index_colour(-6.8));
    EXPECT_EQ(index_colour(1e15), index_colour(1e15));
    EXPECT_EQ(index_colour(0.0), (std::array<double, 3>{1.0, 0.0, 0.0}));  // hue 0: red
}

TEST(IndexColour, NoDataIsBlack) {
    const std::array<double, 3> black{0.0, 0.0, 0.0};
    EXPECT_EQ(index_colour(kNaN), black);
    EXPECT_EQ(index_colour(std::numeric_limits<double>::infinity()), black);
    EXPECT_EQ(index_colour(-std::numeric_limits<double>::infinity()), black);
    EXPECT_EQ(index_colour(1e300), black);
}

TEST(IndexBand, UnitFirstThenName) {
    EXPECT_TRUE(is_index_band("Material Index", ""));
    EXPECT_TRUE(is_index_band("instanceindex", ""));
    EXPECT_TRUE(is_index_band("whatever", "index"));
    EXPECT_TRUE(is_index_band("whatever", " Index "));
    EXPECT_FALSE(is_index_band("Material Index", "m"));  // the unit decides when given
    EXPECT_FALSE(is_index_band("Scene X", ""));
    EXPECT_FALSE(is_index_band("", ""));
}

TEST(ColormapName, RoundTrip) {
    for (Colormap c : {Colormap::automatic, Colormap::index, Colormap::none}) {
        EXPECT_EQ(colormap_from_name(colormap_name(c)), c);
    }
    EXPECT_FALSE(colormap_from_name("grey"));
}

class ColormapConvertTest : public testing::TempDirTest {
protected:
    ConvertOptions options(const fs::path& in, const std::string& out, std::size_t band) {
        ConvertOptions o;
        o.input = in;
        o.output = path(out);
        o.band = band;
        return o;
    }

    /// A 4 x 3 truth-like cube: band 0 "Material Index" (labels 0, 1, 2, 7 by column; NaN
    /// in the last line), band 1 "Scene X" (x, NaN in the last line), band 2 "Object Index".
    fs::path write_truth(const std::string& name, bool units) {
        io::EnviHeader h;
        h.band_names = {"Material Index", "Scene X", "Object Index"};
        h.set_extra("data ignore value", "NaN");
        if (units) h.set_extra("glint band units", "{index, m, index}");
        return write_cube(
            name, 4, 3, 3, io::EnviDataType::float64,
            [](std::size_t x, std::size_t y, std::size_t b) {
                if (y == 2) return kNaN;
                if (b == 0) return std::array<double, 4>{0, 1, 2, 7}[x];
                return double(x);
            },
            h);
    }
};

TEST_F(ColormapConvertTest, IndexBandGetsOneColourPerLabel) {
    const fs::path cube = write_truth("truth.img", true);
    const ConvertResult r = convert_file(options(cube, "mat.png", 0), m_ctx);
    EXPECT_TRUE(r.index_colours);
    EXPECT_TRUE(r.limits.empty());
    const io::Image png = io::read_image(path("mat.png"));
    ASSERT_EQ(png.info.channels, 3u);
    std::map<std::array<int, 3>, int> labels;
    for (std::size_t y = 0; y < 3; ++y) {
        for (std::size_t x = 0; x < 4; ++x) {
            const std::array<int, 3> c = {int(png.at(x, y, 0)), int(png.at(x, y, 1)),
                                          int(png.at(x, y, 2))};
            if (y == 2) {
                EXPECT_EQ(c, (std::array<int, 3>{0, 0, 0})) << x;  // NaN: black
                continue;
            }
            const int label = std::array<int, 4>{0, 1, 2, 7}[x];
            EXPECT_EQ(c, bytes_of(index_colour(label))) << x << "," << y;
            labels[c] = label;
        }
    }
    EXPECT_EQ(labels.size(), 4u);  // four labels, four colours

    // Without units the name decides; a 16-bit output scales the same colours.
    const fs::path bare = write_truth("bare.img", false);
    ConvertOptions o = options(bare, "obj.png", 2);
    o.bit_depth = 16;
    EXPECT_TRUE(convert_file(o, m_ctx).index_colours);
    EXPECT_EQ(io::read_image(path("obj.png")).at(3, 0, 0), std::round(65535 * index_colour(3)[0]));
}

TEST_F(ColormapConvertTest, AutoKeepsStretchAndFloatOutputs) {
    const fs::path cube = write_truth("truth.img", true);
    // Scene X is not an index band: grey min/max stretch over the finite values, NaN black.
    ConvertResult r = convert_file(options(cube, "x.png", 1), m_ctx);
    EXPECT_FALSE(r.index_colours);
    ASSERT_EQ(r.limits.size(), 1u);
    EXPECT_EQ(r.limits[0].low, 0.0);
    EXPECT_EQ(r.limits[0].high, 3.0);
    const io::Image x = io::read_image(path("x.png"));
    EXPECT_EQ(x.info.channels, 1u);
    EXPECT_EQ(x.at(3, 0, 0), 255.0);
    EXPECT_EQ(x.at(3, 2, 0), 0.0);
    // A stretch option, --colormap none or a float output keep the values grey.
    ConvertOptions o = options(cube, "p.png", 0);
    o.percent = 0;
    EXPECT_FALSE(convert_file(o, m_ctx).index_colours);
    o = options(cube, "n.png", 0);
    o.colormap = Colormap::none;
    EXPECT_FALSE(convert_file(o, m_ctx).index_colours);
    EXPECT_FALSE(convert_file(options(cube, "m.exr", 0), m_ctx).index_colours);
    // --colormap index forces it on any band, for float outputs in [0, 1].
    o = options(cube, "f.exr", 1);
    o.colormap = Colormap::index;
    EXPECT_TRUE(convert_file(o, m_ctx).index_colours);
    EXPECT_FLOAT_EQ(float(io::read_image(path("f.exr")).at(2, 0, 1)), float(index_colour(2)[1]));
}

TEST_F(ColormapConvertTest, FiniteIgnoreValueIsNoData) {
    // uint8 labels with data ignore value 255: those pixels are black, not a label colour,
    // and left out of a grey stretch.
    io::EnviHeader h;
    h.band_names = {"Class Index"};
    h.set_extra("data ignore value", "255");
    const fs::path cube = write_cube(
        "c.img", 3, 1, 1, io::EnviDataType::uint8,
        [](std::size_t x, std::size_t, std::size_t) {
            return std::array<double, 3>{4, 255, 9}[x];
        },
        h);
    convert_file(options(cube, "c.png", 0), m_ctx);
    const io::Image png = io::read_image(path("c.png"));
    EXPECT_EQ(png.at(1, 0, 0) + png.at(1, 0, 1) + png.at(1, 0, 2), 0.0);
    EXPECT_EQ(png.at(0, 0, 0), bytes_of(index_colour(4))[0]);
    ConvertOptions o = options(cube, "g.png", 0);
    o.colormap = Colormap::none;
    const ConvertResult r = convert_file(o, m_ctx);
    EXPECT_EQ(r.limits[0].low, 4.0);
    EXPECT_EQ(r.limits[0].high, 9.0);
    EXPECT_EQ(io::read_image(path("g.png")).at(1, 0, 0), 0.0);
}

TEST_F(ColormapConvertTest, ContradictionsAreUsageErrors) {
    const fs::path cube = write_truth("truth.img", true);
    auto expect_usage = [&](ConvertOptions o, const std::string& needle) {
        o.colormap = Colormap::index;
        testing::expect_usage_error([&] { convert_file(o, m_ctx); }, needle);
        EXPECT_FALSE(fs::exists(o.output));
    };
    ConvertOptions o = options(cube, "o.png", 0);
    o.band.reset();
    o.bands = {0, 1, 2};
    expect_usage(o, "--colormap index colours one band; 3 are selected");
    o = options(cube, "o.png", 0);
    o.band.reset();  // default selection of a 3-band file: 0, 1, 2
    expect_usage(o, "3 are selected (choose one with --band N)");
    o = options(cube, "o.png", 0);
    o.gamma = 2.2;
    expect_usage(o, "it excludes --percent, --min/--max, --per-band, --gamma and --raw");
    o = options(cube, "o.png", 0);
    o.raw = true;
    expect_usage(o, "it excludes");
    expect_usage(options(cube, "o.img", 0), "--colormap index applies to image outputs");
    EXPECT_TRUE(temporaries().empty());
}

}  // namespace colormap_test
}  // namespace glint::app_envi
