// SPDX-License-Identifier: Apache-2.0
// The colour filter array layouts of cfa.h: names, parsing and the filter of each pixel.
#include "glint/demosaic/cfa.h"

#include <array>
#include <cctype>
#include <string>

namespace glint::demosaic {
namespace {

std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

constexpr CfaColor R = CfaColor::red;
constexpr CfaColor G = CfaColor::green;
constexpr CfaColor B = CfaColor::blue;
constexpr CfaColor P = CfaColor::pan;

/// The 2×2 blocks of the Bayer phases, [phase][y % 2][x % 2].
constexpr std::array<std::array<std::array<CfaColor, 2>, 2>, 4> kBayer = {{
    {{{R, G}, {G, B}}},  // rggb
    {{{G, R}, {B, G}}},  // grbg
    {{{G, B}, {R, G}}},  // gbrg
    {{{B, G}, {G, R}}},  // bggr
}};

/// The TrueSense block, [y % 4][x % 4].
constexpr std::array<std::array<CfaColor, 4>, 4> kTrueSense = {{
    {P, G, P, R},
    {G, P, R, P},
    {P, B, P, G},
    {B, P, G, P},
}};

}  // namespace

const char* cfa_color_name(CfaColor color) {
    switch (color) {
        case CfaColor::red:
            return "red";
        case CfaColor::green:
            return "green";
        case CfaColor::blue:
            return "blue";
        case CfaColor::pan:
            return "pan";
    }
    return "?";
}

const char* cfa_pattern_name(CfaPattern pattern) {
    return pattern == CfaPattern::bayer ? "bayer" : "truesense";
}

const char* bayer_phase_name(BayerPhase phase) {
    switch (phase) {
        case BayerPhase::rggb:
            return "rggb";
        case BayerPhase::grbg:
            return "grbg";
        case BayerPhase::gbrg:
            return "gbrg";
        case BayerPhase::bggr:
            return "bggr";
    }
    return "?";
}

std::optional<CfaPattern> cfa_pattern_from_name(std::string_view name) {
    const std::string n = lower(name);
    if (n == "bayer") return CfaPattern::bayer;
    if (n == "truesense") return CfaPattern::truesense;
    return std::nullopt;
}

std::optional<BayerPhase> bayer_phase_from_name(std::string_view name) {
    const std::string n = lower(name);
    for (BayerPhase phase :
         {BayerPhase::rggb, BayerPhase::grbg, BayerPhase::gbrg, BayerPhase::bggr}) {
        if (n == bayer_phase_name(phase)) return phase;
    }
    return std::nullopt;
}

std::size_t cfa_period(CfaPattern pattern) { return pattern == CfaPattern::bayer ? 2 : 4; }

CfaColor bayer_color(BayerPhase phase, std::size_t x, std::size_t y) {
    return kBayer[static_cast<std::size_t>(phase)][y % 2][x % 2];
}

CfaColor truesense_color(std::size_t x, std::size_t y) { return kTrueSense[y % 4][x % 4]; }

CfaColor cfa_color(CfaPattern pattern, BayerPhase phase, std::size_t x, std::size_t y) {
    return pattern == CfaPattern::bayer ? bayer_color(phase, x, y) : truesense_color(x, y);
}

}  // namespace glint::demosaic
