// SPDX-License-Identifier: Apache-2.0
// The colour filter array layouts: the Bayer phases and the TrueSense block as drawn in
// cfa.h, the filter proportions, and the names accepted on a command line.
#include "glint/demosaic/cfa.h"

#include <gtest/gtest.h>

#include <map>

#include "mosaic_support.h"

namespace glint::demosaic {
namespace cfa_test {

char letter(CfaColor color) {
    switch (color) {
        case CfaColor::red:
            return 'R';
        case CfaColor::green:
            return 'G';
        case CfaColor::blue:
            return 'B';
        case CfaColor::pan:
            return 'P';
    }
    return '?';
}

TEST(Cfa, BayerPhaseNamesTheBlockFromPixelZeroZero) {
    const std::map<BayerPhase, std::string> blocks = {{BayerPhase::rggb, "RGGB"},
                                                      {BayerPhase::grbg, "GRBG"},
                                                      {BayerPhase::gbrg, "GBRG"},
                                                      {BayerPhase::bggr, "BGGR"}};
    for (const auto& [phase, block] : blocks) {
        SCOPED_TRACE(bayer_phase_name(phase));
        for (std::size_t y = 0; y < 6; ++y) {
            for (std::size_t x = 0; x < 7; ++x) {
                EXPECT_EQ(letter(bayer_color(phase, x, y)), block[(y % 2) * 2 + x % 2]);
                EXPECT_EQ(letter(cfa_color(CfaPattern::bayer, phase, x, y)),
                          test::filter_letter(CfaPattern::bayer, phase, x, y));
            }
        }
    }
}

TEST(Cfa, TrueSenseBlock) {
    const char* rows[4] = {"PGPR", "GPRP", "PBPG", "BPGP"};
    std::map<char, int> counts;
    for (std::size_t y = 0; y < 8; ++y) {
        for (std::size_t x = 0; x < 8; ++x) {
            const char l = letter(truesense_color(x, y));
            EXPECT_EQ(l, rows[y % 4][x % 4]) << x << "," << y;
            EXPECT_EQ(l == 'P', (x + y) % 2 == 0) << "pan lies on the even checkerboard";
            EXPECT_EQ(cfa_color(CfaPattern::truesense, BayerPhase::bggr, x, y),
                      truesense_color(x, y));
            ++counts[l];
        }
    }
    EXPECT_EQ(counts['P'], 32);
    EXPECT_EQ(counts['G'], 16);
    EXPECT_EQ(counts['R'], 8);
    EXPECT_EQ(counts['B'], 8);
}

TEST(Cfa, Names) {
    EXPECT_EQ(cfa_pattern_from_name("Bayer"), CfaPattern::bayer);
    EXPECT_EQ(cfa_pattern_from_name("truesense"), CfaPattern::truesense);
    EXPECT_FALSE(cfa_pattern_from_name("xtrans"));
    for (BayerPhase phase : test::kPhases) {
        EXPECT_EQ(bayer_phase_from_name(bayer_phase_name(phase)), phase);
    }
    EXPECT_EQ(bayer_phase_from_name("BGGR"), BayerPhase::bggr);
    EXPECT_FALSE(bayer_phase_from_name("rgbg"));
    EXPECT_EQ(cfa_period(CfaPattern::bayer), 2u);
    EXPECT_EQ(cfa_period(CfaPattern::truesense), 4u);
    EXPECT_STREQ(cfa_color_name(CfaColor::pan), "pan");
}

}  // namespace cfa_test
}  // namespace glint::demosaic
