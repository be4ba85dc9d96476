// SPDX-License-Identifier: Apache-2.0
// The numbers of an OBJ file (obj_parser.cpp). A vertex coordinate's value is computed as
// tinyobjloader 2.0.0rc10's tryParseDouble computed it when glint read OBJ files through
// tinyobjloader: digit by digit in double (mantissa × 10 + digit, then + digit × 10^-k), which
// is not always the correctly rounded double, so that meshes keep the bits they had. Whether
// a coordinate is valid is still glint::parse_double's verdict (std::from_chars).
#pragma once

#include <cmath>
#include <optional>

namespace glint::mesh::detail {

inline bool is_digit(char c) { return static_cast<unsigned>(c - '0') < 10u; }

/// 10^-k for k < 8, as tinyobjloader's table holds them; longer fractions use std::pow.
inline constexpr double kNegativePowersOfTen[] = {1.0,    0.1,     0.01,     0.001,
                                                  0.0001, 0.00001, 0.000001, 0.0000001};

/// The value tinyobjloader reads from the token [begin, end) (its tryParseDouble): an
/// optional sign, digits, a fraction, an exponent, stopping at the first character that fits
/// none (so "1.5x" is 1.5); nullopt where tinyobjloader fails (no digits, an empty exponent,
/// an exponent beyond 2147483647), which it then reads as 0.
std::optional<double> legacy_real(const char* begin, const char* end);

/// The hot path of a vertex coordinate: when [begin, end) is a plain decimal,
/// `[+-]?D+(.D+)?` of at most 64 characters (which glint::parse_double accepts and finds
/// finite), sets `value` to legacy_real's value and returns true; false otherwise.
inline bool plain_real(const char* begin, const char* end, double& value) {
    if (begin == end || end - begin > 64) return false;
    const char* p = begin;
    const bool negative = *p == '-';
    if (*p == '+' || *p == '-') ++p;
    const char* const digits = p;
    double mantissa = 0.0;
    // The same operations, in the same order, as tryParseDouble (no FMA on x86-64's baseline;
    // never -ffast-math: docs/architecture.md).
    while (p != end && is_digit(*p)) {
        mantissa *= 10;
        mantissa += static_cast<int>(*p - '0');
        ++p;
    }
    if (p == digits) return false;
    if (p != end) {
        if (*p != '.' || ++p == end) return false;
        for (int read = 1; p != end; ++read, ++p) {
            if (!is_digit(*p)) return false;
            mantissa += static_cast<int>(*p - '0') *
                        (read < 8 ? kNegativePowersOfTen[read] : std::pow(10.0, -read));
        }
    }
    value = negative ? -mantissa : mantissa;
    return true;
}

}  // namespace glint::mesh::detail
