// SPDX-License-Identifier: Apache-2.0
// The Bayer and TrueSense layouts of cfa.h and the names of filters, patterns and phases.
#include "glint/detect/cfa.h"

#include <array>
#include <cctype>
#include <string>

namespace glint::detect {
namespace {

using F = CfaFilter;

constexpr std::array<CfaFilter, 3> kBayerFilters{F::red, F::green, F::blue};
constexpr std::array<CfaFilter, 4> kTrueSenseFilters{F::pan, F::red, F::green, F::blue};

/// RGGB; the other phases shift it by one row and/or one column.
constexpr CfaFilter kBayer[2][2] = {{F::red, F::green}, {F::green, F::blue}};

constexpr CfaFilter kTrueSense[4][4] = {
    {F::pan, F::green, F::pan, F::red},
    {F::green, F::pan, F::red, F::pan},
    {F::pan, F::blue, F::pan, F::green},
    {F::blue, F::pan, F::green, F::pan},
};

bool same_text(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i]))) {
            return false;
        }
    }
    return true;
}

}  // namespace

const char* cfa_filter_name(CfaFilter filter) {
    switch (filter) {
        case CfaFilter::red:
            return "red";
        case CfaFilter::green:
            return "green";
        case CfaFilter::blue:
            return "blue";
        case CfaFilter::pan:
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

std::optional<CfaFilter> cfa_filter_from_name(std::string_view name) {
    for (CfaFilter f : kTrueSenseFilters) {
        if (same_text(name, cfa_filter_name(f))) return f;
    }
    return std::nullopt;
}

std::optional<CfaPattern> cfa_pattern_from_name(std::string_view name) {
    for (CfaPattern p : {CfaPattern::bayer, CfaPattern::truesense}) {
        if (same_text(name, cfa_pattern_name(p))) return p;
    }
    return std::nullopt;
}

std::optional<BayerPhase> bayer_phase_from_name(std::string_view name) {
    for (BayerPhase p : {BayerPhase::rggb, BayerPhase::grbg, BayerPhase::gbrg, BayerPhase::bggr}) {
        if (same_text(name, bayer_phase_name(p))) return p;
    }
    return std::nullopt;
}

std::span<const CfaFilter> cfa_filters(CfaPattern pattern) {
    if (pattern == CfaPattern::bayer) return kBayerFilters;
    return kTrueSenseFilters;
}

std::size_t cfa_period(CfaPattern pattern) { return pattern == CfaPattern::bayer ? 2 : 4; }

CfaFilter cfa_filter_at(CfaPattern pattern, BayerPhase phase, std::size_t row, std::size_t column) {
    if (pattern == CfaPattern::truesense) return kTrueSense[row & 3u][column & 3u];
    // grbg starts one column into rggb, gbrg one row, bggr one of each.
    const std::size_t row_shift = (phase == BayerPhase::gbrg || phase == BayerPhase::bggr) ? 1 : 0;
    const std::size_t column_shift =
        (phase == BayerPhase::grbg || phase == BayerPhase::bggr) ? 1 : 0;
    return kBayer[(row + row_shift) & 1u][(column + column_shift) & 1u];
}

}  // namespace glint::detect
