// SPDX-License-Identifier: Apache-2.0
// Contrast stretch of image outputs (glint-envi convert, glint-demosaic): the limits
// [low, high] of a linear stretch, found from the data (min/max or percentiles) in streaming
// passes, and the mapping of a value to the display range [0, 1] with a gamma.
//
// Percentile limits. Of the n finite values of the stretched set (one band, or all selected
// bands together), sorted ascending as x_0 <= ... <= x_{n-1}, with q = P/100:
//     low  = x_k  with k = floor(q (n - 1)),
//     high = x_m  with m = ceil((1 - q) (n - 1)),
// so at most P % of the values lie below low and at most P % above high (P = 0 gives the
// minimum and maximum). NaN and infinite values are not counted.
//
// Streaming: pass 1 finds min, max and n; pass 2 counts values into kBins equal bins over
// [min, max], keeping each bin's smallest and largest value. x_k is then exact when its bin
// holds one distinct value (always for integer data spanning fewer than kBins codes);
// otherwise it is interpolated linearly by rank between the bin's smallest and largest
// value, within one bin width, (max - min) / kBins, of the exact order statistic.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace glint::io {

/// Limits of a linear stretch.
struct StretchLimits {
    double low = 0.0;
    double high = 1.0;
};

/// Order statistics of a stream of values, in two passes (see the top of this file).
class PercentileHistogram {
public:
    static constexpr std::size_t kBins = 65536;

    /// Pass 1: records the range and count of finite values.
    void observe(double value) {
        if (!is_finite(value)) return;
        if (value < m_min) m_min = value;
        if (value > m_max) m_max = value;
        ++m_count;
    }
    /// Ends pass 1; allocates the bins.
    void begin_counting();
    /// Pass 2: counts a value (the same values as pass 1, in any order).
    void count(double value);

    std::uint64_t finite_count() const { return m_count; }
    double min() const { return m_min; }
    double max() const { return m_max; }

    /// The order statistic x_k (0-based rank, ascending) after pass 2; min()/max() for the
    /// extreme ranks even without pass 2. Requires finite_count() > 0.
    double value_at_rank(std::uint64_t k) const;
    /// Percentile limits for `percent` in [0, 50). Without finite values: {0, 1}.
    StretchLimits limits(double percent) const;

private:
    static bool is_finite(double v) {
        return v - v == 0.0;  // false for NaN and ±infinity
    }
    std::size_t bin_of(double value) const;

    double m_min = std::numeric_limits<double>::infinity();
    double m_max = -std::numeric_limits<double>::infinity();
    std::uint64_t m_count = 0;
    std::vector<std::uint64_t> m_counts;
    std::vector<double> m_bin_min;
    std::vector<double> m_bin_max;
    std::uint64_t m_counted = 0;
};

/// Maps a value to [0, 1]: s = clamp((v - low) / (high - low), 0, 1), then s^(1 / gamma).
/// A flat range (high <= low) maps every value to 0. NaN stays NaN.
double stretch_value(double value, const StretchLimits& limits, double gamma);

/// The stretch a tool's options ask for (--gamma, --percent, --min/--max).
struct StretchRequest {
    std::optional<double> gamma;
    std::optional<double> percent;
    std::optional<double> min;
    std::optional<double> max;
};

/// Checks the values: gamma finite and > 0, percent in [0, 50), min and max given together
/// with min < max (both finite), not both percent and min/max. Throws a usage error naming
/// the option.
void check_stretch_request(const StretchRequest& request);

}  // namespace glint::io
