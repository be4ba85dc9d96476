// SPDX-License-Identifier: Apache-2.0
// tinyobjloader's number reading, operation for operation (obj_numbers.h).
#include "obj_numbers.h"

#include <cmath>

namespace glint::mesh::detail {

std::optional<double> legacy_real(const char* begin, const char* end) {
    if (begin == end) return std::nullopt;
    const char* p = begin;
    bool negative = false;
    bool leading_dot = false;  // ".5", "-.5": no integer part
    if (*p == '+' || *p == '-') {
        negative = *p == '-';
        ++p;
        leading_dot = p != end && *p == '.';
    } else if (*p == '.') {
        leading_dot = true;
    } else if (!is_digit(*p)) {
        return std::nullopt;
    }

    double mantissa = 0.0;
    if (!leading_dot) {
        const char* const digits = p;
        while (p != end && is_digit(*p)) {
            mantissa *= 10;
            mantissa += static_cast<int>(*p - '0');
            ++p;
        }
        if (p == digits) return std::nullopt;
    }
    // tinyobjloader reads a fraction only after a '.', an exponent after the fraction or
    // straight after the integer part; anything else ends the number.
    if (p != end && *p == '.') {
        ++p;
        for (int read = 1; p != end && is_digit(*p); ++read, ++p) {
            mantissa += static_cast<int>(*p - '0') *
                        (read < 8 ? kNegativePowersOfTen[read] : std::pow(10.0, -read));
        }
    } else if (p == end || (*p != 'e' && *p != 'E')) {
        return negative ? -mantissa : mantissa;
    }

    int exponent = 0;
    if (p != end && (*p == 'e' || *p == 'E')) {
        ++p;
        bool exponent_negative = false;
        if (p != end && (*p == '+' || *p == '-')) {
            exponent_negative = *p == '-';
            ++p;
        } else if (p == end || !is_digit(*p)) {
            return std::nullopt;  // an empty exponent
        }
        const char* const digits = p;
        for (; p != end && is_digit(*p); ++p) {
            if (exponent > 2147483647 / 10) return std::nullopt;
            // tinyobjloader's int arithmetic, wrapping where it would overflow (1e2147483648).
            exponent = static_cast<int>(static_cast<unsigned>(exponent) * 10u +
                                        static_cast<unsigned>(*p - '0'));
        }
        if (exponent_negative) exponent = static_cast<int>(0u - static_cast<unsigned>(exponent));
        if (p == digits) return std::nullopt;
    }
    const double value =
        exponent != 0 ? std::ldexp(mantissa * std::pow(5.0, exponent), exponent) : mantissa;
    // tinyobjloader multiplies by -1, which on x86-64 leaves a NaN as it is ("-0e999" is
    // 0 × inf, a NaN with its sign bit set); GCC would fold that multiplication to a negation.
    return negative && !std::isnan(value) ? -value : value;
}

}  // namespace glint::mesh::detail
