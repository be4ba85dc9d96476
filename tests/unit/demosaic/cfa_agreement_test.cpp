// SPDX-License-Identifier: Apache-2.0
// glint-detect mosaics and glint-demosaic demosaics with the same layouts: lib/detect's
// cfa_filter_at(row, column) and lib/demosaic's cfa_color(x = column, y = row) agree on every
// pixel of both patterns and all four Bayer phases, and so do their names.
#include <gtest/gtest.h>

#include "glint/demosaic/cfa.h"
#include "glint/detect/cfa.h"

namespace glint::demosaic {
namespace {

const char* name(CfaColor c) { return cfa_color_name(c); }

TEST(CfaAgreement, DetectAndDemosaicUseTheSameLayouts) {
    for (const CfaPattern pattern : {CfaPattern::bayer, CfaPattern::truesense}) {
        const auto detect_pattern = detect::cfa_pattern_from_name(cfa_pattern_name(pattern));
        ASSERT_TRUE(detect_pattern) << cfa_pattern_name(pattern);
        EXPECT_EQ(detect::cfa_period(*detect_pattern), cfa_period(pattern));
        for (const BayerPhase phase :
             {BayerPhase::rggb, BayerPhase::grbg, BayerPhase::gbrg, BayerPhase::bggr}) {
            const auto detect_phase = detect::bayer_phase_from_name(bayer_phase_name(phase));
            ASSERT_TRUE(detect_phase) << bayer_phase_name(phase);
            for (std::size_t y = 0; y < 9; ++y) {
                for (std::size_t x = 0; x < 11; ++x) {
                    EXPECT_STREQ(detect::cfa_filter_name(
                                     detect::cfa_filter_at(*detect_pattern, *detect_phase, y, x)),
                                 name(cfa_color(pattern, phase, x, y)))
                        << cfa_pattern_name(pattern) << " " << bayer_phase_name(phase) << " x=" << x
                        << " y=" << y;
                }
            }
        }
    }
}

}  // namespace
}  // namespace glint::demosaic
