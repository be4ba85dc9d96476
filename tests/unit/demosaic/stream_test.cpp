// SPDX-License-Identifier: Apache-2.0
// DemosaicStream: each mosaic line read once and in order, for every method and the sizes
// where mirroring folds more than once; the window of lines stays within bytes_held whatever
// the height; the output equals the whole-image functions to the bit; misuse refused.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <vector>

#include "glint/core/error.h"
#include "glint/demosaic/demosaic.h"
#include "mosaic_support.h"

namespace glint::demosaic {
namespace stream_test {

constexpr std::array<DemosaicOptions, 3> kMethods = {
    {{CfaPattern::bayer, BayerPhase::grbg, DemosaicMethod::bilinear},
     {CfaPattern::bayer, BayerPhase::bggr, DemosaicMethod::mhc},
     {CfaPattern::truesense, BayerPhase::rggb, DemosaicMethod::pan_guided}}};

/// A mosaic line reader over `plane` that records the lines asked for.
MosaicLineReader recording_reader(const Plane& plane, std::vector<std::size_t>& asked) {
    return [&plane, &asked](std::size_t y, std::span<double> out) {
        asked.push_back(y);
        ASSERT_EQ(out.size(), plane.width);
        for (std::size_t x = 0; x < plane.width; ++x) out[x] = plane.at(x, y);
    };
}

TEST(DemosaicStream, ReadsEachLineOnceInOrderAndMatchesTheWholeImage) {
    for (const DemosaicOptions& options : kMethods) {
        const std::size_t period = cfa_period(options.pattern);
        for (std::size_t height = period; height <= 13; ++height) {
            for (std::size_t width : {period, period + 1, std::size_t{11}}) {
                SCOPED_TRACE(std::string(demosaic_method_name(options.method)) + " " +
                             std::to_string(width) + " x " + std::to_string(height));
                const Plane mosaic = test::random_plane(width, height, 7 + height);
                const RgbImage whole = demosaic(mosaic, options);
                std::vector<std::size_t> asked;
                DemosaicStream stream(width, height, options, recording_reader(mosaic, asked));
                std::vector<double> line(width * 3);
                for (std::size_t y = 0; y < height; ++y) {
                    stream.next_line(line);
                    // Bitwise: the stream and the whole image sum in the same order.
                    ASSERT_EQ(std::memcmp(line.data(), whole.rgb.data() + y * width * 3,
                                          line.size() * sizeof(double)),
                              0)
                        << "line " << y;
                }
                std::vector<std::size_t> expected(height);
                for (std::size_t y = 0; y < height; ++y) expected[y] = y;
                EXPECT_EQ(asked, expected);
            }
        }
    }
}

TEST(DemosaicStream, ReadsAheadOnlyAsFarAsTheKernelsReach) {
    // Output line y of a tall image needs mosaic lines up to y + 2 (Bayer) or y + 4
    // (pan-guided: pan at y + 3 for the difference filter, pan needing the line below).
    for (const DemosaicOptions& options : kMethods) {
        const std::size_t reach = options.pattern == CfaPattern::bayer ? 2 : 4;
        const Plane mosaic = test::random_plane(12, 40, 3);
        std::vector<std::size_t> asked;
        DemosaicStream stream(12, 40, options, recording_reader(mosaic, asked));
        std::vector<double> line(12 * 3);
        for (std::size_t y = 0; y < 30; ++y) {
            stream.next_line(line);
            EXPECT_EQ(asked.size(), y + reach + 1) << demosaic_method_name(options.method);
        }
    }
}

TEST(DemosaicStream, HoldsAFewLinesOfTheWidth) {
    // bytes_held depends on the width only: a handful of lines (Bayer: 5 mosaic lines and a
    // spare; pan-guided: mosaic, pan and six filtered values per pixel over 7 lines).
    for (const DemosaicOptions& options : kMethods) {
        const std::size_t line_bytes = 1000 * sizeof(double);
        const std::size_t held = DemosaicStream::bytes_held(1000, options.method);
        EXPECT_GE(held, 5 * line_bytes) << demosaic_method_name(options.method);
        EXPECT_LE(held, 64 * line_bytes) << demosaic_method_name(options.method);
        EXPECT_LE(DemosaicStream::bytes_held(2000, options.method), 2 * held);
    }
}

TEST(DemosaicStream, RefusesMisuse) {
    const Plane mosaic = test::random_plane(4, 4, 1);
    std::vector<std::size_t> asked;
    DemosaicStream stream(4, 4, kMethods[0], recording_reader(mosaic, asked));
    std::vector<double> short_line(4 * 3 - 1);
    EXPECT_THROW(stream.next_line(short_line), Error);
    std::vector<double> line(4 * 3);
    for (int y = 0; y < 4; ++y) stream.next_line(line);
    try {
        stream.next_line(line);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::internal);
    }
    try {
        DemosaicStream small(3, 5, kMethods[2], recording_reader(mosaic, asked));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::input);
        EXPECT_NE(std::string(e.what()).find("needs at least 4 x 4 pixels"), std::string::npos)
            << e.what();
    }
}

}  // namespace stream_test
}  // namespace glint::demosaic
