// SPDX-License-Identifier: Apache-2.0
// Tests of io::ImageReader / io::ImageWriter (glint/io/image.h; image_reader.cpp,
// image_writer.cpp, image_types.cpp): round trips per format and pixel type, code values,
// clamping, errors naming the file, and atomic output.
#include "glint/io/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "glint/core/error.h"
#include "glint/test/temp_dir.h"

namespace glint::io {
namespace image_test {

namespace fs = std::filesystem;
/// A fresh folder per test, removed after it.
class ImageTest : public ::testing::Test {
protected:
    std::filesystem::path path(const std::string& name) const { return m_temp / name; }

    /// Names in the folder containing ".tmp-" (temporary files that should be gone).
    std::vector<std::string> temporaries() const {
        std::vector<std::string> found;
        for (const std::string& name : m_temp.entries()) {
            if (name.find(".tmp-") != std::string::npos) found.push_back(name);
        }
        return found;
    }

private:
    glint::test::TempDir m_temp;
};

std::vector<double> pattern(std::size_t w, std::size_t h, std::size_t c, double scale) {
    std::vector<double> v(w * h * c);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = std::fmod(double(i) * 7.0, scale + 1.0);
    return v;
}

TEST_F(ImageTest, RoundTripsKeepCodeValues) {
    struct Case {
        ImageFormat format;
        PixelType type;
        std::size_t channels;
        double scale;
        const char* name;
        SampleType read_back;
    };
    const Case cases[] = {
        {ImageFormat::png, PixelType::uint8, 3, 255, "a.png", SampleType::uint8},
        {ImageFormat::png, PixelType::uint16, 1, 65535, "b.png", SampleType::uint16},
        {ImageFormat::png, PixelType::uint8, 4, 255, "rgba.png", SampleType::uint8},
        {ImageFormat::tiff, PixelType::uint16, 2, 65535, "c.tif", SampleType::uint16},
        {ImageFormat::tiff, PixelType::float32, 5, 1000, "d.tiff", SampleType::float32},
        {ImageFormat::exr, PixelType::float32, 3, 1000, "e.exr", SampleType::float32},
        {ImageFormat::exr, PixelType::half, 3, 1000, "f.exr", SampleType::half},
        {ImageFormat::ppm, PixelType::uint8, 3, 255, "g.ppm", SampleType::uint8},
        {ImageFormat::ppm, PixelType::uint8, 1, 255, "h.pgm", SampleType::uint8},
    };
    for (const Case& c : cases) {
        const auto pixels = pattern(5, 3, c.channels, c.scale);
        ImageWriteOptions options;
        options.format = c.format;
        options.pixel_type = c.type;
        write_image(path(c.name), 5, 3, c.channels, pixels, options);
        const Image image = read_image(path(c.name));
        EXPECT_EQ(image.info.width, 5u) << c.name;
        EXPECT_EQ(image.info.height, 3u) << c.name;
        EXPECT_EQ(image.info.channels, c.channels) << c.name;
        EXPECT_EQ(image.info.sample_type, c.read_back) << c.name;
        EXPECT_EQ(image.pixels, pixels) << c.name;  // all values are exact in half too
    }
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ImageTest, JpegIsLossyButClose) {
    std::vector<double> pixels(16 * 8 * 3, 128.0);
    ImageWriteOptions options;
    options.format = ImageFormat::jpeg;
    write_image(path("x.jpg"), 16, 8, 3, pixels, options);
    const Image image = read_image(path("x.jpg"));
    for (double v : image.pixels) EXPECT_NEAR(v, 128.0, 2.0);
}

TEST_F(ImageTest, IntegerOutputsRoundAndClamp) {
    const std::vector<double> pixels{-5.0, 0.4, 0.6, 254.5, 300.0, std::nan("")};
    ImageWriteOptions options;
    write_image(path("c.png"), 6, 1, 1, pixels, options);
    const Image image = read_image(path("c.png"));
    EXPECT_EQ(image.pixels, (std::vector<double>{0, 0, 1, 254, 255, 0}));  // ties to even
}

TEST_F(ImageTest, ChannelNamesAreWrittenToExr) {
    ImageWriteOptions options;
    options.format = ImageFormat::exr;
    options.pixel_type = PixelType::float32;
    options.channel_names = {"red", "nir"};
    write_image(path("n.exr"), 2, 2, 2, std::vector<double>(8, 1.0), options);
    // OpenEXR stores channels sorted by name.
    const Image image = read_image(path("n.exr"));
    EXPECT_EQ(image.info.channel_names.size(), 2u);
    EXPECT_NE(std::find(image.info.channel_names.begin(), image.info.channel_names.end(), "nir"),
              image.info.channel_names.end());
}

TEST_F(ImageTest, FormatNamesAndCapabilities) {
    EXPECT_EQ(image_format_from_name("JPG"), ImageFormat::jpeg);
    EXPECT_EQ(image_format_from_name("tif"), ImageFormat::tiff);
    EXPECT_EQ(image_format_from_name("pgm"), ImageFormat::ppm);
    EXPECT_FALSE(image_format_from_name("gif").has_value());
    EXPECT_EQ(image_format_from_extension("a/b.EXR"), ImageFormat::exr);
    EXPECT_FALSE(image_format_from_extension("a/b").has_value());
    EXPECT_EQ(pixel_type_for_bit_depth(ImageFormat::exr, 16), PixelType::half);
    EXPECT_EQ(pixel_type_for_bit_depth(ImageFormat::png, 16), PixelType::uint16);
    EXPECT_FALSE(pixel_type_for_bit_depth(ImageFormat::jpeg, 16).has_value());
    EXPECT_FALSE(pixel_type_for_bit_depth(ImageFormat::png, 32).has_value());
    EXPECT_FALSE(pixel_type_for_bit_depth(ImageFormat::exr, 8).has_value());
    EXPECT_FALSE(pixel_type_for_bit_depth(ImageFormat::ppm, 16).has_value());
    EXPECT_EQ(default_pixel_type(ImageFormat::exr), PixelType::float32);
}

TEST_F(ImageTest, ErrorsNameTheFile) {
    try {
        read_image(path("missing.png"));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
    }
    std::ofstream(path("junk.png")) << "not a png at all";
    try {
        read_image(path("junk.png"));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("junk.png"), std::string::npos) << e.what();
    }
    ImageWriteOptions jpeg;
    jpeg.format = ImageFormat::jpeg;
    EXPECT_THROW(ImageWriter(path("two.jpg"), 2, 2, 2, jpeg), Error);  // 2 channels
    jpeg.pixel_type = PixelType::float32;
    EXPECT_THROW(ImageWriter(path("f.jpg"), 2, 2, 3, jpeg), Error);
    ImageWriteOptions png;
    EXPECT_THROW(ImageWriter(path("no/such/folder/x.png"), 2, 2, 1, png), Error);
    EXPECT_FALSE(fs::exists(path("two.jpg")));
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ImageTest, UncommittedWriterLeavesNothing) {
    {
        ImageWriter writer(path("half.png"), 4, 4, 1, ImageWriteOptions{});
        writer.write_line(std::vector<double>(4, 1.0));
    }
    EXPECT_FALSE(fs::exists(path("half.png")));
    EXPECT_TRUE(temporaries().empty());
}

}  // namespace image_test
}  // namespace glint::io
