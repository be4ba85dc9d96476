// SPDX-License-Identifier: Apache-2.0
// PixelTable (pixel_table.h).
#include "glint/sensor/pixel_table.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "glint/core/error.h"

namespace glint::sensor {
namespace {

/// The index i of `cdf` (ascending, cdf[0] = 0, cdf[cells] = 1) with cdf[i] <= r <
/// cdf[i + 1] (empty cells are never chosen), and where r falls inside it (0 … 1).
std::pair<std::size_t, double> locate(const double* cdf, std::size_t cells, double r) {
    const double* upper = std::upper_bound(cdf + 1, cdf + cells + 1, r);
    std::size_t i = static_cast<std::size_t>(upper - cdf) - 1;
    if (i >= cells) i = cells - 1;  // r at the top (rounding)
    const double width = cdf[i + 1] - cdf[i];
    const double inside = width > 0.0 ? std::clamp((r - cdf[i]) / width, 0.0, 1.0) : 0.5;
    return {i, inside};
}

/// Writes the CDF of `cells` values >= 0 (cells + 1 entries); false when they sum to 0.
bool to_cdf(const double* values, std::size_t cells, double* cdf) {
    cdf[0] = 0.0;
    for (std::size_t i = 0; i < cells; ++i) cdf[i + 1] = cdf[i] + values[i];
    const double total = cdf[cells];
    if (!(total > 0.0)) return false;
    for (std::size_t i = 1; i <= cells; ++i) cdf[i] /= total;
    cdf[cells] = 1.0;
    return true;
}

}  // namespace

PixelTable::PixelTable(const std::vector<double>& weights, std::size_t width, std::size_t height)
    : m_width(width), m_height(height) {
    if (const auto problem = io::weight_image_problem(weights, width, height)) {
        throw input_error(*problem);
    }
    m_column_cdf.resize(height * (width + 1));
    std::vector<double> line_sums(height, 0.0);
    for (std::size_t y = 0; y < height; ++y) {
        const double* line = weights.data() + y * width;
        for (std::size_t x = 0; x < width; ++x) line_sums[y] += line[x];
        // An all-zero line keeps a zero table: its marginal probability is 0.
        (void)to_cdf(line, width, m_column_cdf.data() + y * (width + 1));
    }
    m_line_cdf.resize(height + 1);
    (void)to_cdf(line_sums.data(), height, m_line_cdf.data());  // not all zero: checked above
}

std::array<double, 2> PixelTable::sample(double r1, double r2) const noexcept {
    const auto [line, in_line] = locate(m_line_cdf.data(), m_height, r1);
    const auto [column, in_column] =
        locate(m_column_cdf.data() + line * (m_width + 1), m_width, r2);
    return {static_cast<double>(column) + in_column, static_cast<double>(line) + in_line};
}

}  // namespace glint::sensor
