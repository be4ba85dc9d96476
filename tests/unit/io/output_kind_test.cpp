// SPDX-License-Identifier: Apache-2.0
// Tests of the output kind of raster tools: by format name, by extension, and the errors
// when neither tells.
#include "glint/io/output_kind.h"

#include <gtest/gtest.h>

#include <string>

#include "glint/core/error.h"

namespace glint::io {
namespace output_kind_test {

TEST(OutputKind, FromNameAcceptsImageSpellingsAndEnvi) {
    EXPECT_EQ(output_kind_from_name("ENVI"), OutputKind::envi);
    EXPECT_EQ(output_kind_from_name("png"), OutputKind::png);
    EXPECT_EQ(output_kind_from_name("tif"), OutputKind::tiff);
    EXPECT_EQ(output_kind_from_name("JPG"), OutputKind::jpeg);
    EXPECT_EQ(output_kind_from_name("openexr"), OutputKind::exr);
    EXPECT_EQ(output_kind_from_name("pgm"), OutputKind::ppm);
    EXPECT_EQ(output_kind_from_name("bmp"), std::nullopt);
}

TEST(OutputKind, ExplicitFormatWinsOverTheExtension) {
    EXPECT_EQ(output_kind_of("out.img", "png"), OutputKind::png);
    EXPECT_EQ(output_kind_of("out.png", "envi"), OutputKind::envi);
}

TEST(OutputKind, ExtensionsTellImagesAndEnvi) {
    EXPECT_EQ(output_kind_of("a/out.TIFF", ""), OutputKind::tiff);
    EXPECT_EQ(output_kind_of("out.jpeg", ""), OutputKind::jpeg);
    for (const char* name : {"x.img", "x.dat", "x.raw", "x.bsq", "x.bil", "x.BIP", "x.envi"}) {
        EXPECT_EQ(output_kind_of(name, ""), OutputKind::envi) << name;
    }
}

TEST(OutputKind, UnknownNamesAreUsageErrors) {
    try {
        output_kind_of("out.img", "gif");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_EQ(e.message(),
                  "unknown output format 'gif' (expected png, tiff, jpeg, exr, ppm or envi)");
    }
    try {
        output_kind_of("out.xyz", "");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_EQ(e.message(),
                  "cannot tell the output format from the name out.xyz; use --format "
                  "png|tiff|jpeg|exr|ppm|envi");
    }
}

TEST(OutputKind, ImageFormatOfEachImageKind) {
    EXPECT_EQ(image_format_of(OutputKind::png), ImageFormat::png);
    EXPECT_EQ(image_format_of(OutputKind::tiff), ImageFormat::tiff);
    EXPECT_EQ(image_format_of(OutputKind::jpeg), ImageFormat::jpeg);
    EXPECT_EQ(image_format_of(OutputKind::exr), ImageFormat::exr);
    EXPECT_EQ(image_format_of(OutputKind::ppm), ImageFormat::ppm);
    EXPECT_THROW(image_format_of(OutputKind::envi), Error);
}

TEST(OutputKind, PixelTypeByDefaultOrBitDepth) {
    EXPECT_EQ(output_pixel_type(ImageFormat::png, std::nullopt, "a.png"), PixelType::uint8);
    EXPECT_EQ(output_pixel_type(ImageFormat::exr, std::nullopt, "a.exr"), PixelType::float32);
    EXPECT_EQ(output_pixel_type(ImageFormat::png, 16, "a.png"), PixelType::uint16);
    EXPECT_EQ(output_pixel_type(ImageFormat::exr, 16, "a.exr"), PixelType::half);
    EXPECT_EQ(output_pixel_type(ImageFormat::tiff, 32, "a.tif"), PixelType::float32);
    try {
        output_pixel_type(ImageFormat::jpeg, 16, "out/a.jpg");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_EQ(e.message(), "jpeg cannot store a bit depth of 16 (out/a.jpg)");
    }
}

}  // namespace output_kind_test
}  // namespace glint::io
