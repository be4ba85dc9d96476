// SPDX-License-Identifier: Apache-2.0
// The analog-to-digital converter and how its counts are stored: electrons clipped to [min,
// max], scaled linearly onto [0, 2^bits − 1] and rounded; then written in the `<datatype>` of
// the output, where an integer type narrower than the ADC keeps only the count's low bits
// (the DIRSIG5 BasicPlatform manual: "an 8-bit output would cause the upper 4-bits to be
// clipped from the 12-bit values"), e.g. 4095 → 255 and 256 → 0 in uint8.
#pragma once

#include <cmath>
#include <cstdint>

#include "glint/io/envi.h"

namespace glint::detect {

/// An ADC over [min_electrons, max_electrons] with `bit_depth` bits (min < max, 1–32 bits).
class Adc {
public:
    Adc(double min_electrons, double max_electrons, int bit_depth)
        : m_min_e(min_electrons),
          m_max_e(max_electrons),
          m_max_count(std::ldexp(1.0, bit_depth) - 1.0),
          m_gain(m_max_count / (max_electrons - min_electrons)) {}

    /// round(K (clamp(e, min, max) − min)), K = (2^bits − 1)/(max − min), rounding half up;
    /// NaN gives 0.
    double count(double electrons) const noexcept {
        if (!(electrons > m_min_e)) return 0.0;
        if (electrons >= m_max_e) return m_max_count;
        const double rounded =
            static_cast<double>(static_cast<std::uint64_t>((electrons - m_min_e) * m_gain + 0.5));
        return rounded < m_max_count ? rounded : m_max_count;
    }
    /// K in DN per electron.
    double gain_dn_per_e() const noexcept { return m_gain; }
    /// 2^bits − 1.
    double max_count() const noexcept { return m_max_count; }

private:
    double m_min_e;
    double m_max_e;
    double m_max_count;
    double m_gain;
};

/// Adc(min_electrons, max_electrons, bit_depth).count(electrons).
double adc_count(double electrons, double min_electrons, double max_electrons, int bit_depth);

/// The value a count in [0, 2^32 − 1] takes when stored as `type`: its low 8, 16 or 32 bits
/// for uint8, uint16 and uint32 (the same bits read as two's complement for int16 and int32);
/// unchanged for int64, uint64, float64; rounded to float precision for float32 (exact up
/// to 2^24).
inline double stored_count(double count, io::EnviDataType type) noexcept {
    const auto bits = static_cast<std::uint64_t>(count);
    switch (type) {
        case io::EnviDataType::uint8:
            return static_cast<double>(bits & 0xFFu);
        case io::EnviDataType::int16:
            return static_cast<double>(static_cast<std::int16_t>(bits & 0xFFFFu));
        case io::EnviDataType::uint16:
            return static_cast<double>(bits & 0xFFFFu);
        case io::EnviDataType::int32:
            return static_cast<double>(static_cast<std::int32_t>(bits & 0xFFFFFFFFu));
        case io::EnviDataType::uint32:
            return static_cast<double>(bits & 0xFFFFFFFFu);
        case io::EnviDataType::float32:
            return static_cast<double>(static_cast<float>(count));
        default:
            return count;
    }
}

/// Bits of a non-negative count the type holds without loss: 8 (uint8), 15 (int16),
/// 16 (uint16), 31 (int32), 32 (uint32), 24 (float32), 53 (float64), 63 (int64), 64 (uint64).
int lossless_count_bits(io::EnviDataType type);

}  // namespace glint::detect
