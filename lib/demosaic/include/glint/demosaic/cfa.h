// SPDX-License-Identifier: Apache-2.0
// Colour filter array layouts as glint defines them: which filter covers pixel (x, y), x the
// sample (column) and y the line (row), both from 0 at the top-left pixel of the image.
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
#include <optional>
#include <string_view>

namespace glint::demosaic {

/// The filter over one pixel.
enum class CfaColor { red = 0, green = 1, blue = 2, pan = 3 };

/// A colour filter array layout.
enum class CfaPattern { bayer, truesense };

/// The phase of a Bayer layout: the 2×2 block from pixel (0, 0), row by row.
enum class BayerPhase { rggb, grbg, gbrg, bggr };

/// "red", "green", "blue", "pan".
const char* cfa_color_name(CfaColor color);
/// "bayer", "truesense".
const char* cfa_pattern_name(CfaPattern pattern);
/// "rggb", "grbg", "gbrg", "bggr".
const char* bayer_phase_name(BayerPhase phase);

/// Pattern for a command-line name (bayer, truesense; case-insensitive); nullopt otherwise.
std::optional<CfaPattern> cfa_pattern_from_name(std::string_view name);
/// Phase for a command-line name (rggb, grbg, gbrg, bggr; case-insensitive); nullopt otherwise.
std::optional<BayerPhase> bayer_phase_from_name(std::string_view name);

/// Side of the repeating block: 2 for Bayer, 4 for TrueSense. An image must be at least this
/// many samples wide and lines tall to be demosaiced.
std::size_t cfa_period(CfaPattern pattern);

/// Filter of pixel (x, y) of a Bayer layout.
CfaColor bayer_color(BayerPhase phase, std::size_t x, std::size_t y);
/// Filter of pixel (x, y) of the TrueSense layout.
CfaColor truesense_color(std::size_t x, std::size_t y);
/// Filter of pixel (x, y) of `pattern` (the phase is used for Bayer only).
CfaColor cfa_color(CfaPattern pattern, BayerPhase phase, std::size_t x, std::size_t y);

}  // namespace glint::demosaic
