// SPDX-License-Identifier: Apache-2.0
// Colour-filter-array (CFA) layouts: which filter covers pixel (row, column) of a Bayer or
// TrueSense mosaic. Rows are lines within a capture (ENVI lines), columns are samples; (0, 0)
// is the first sample of the capture's first line. docs/detector.md draws the layouts.
//
//   Bayer, 2 × 2 period, four phases named by the filters of the top-left 2 × 2 block read
//   row by row (the default is rggb):
//     rggb: R G    grbg: G R    gbrg: G B    bggr: B G
//           G B          B G          R G          G R
//   TrueSense (Kodak's 50 % panchromatic pattern), 4 × 4 period, one phase:
//     P G P R
//     G P R P
//     P B P G
//     B P G P
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace glint::detect {

/// A filter of a CFA pattern (the `filtername` of `<channelpattern><mapping>`).
enum class CfaFilter : std::uint8_t { red, green, blue, pan };

/// The CFA patterns DIRSIG supports (`<channelpattern name=...>`).
enum class CfaPattern : std::uint8_t { bayer, truesense };

/// Where the Bayer 2 × 2 block starts: the filters of its first row, then its second.
enum class BayerPhase : std::uint8_t { rggb, grbg, gbrg, bggr };

/// "red", "green", "blue", "pan".
const char* cfa_filter_name(CfaFilter filter);
/// "bayer", "truesense".
const char* cfa_pattern_name(CfaPattern pattern);
/// "rggb", "grbg", "gbrg", "bggr".
const char* bayer_phase_name(BayerPhase phase);

/// The filter for a name ("red", ...; case-insensitive), if any.
std::optional<CfaFilter> cfa_filter_from_name(std::string_view name);
/// The pattern for a name ("bayer", "truesense"; case-insensitive), if any.
std::optional<CfaPattern> cfa_pattern_from_name(std::string_view name);
/// The phase for a name ("rggb", ...; case-insensitive), if any.
std::optional<BayerPhase> bayer_phase_from_name(std::string_view name);

/// The filters a pattern needs mapped to channels, in the order of the DIRSIG5 BasicPlatform
/// manual: bayer red, green, blue; truesense pan, red, green, blue.
std::span<const CfaFilter> cfa_filters(CfaPattern pattern);

/// The side of the pattern's repeating block: 2 (bayer) or 4 (truesense).
std::size_t cfa_period(CfaPattern pattern);

/// The filter over pixel (row, column). `phase` applies to bayer and is ignored for
/// truesense (which has one layout).
CfaFilter cfa_filter_at(CfaPattern pattern, BayerPhase phase, std::size_t row, std::size_t column);

}  // namespace glint::detect
