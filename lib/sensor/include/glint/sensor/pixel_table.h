// SPDX-License-Identifier: Apache-2.0
// A piecewise-constant 2-D density over the pixels of a grey image, sampled with two uniforms
// (the PSF image of psf.h and the active-area mask of active_area.h): the cumulative sums of
// the line totals (the marginal) and of each line (the conditionals), built once. r1 picks the
// line by binary search in the marginal, r2 the column in that line's table, and the
// remainder of each uniform inside its cell places the point uniformly inside the image pixel,
// so two uniforms give one continuous point, its density proportional to the pixel's value.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "glint/io/image.h"

namespace glint::sensor {

using io::GreyImage;

class PixelTable {
public:
    /// Throws glint::Error (input, no context) with io::weight_image_problem's message for an
    /// empty image, a negative or non-finite value or an all-zero one.
    PixelTable(const std::vector<double>& weights, std::size_t width, std::size_t height);

    std::size_t width() const noexcept { return m_width; }
    std::size_t height() const noexcept { return m_height; }
    /// A point (x, y) in [0, width] × [0, height] (image pixels, line 0 at the top) for two
    /// uniforms in [0, 1).
    std::array<double, 2> sample(double r1, double r2) const noexcept;

private:
    std::size_t m_width = 0;
    std::size_t m_height = 0;
    std::vector<double> m_line_cdf;    ///< height + 1 values, 0 … 1
    std::vector<double> m_column_cdf;  ///< per line, width + 1 values, 0 … 1
};

}  // namespace glint::sensor
