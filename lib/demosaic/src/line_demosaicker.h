// SPDX-License-Identifier: Apache-2.0
// Internal: the line-by-line demosaicers behind DemosaicStream (Bayer in bayer.cpp,
// TrueSense in truesense.cpp), and reflect-101 mirroring.
#pragma once

#include <cstddef>
#include <memory>
#include <span>

#include "glint/demosaic/demosaic.h"

namespace glint::demosaic::internal {

/// Reflect-101 index of `i` into [0, n) (index -1 reads 1, index n reads n - 2, repeated for
/// offsets wider than the image; n == 1 gives 0). Mirroring about a pixel keeps the parity of
/// x and y, hence the Bayer filter, of every mirrored pixel.
inline std::ptrdiff_t reflect101(std::ptrdiff_t i, std::ptrdiff_t n) {
    if (n == 1) return 0;
    const std::ptrdiff_t period = 2 * (n - 1);
    std::ptrdiff_t m = i % period;
    if (m < 0) m += period;
    return m < n ? m : period - m;
}

/// Output lines 0, 1, 2, ... of one method, each from the few mosaic lines around it.
class LineDemosaicker {
public:
    virtual ~LineDemosaicker() = default;
    /// Output line `y` (width × 3 values); called with y = 0, 1, 2, ... in turn.
    virtual void line(std::size_t y, std::span<double> rgb) = 0;
};

/// Bayer, bilinear or mhc.
std::unique_ptr<LineDemosaicker> make_bayer(std::size_t width, std::size_t height,
                                            BayerPhase phase, DemosaicMethod method,
                                            MosaicLineReader read);
/// TrueSense, pan-guided.
std::unique_ptr<LineDemosaicker> make_truesense(std::size_t width, std::size_t height,
                                                MosaicLineReader read);

/// At most how many values of `width` a method's windows hold (for bytes_held).
std::size_t bayer_values_held(std::size_t width);
std::size_t truesense_values_held(std::size_t width);

}  // namespace glint::demosaic::internal
