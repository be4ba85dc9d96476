// SPDX-License-Identifier: Apache-2.0
// Bayer demosaicing: flat colour fields exact for every phase and size (borders included),
// samples kept at their own pixels, bilinear equal to averaging the neighbours that exist,
// MHC equal to the 5×5 kernels of H. S. Malvar, L.-W. He and R. Cutler, "High-quality linear
// interpolation for demosaicing of Bayer-patterned color images", ICASSP 2004 (Figure 2;
// docs/references.md) over a reflect-101 mirrored image, linear ramps exact away from the
// edges, MHC better than bilinear on a colour edge chart, bad inputs refused.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <iostream>

#include "glint/core/error.h"
#include "glint/demosaic/demosaic.h"
#include "mosaic_support.h"

namespace glint::demosaic {
namespace bayer_test {

using test::kPhases;

constexpr std::array<std::array<std::size_t, 2>, 8> kSizes = {
    {{2, 2}, {3, 2}, {2, 3}, {3, 3}, {5, 7}, {8, 6}, {9, 11}, {16, 13}}};

RgbImage run(DemosaicMethod method, const Plane& mosaic, BayerPhase phase) {
    return demosaic(mosaic, DemosaicOptions{CfaPattern::bayer, phase, method});
}

TEST(Bayer, FlatColourFieldIsExactForEveryPhaseMethodAndSize) {
    for (DemosaicMethod method : {DemosaicMethod::bilinear, DemosaicMethod::mhc}) {
        for (BayerPhase phase : kPhases) {
            for (const auto& [w, h] : kSizes) {
                SCOPED_TRACE(std::string(demosaic_method_name(method)) + " " +
                             bayer_phase_name(phase) + " " + std::to_string(w) + "x" +
                             std::to_string(h));
                const test::Truth truth = test::flat_truth(w, h, {1234, 3071, 517, 0});
                const RgbImage out =
                    run(method, test::mosaic_of(truth, CfaPattern::bayer, phase), phase);
                ASSERT_EQ(out.width, w);
                ASSERT_EQ(out.height, h);
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
    }
}

TEST(Bayer, SamplesKeepTheirValueAtTheirOwnPixels) {
    for (DemosaicMethod method : {DemosaicMethod::bilinear, DemosaicMethod::mhc}) {
        for (BayerPhase phase : kPhases) {
            const Plane mosaic = test::random_plane(7, 9, 3);
            const RgbImage out = run(method, mosaic, phase);
            for (std::size_t y = 0; y < 9; ++y) {
                for (std::size_t x = 0; x < 7; ++x) {
                    const std::size_t c = test::channel_of_letter(
                        test::filter_letter(CfaPattern::bayer, phase, x, y));
                    EXPECT_EQ(out.at(x, y, c), mosaic.at(x, y));
                }
            }
        }
    }
}

/// Reflect-101 by repeated reflection (independent of the library's formula).
long mirror(long i, long n) {
    while (i < 0 || i >= n) {
        if (i < 0) i = -i;
        if (i >= n) i = 2 * (n - 1) - i;
    }
    return i;
}

/// Bilinear by definition: the mean of the nearest samples of the wanted colour in the 3×3
/// neighbourhood of the mirrored image (edge neighbours when there are any, else corners).
double bilinear_reference(const Plane& m, BayerPhase phase, std::size_t x, std::size_t y,
                          std::size_t channel) {
    const long lx = static_cast<long>(x), ly = static_cast<long>(y);
    auto chan = [&](long xx, long yy) {
        return test::channel_of_letter(test::filter_letter(
            CfaPattern::bayer, phase, static_cast<std::size_t>(xx), static_cast<std::size_t>(yy)));
    };
    auto value = [&](long xx, long yy) {
        return m.at(static_cast<std::size_t>(mirror(xx, static_cast<long>(m.width))),
                    static_cast<std::size_t>(mirror(yy, static_cast<long>(m.height))));
    };
    if (chan(lx, ly) == channel) return m.at(x, y);
    for (const bool edges : {true, false}) {
        double sum = 0, n = 0;
        for (long dy = -1; dy <= 1; ++dy) {
            for (long dx = -1; dx <= 1; ++dx) {
                const bool is_edge = (dx == 0) != (dy == 0);
                if (is_edge != edges || (dx == 0 && dy == 0)) continue;
                // the layout repeats every 2 pixels, so the filter at (x+dx, y+dy) is the
                // filter of its mirror image
                if (chan(lx + dx + 2, ly + dy + 2) != channel) continue;
                sum += value(lx + dx, ly + dy);
                n += 1;
            }
        }
        if (n > 0) return sum / n;
    }
    return -1;
}

TEST(Bayer, BilinearAveragesTheNearestSamplesOfTheMirroredImage) {
    for (BayerPhase phase : kPhases) {
        for (const auto& [w, h] : kSizes) {
            const Plane mosaic = test::random_plane(w, h, static_cast<unsigned>(w * 31 + h));
            const RgbImage out = run(DemosaicMethod::bilinear, mosaic, phase);
            for (std::size_t y = 0; y < h; ++y) {
                for (std::size_t x = 0; x < w; ++x) {
                    for (std::size_t c = 0; c < 3; ++c) {
                        ASSERT_DOUBLE_EQ(out.at(x, y, c),
                                         bilinear_reference(mosaic, phase, x, y, c))
                            << bayer_phase_name(phase) << " " << w << "x" << h << " pixel " << x
                            << "," << y << " channel " << c;
                    }
                }
            }
        }
    }
}

using Kernel = std::array<std::array<double, 5>, 5>;
// Malvar, He, Cutler (2004), figure 2, in eighths.
constexpr Kernel kGreenAtChroma = {
    {{0, 0, -1, 0, 0}, {0, 0, 2, 0, 0}, {-1, 2, 4, 2, -1}, {0, 0, 2, 0, 0}, {0, 0, -1, 0, 0}}};
constexpr Kernel kChromaAtGreenAlongLine = {{{0, 0, 0.5, 0, 0},
                                             {0, -1, 0, -1, 0},
                                             {-1, 4, 5, 4, -1},
                                             {0, -1, 0, -1, 0},
                                             {0, 0, 0.5, 0, 0}}};
constexpr Kernel kChromaAtGreenAlongColumn = {{{0, 0, -1, 0, 0},
                                               {0, -1, 4, -1, 0},
                                               {0.5, 0, 5, 0, 0.5},
                                               {0, -1, 4, -1, 0},
                                               {0, 0, -1, 0, 0}}};
constexpr Kernel kChromaAtOtherChroma = {{{0, 0, -1.5, 0, 0},
                                          {0, 2, 0, 2, 0},
                                          {-1.5, 0, 6, 0, -1.5},
                                          {0, 2, 0, 2, 0},
                                          {0, 0, -1.5, 0, 0}}};

double mhc_reference(const Plane& m, BayerPhase phase, std::size_t x, std::size_t y,
                     std::size_t channel) {
    auto chan = [&](long xx, long yy) {
        return test::channel_of_letter(test::filter_letter(
            CfaPattern::bayer, phase, static_cast<std::size_t>(xx), static_cast<std::size_t>(yy)));
    };
    const long lx = static_cast<long>(x), ly = static_cast<long>(y);
    const std::size_t own = chan(lx, ly);
    if (own == channel) return m.at(x, y);
    const Kernel* k = nullptr;
    if (channel == 1) {
        k = &kGreenAtChroma;
    } else if (own == 1) {
        k = chan(lx + 1, ly) == channel ? &kChromaAtGreenAlongLine : &kChromaAtGreenAlongColumn;
    } else {
        k = &kChromaAtOtherChroma;
    }
    double sum = 0;
    for (long dy = -2; dy <= 2; ++dy) {
        for (long dx = -2; dx <= 2; ++dx) {
            const double v =
                m.at(static_cast<std::size_t>(mirror(lx + dx, static_cast<long>(m.width))),
                     static_cast<std::size_t>(mirror(ly + dy, static_cast<long>(m.height))));
            sum += (*k)[static_cast<std::size_t>(dy + 2)][static_cast<std::size_t>(dx + 2)] * v;
        }
    }
    return sum / 8.0;
}

TEST(Bayer, MhcAppliesThePapersKernelsOverAMirroredImage) {
    for (BayerPhase phase : kPhases) {
        for (const auto& [w, h] : kSizes) {
            const Plane mosaic = test::random_plane(w, h, static_cast<unsigned>(w * 17 + h));
            const RgbImage out = run(DemosaicMethod::mhc, mosaic, phase);
            for (std::size_t y = 0; y < h; ++y) {
                for (std::size_t x = 0; x < w; ++x) {
                    for (std::size_t c = 0; c < 3; ++c) {
                        ASSERT_NEAR(out.at(x, y, c), mhc_reference(mosaic, phase, x, y, c), 1e-9)
                            << bayer_phase_name(phase) << " " << w << "x" << h << " pixel " << x
                            << "," << y << " channel " << c;
                    }
                }
            }
        }
    }
}

TEST(Bayer, LinearRampsAreExactAwayFromTheEdges) {
    const test::Truth truth = test::ramp_truth(13, 11);
    for (DemosaicMethod method : {DemosaicMethod::bilinear, DemosaicMethod::mhc}) {
        for (BayerPhase phase : kPhases) {
            const RgbImage out =
                run(method, test::mosaic_of(truth, CfaPattern::bayer, phase), phase);
            EXPECT_LT(test::mean_abs_error(out, truth, 2), 1e-9)
                << demosaic_method_name(method) << " " << bayer_phase_name(phase);
        }
    }
}

TEST(Bayer, MhcBeatsBilinearOnAColourEdgeChart) {
    const test::Truth truth = test::edge_chart(96, 80);
    for (BayerPhase phase : kPhases) {
        const Plane mosaic = test::mosaic_of(truth, CfaPattern::bayer, phase);
        const double bilinear =
            test::mean_abs_error(run(DemosaicMethod::bilinear, mosaic, phase), truth, 2);
        const double mhc = test::mean_abs_error(run(DemosaicMethod::mhc, mosaic, phase), truth, 2);
        std::cout << "[ chart    ] " << bayer_phase_name(phase) << ": mean |error| bilinear "
                  << bilinear << " DN, mhc " << mhc << " DN\n";
        EXPECT_LT(mhc, 0.9 * bilinear) << bayer_phase_name(phase);
    }
}

TEST(Bayer, RefusesAnImageSmallerThanOneBlock) {
    for (const auto& [w, h] : std::array<std::array<std::size_t, 2>, 3>{{{1, 5}, {5, 1}, {1, 1}}}) {
        const Plane mosaic = test::random_plane(w, h, 1);
        try {
            run(DemosaicMethod::mhc, mosaic, BayerPhase::rggb);
            FAIL() << "no error for " << w << "x" << h;
        } catch (const Error& e) {
            EXPECT_EQ(e.category(), ErrorCategory::input);
            EXPECT_NE(std::string(e.what()).find("at least 2 x 2"), std::string::npos) << e.what();
        }
    }
}

TEST(Bayer, RefusesTheTrueSenseMethod) {
    const Plane mosaic = test::random_plane(8, 8, 1);
    try {
        demosaic(mosaic, {CfaPattern::bayer, BayerPhase::rggb, DemosaicMethod::pan_guided});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage);
        EXPECT_NE(std::string(e.what()).find("does not apply to the bayer pattern"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Bayer, PollsTheCancelToken) {
    const Plane mosaic = test::random_plane(8, 8, 1);
    CancelToken cancel;
    cancel.cancel();
    try {
        demosaic_bayer_mhc(mosaic, BayerPhase::rggb, &cancel);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::cancelled);
    }
}

}  // namespace bayer_test
}  // namespace glint::demosaic
