// SPDX-License-Identifier: Apache-2.0
// Internal: a plane extended by a margin of reflect-101 mirrored pixels (index -1 reads 1,
// index n reads n - 2, repeated for margins wider than the image), so that kernels read
// their whole footprint without bounds checks. Mirroring about a pixel keeps the parity of
// x and y, hence the Bayer filter, of every mirrored pixel.
#pragma once

#include <cstddef>
#include <vector>

#include "glint/demosaic/demosaic.h"

namespace glint::demosaic::internal {

/// Reflect-101 index of `i` into [0, n), n >= 2 (n == 1 gives 0).
inline std::ptrdiff_t reflect101(std::ptrdiff_t i, std::ptrdiff_t n) {
    if (n == 1) return 0;
    const std::ptrdiff_t period = 2 * (n - 1);
    std::ptrdiff_t m = i % period;
    if (m < 0) m += period;
    return m < n ? m : period - m;
}

/// `plane` with `margin` mirrored pixels on every side.
class PaddedPlane {
public:
    PaddedPlane(const Plane& plane, std::ptrdiff_t margin)
        : m_margin(margin),
          m_stride(static_cast<std::ptrdiff_t>(plane.width) + 2 * margin),
          m_values(
              static_cast<std::size_t>(m_stride) *
              static_cast<std::size_t>(static_cast<std::ptrdiff_t>(plane.height) + 2 * margin)) {
        const auto w = static_cast<std::ptrdiff_t>(plane.width);
        const auto h = static_cast<std::ptrdiff_t>(plane.height);
        std::size_t i = 0;
        for (std::ptrdiff_t y = -margin; y < h + margin; ++y) {
            const std::size_t row = static_cast<std::size_t>(reflect101(y, h)) * plane.width;
            for (std::ptrdiff_t x = -margin; x < w + margin; ++x) {
                m_values[i++] = plane.values[row + static_cast<std::size_t>(reflect101(x, w))];
            }
        }
    }

    /// Pointer to pixel (x, y) of the image; offsets up to ±margin around it are valid,
    /// a line further is `stride()` values away.
    const double* pixel(std::size_t x, std::size_t y) const {
        return m_values.data() + (static_cast<std::ptrdiff_t>(y) + m_margin) * m_stride +
               static_cast<std::ptrdiff_t>(x) + m_margin;
    }
    std::ptrdiff_t stride() const { return m_stride; }

private:
    std::ptrdiff_t m_margin;
    std::ptrdiff_t m_stride;
    std::vector<double> m_values;
};

}  // namespace glint::demosaic::internal
