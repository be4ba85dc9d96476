// SPDX-License-Identifier: Apache-2.0
// PercentileHistogram and stretch_value (the definitions are at the top of stretch.h).
#include "glint/io/stretch.h"

#include <algorithm>
#include <cmath>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::io {

void PercentileHistogram::begin_counting() {
    m_counts.assign(kBins, 0);
    m_bin_min.assign(kBins, std::numeric_limits<double>::infinity());
    m_bin_max.assign(kBins, -std::numeric_limits<double>::infinity());
    m_counted = 0;
}

std::size_t PercentileHistogram::bin_of(double value) const {
    if (!(m_max > m_min)) return 0;
    // Halved so that the range of values near ±DBL_MAX cannot overflow.
    const double t = (0.5 * value - 0.5 * m_min) / (0.5 * m_max - 0.5 * m_min);
    const double scaled = std::floor(t * static_cast<double>(kBins));
    if (!(scaled > 0)) return 0;
    return std::min(kBins - 1, static_cast<std::size_t>(scaled));
}

void PercentileHistogram::count(double value) {
    if (!is_finite(value)) return;
    if (m_counts.empty()) throw internal_error("PercentileHistogram::count before begin_counting");
    const std::size_t bin = bin_of(value);
    ++m_counts[bin];
    m_bin_min[bin] = std::min(m_bin_min[bin], value);
    m_bin_max[bin] = std::max(m_bin_max[bin], value);
    ++m_counted;
}

double PercentileHistogram::value_at_rank(std::uint64_t k) const {
    if (m_count == 0) throw internal_error("PercentileHistogram: no values");
    if (k == 0) return m_min;
    if (k + 1 >= m_count) return m_max;
    if (m_counts.empty() || m_counted != m_count) {
        throw internal_error("PercentileHistogram: pass 2 did not see the values of pass 1");
    }
    std::uint64_t before = 0;
    for (std::size_t bin = 0; bin < kBins; ++bin) {
        const std::uint64_t n = m_counts[bin];
        if (k < before + n) {
            const double lo = m_bin_min[bin];
            const double hi = m_bin_max[bin];
            if (n == 1 || lo == hi) return lo;
            const double t = static_cast<double>(k - before) / static_cast<double>(n - 1);
            return lo + t * (hi - lo);
        }
        before += n;
    }
    return m_max;
}

StretchLimits PercentileHistogram::limits(double percent) const {
    if (m_count == 0) return {};
    if (percent <= 0) return {m_min, m_max};
    const double q = percent / 100.0;
    const double last = static_cast<double>(m_count - 1);
    const auto k = static_cast<std::uint64_t>(std::floor(q * last));
    const auto m = static_cast<std::uint64_t>(std::ceil((1.0 - q) * last));
    return {value_at_rank(k), value_at_rank(std::max(k, m))};
}

double stretch_value(double value, const StretchLimits& limits, double gamma) {
    if (std::isnan(value)) return value;
    if (!(limits.high > limits.low)) return 0.0;
    const double s = std::clamp((value - limits.low) / (limits.high - limits.low), 0.0, 1.0);
    if (gamma == 1.0 || s == 0.0 || s == 1.0) return s;
    return std::pow(s, 1.0 / gamma);
}

void check_stretch_request(const StretchRequest& r) {
    if (r.gamma && !(*r.gamma > 0 && std::isfinite(*r.gamma))) {
        throw usage_error("--gamma must be a positive number, got " + format_shortest(*r.gamma));
    }
    if (r.percent && !(*r.percent >= 0 && *r.percent < 50)) {
        throw usage_error("--percent must be in [0, 50), got " + format_shortest(*r.percent));
    }
    if (r.min.has_value() != r.max.has_value()) throw usage_error("--min and --max go together");
    if (r.min && !(std::isfinite(*r.min) && std::isfinite(*r.max) && *r.min < *r.max)) {
        throw usage_error("--min must be less than --max (got " + format_shortest(*r.min) +
                          " and " + format_shortest(*r.max) + ")");
    }
    if (r.min && r.percent) throw usage_error("give --percent or --min/--max, not both");
}

}  // namespace glint::io
