// SPDX-License-Identifier: Apache-2.0
// TrueSense demosaicing (pan-guided): flat colour fields exact at every size, samples kept,
// the result equal to a direct evaluation of the documented method (pan means, then
// normalized convolution of the colour differences), constant colour differences over a
// linear pan exact away from the edges, bad inputs refused.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>

#include "glint/core/error.h"
#include "glint/demosaic/demosaic.h"
#include "mosaic_support.h"

namespace glint::demosaic {
namespace truesense_test {

constexpr std::array<std::array<std::size_t, 2>, 7> kSizes = {
    {{4, 4}, {5, 4}, {4, 7}, {5, 7}, {9, 13}, {16, 16}, {17, 6}}};

const DemosaicOptions kTrueSense{CfaPattern::truesense, BayerPhase::rggb,
                                 DemosaicMethod::pan_guided};

TEST(TrueSense, FlatColourFieldIsExactAtEverySize) {
    for (const auto& [w, h] : kSizes) {
        SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
        const test::Truth truth = test::flat_truth(w, h, {1234, 3071, 517, 2900});
        const RgbImage out =
            demosaic(test::mosaic_of(truth, CfaPattern::truesense, BayerPhase::rggb), kTrueSense);
        for (std::size_t y = 0; y < h; ++y) {
            for (std::size_t x = 0; x < w; ++x) {
                for (std::size_t c = 0; c < 3; ++c) {
                    ASSERT_EQ(out.at(x, y, c), truth.at(x, y)[c])
                        << "pixel " << x << "," << y << " channel " << c;
                }
            }
        }
    }
}

TEST(TrueSense, ColourSamplesKeepTheirValue) {
    const Plane mosaic = test::random_plane(11, 9, 5);
    const RgbImage out = demosaic(mosaic, kTrueSense);
    for (std::size_t y = 0; y < 9; ++y) {
        for (std::size_t x = 0; x < 11; ++x) {
            const char l = test::filter_letter(CfaPattern::truesense, BayerPhase::rggb, x, y);
            if (l == 'P') continue;
            EXPECT_EQ(out.at(x, y, test::channel_of_letter(l)), mosaic.at(x, y));
        }
    }
}

bool inside(const Plane& m, long x, long y) {
    return x >= 0 && y >= 0 && x < static_cast<long>(m.width) && y < static_cast<long>(m.height);
}

char letter_at(long x, long y) {
    return test::filter_letter(CfaPattern::truesense, BayerPhase::rggb, static_cast<std::size_t>(x),
                               static_cast<std::size_t>(y));
}

/// The method as docs/tools/glint-demosaic.md states it, evaluated directly.
double pan_reference(const Plane& m, long x, long y) {
    if (letter_at(x, y) == 'P')
        return m.at(static_cast<std::size_t>(x), static_cast<std::size_t>(y));
    double sum = 0, n = 0;
    for (const auto& [dx, dy] :
         std::array<std::array<long, 2>, 4>{{{-1, 0}, {1, 0}, {0, -1}, {0, 1}}}) {
        if (!inside(m, x + dx, y + dy)) continue;
        sum += m.at(static_cast<std::size_t>(x + dx), static_cast<std::size_t>(y + dy));
        n += 1;
    }
    return sum / n;
}

double colour_reference(const Plane& m, long x, long y, char colour) {
    if (letter_at(x, y) == colour) {
        return m.at(static_cast<std::size_t>(x), static_cast<std::size_t>(y));
    }
    double sum = 0, weight = 0;
    for (long dy = -3; dy <= 3; ++dy) {
        for (long dx = -3; dx <= 3; ++dx) {
            if (!inside(m, x + dx, y + dy) || letter_at(x + dx, y + dy) != colour) continue;
            const double w = (4.0 - std::abs(dx)) * (4.0 - std::abs(dy));
            const double d =
                m.at(static_cast<std::size_t>(x + dx), static_cast<std::size_t>(y + dy)) -
                pan_reference(m, x + dx, y + dy);
            sum += w * d;
            weight += w;
        }
    }
    return pan_reference(m, x, y) + sum / weight;
}

TEST(TrueSense, EqualsTheDocumentedMethodEvaluatedDirectly) {
    for (const auto& [w, h] : kSizes) {
        const Plane mosaic = test::random_plane(w, h, static_cast<unsigned>(w * 7 + h));
        const RgbImage out = demosaic(mosaic, kTrueSense);
        for (long y = 0; y < static_cast<long>(h); ++y) {
            for (long x = 0; x < static_cast<long>(w); ++x) {
                for (std::size_t c = 0; c < 3; ++c) {
                    ASSERT_NEAR(out.at(static_cast<std::size_t>(x), static_cast<std::size_t>(y), c),
                                colour_reference(mosaic, x, y, "RGB"[c]), 1e-9)
                        << w << "x" << h << " pixel " << x << "," << y << " channel " << c;
                }
            }
        }
    }
}

TEST(TrueSense, ConstantColourDifferencesOverALinearPanAreExactAwayFromTheEdges) {
    test::Truth truth{21, 17, {}};
    for (std::size_t y = 0; y < truth.height; ++y) {
        for (std::size_t x = 0; x < truth.width; ++x) {
            const double pan =
                1000.0 + 37.0 * static_cast<double>(x) - 23.0 * static_cast<double>(y);
            truth.rgbp.push_back({pan + 150, pan - 80, pan - 400, pan});
        }
    }
    const RgbImage out =
        demosaic(test::mosaic_of(truth, CfaPattern::truesense, BayerPhase::rggb), kTrueSense);
    EXPECT_LT(test::mean_abs_error(out, truth, 4), 1e-9);
}

TEST(TrueSense, RefusesAnImageSmallerThanOneBlock) {
    for (const auto& [w, h] : std::array<std::array<std::size_t, 2>, 3>{{{3, 8}, {8, 3}, {2, 2}}}) {
        try {
            demosaic(test::random_plane(w, h, 1), kTrueSense);
            FAIL() << "no error for " << w << "x" << h;
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::input);
            EXPECT_NE(std::string(e.what()).find("a truesense mosaic needs at least 4 x 4 pixels"),
                      std::string::npos)
                << e.what();
        }
    }
}

TEST(TrueSense, RefusesTheBayerMethods) {
    for (DemosaicMethod method : {DemosaicMethod::bilinear, DemosaicMethod::mhc}) {
        try {
            demosaic(test::random_plane(8, 8, 1),
                     {CfaPattern::truesense, BayerPhase::rggb, method});
            FAIL() << "no error";
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::usage);
            EXPECT_NE(std::string(e.what()).find("expected pan-guided"), std::string::npos);
        }
    }
}

}  // namespace truesense_test
}  // namespace glint::demosaic
