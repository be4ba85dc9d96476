// SPDX-License-Identifier: Apache-2.0
// Colour filter array layouts as glint defines them, in demosaicing's (x, y) terms: which
// filter covers pixel (x, y), x the sample (column) and y the line (row), both from 0 at the
// top-left pixel of the image. The layouts are defined once, in glint/detect/cfa.h (the
// mosaic glint-detect writes); this header names them for the demosaicing code.
//
// Bayer (period 2). The phase names the 2×2 block read left to right, top to bottom; its
// first letter is the filter of pixel (0, 0):
//     rggb (default)   grbg         gbrg         bggr
//       R G              G R          G B          B G
//       G B              B G          R G          G R
// OpenCV names the same layouts after the second line's second and third pixels:
// rggb = COLOR_BayerBG*, grbg = COLOR_BayerGB*, gbrg = COLOR_BayerGR*, bggr = COLOR_BayerRG*.
//
// TrueSense (period 4, no phase), after Kodak's TRUESENSE sparse colour filter: panchromatic
// (P) pixels on the checkerboard where x + y is even, red/green/blue on the others, arranged
// so that every 2×2 cell holds two P on its main diagonal and two of one colour on the other
// diagonal, the cells' colours forming a G R / B G Bayer block:
//     line 0:  P G P R
//     line 1:  G P R P
//     line 2:  P B P G
//     line 3:  B P G P
// Half the pixels are P, a quarter G, an eighth R and an eighth B.
#pragma once

#include <cstddef>

#include "glint/detect/cfa.h"

namespace glint::demosaic {

/// The filter over a pixel (red, green, blue, pan: the values index colour planes).
using CfaColor = detect::CfaFilter;
using detect::BayerPhase;
using detect::bayer_phase_from_name;
using detect::bayer_phase_name;
using detect::cfa_pattern_from_name;
using detect::cfa_pattern_name;
using detect::cfa_period;
using detect::CfaPattern;

/// "red", "green", "blue", "pan".
inline const char* cfa_color_name(CfaColor color) { return detect::cfa_filter_name(color); }

/// The filter over pixel (x, y) of `pattern` (the phase matters for Bayer only).
inline CfaColor cfa_color(CfaPattern pattern, BayerPhase phase, std::size_t x, std::size_t y) {
    return detect::cfa_filter_at(pattern, phase, y, x);
}
/// The Bayer filter over pixel (x, y).
inline CfaColor bayer_color(BayerPhase phase, std::size_t x, std::size_t y) {
    return cfa_color(CfaPattern::bayer, phase, x, y);
}
/// The TrueSense filter over pixel (x, y).
inline CfaColor truesense_color(std::size_t x, std::size_t y) {
    return cfa_color(CfaPattern::truesense, BayerPhase::rggb, x, y);
}

}  // namespace glint::demosaic
