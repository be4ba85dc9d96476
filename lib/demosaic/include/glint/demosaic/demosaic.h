// SPDX-License-Identifier: Apache-2.0
// Demosaicing: a one-band colour filter array image (cfa.h) to three bands R, G, B at every
// pixel. Values are doubles whatever the stored type; the result is not rounded or clamped.
//
// Methods (docs/tools/glint-demosaic.md gives the kernels):
//   bilinear    Bayer. Each missing colour is the mean of its nearest samples: G from the 4
//               edge neighbours, R/B from the 2 neighbours in the line or column that holds
//               them, or from the 4 diagonal neighbours. Samples keep their own value. The
//               result lies between the mosaic's minimum and maximum.
//   mhc         Bayer. Malvar, He and Cutler (ICASSP 2004), "high-quality linear
//               interpolation": bilinear plus a Laplacian correction from the pixel's own
//               channel, as four 5×5 kernels in eighths. Samples keep their own value;
//               results may overshoot the mosaic's range near edges.
//   pan-guided  TrueSense. Pan is averaged from the 4 edge neighbours at every colour pixel;
//               then, for each colour C, the differences D = C − P at C's own pixels are
//               spread by normalized convolution with the weight (4 − |dx|)(4 − |dy|) over
//               C's pixels within |dx|, |dy| <= 3; the output is C = P + D at every pixel.
//
// Borders. Bayer methods read beyond the edges through reflect-101 mirroring (index -1 reads
// 1, index n reads n - 2, repeated for kernels wider than the image), which keeps every
// mirrored pixel's filter equal to the filter the layout puts there, so the interior formulas
// apply unchanged up to the edge. Pan-guided uses only pixels inside the image: the pan mean and
// the normalized convolution divide by the weights of the pixels they found. A flat colour field is
// reconstructed exactly by every method, borders included.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "glint/core/cancel.h"
#include "glint/demosaic/cfa.h"

namespace glint::demosaic {

/// How missing colours are estimated.
enum class DemosaicMethod { bilinear, mhc, pan_guided };

/// "bilinear", "mhc", "pan-guided".
const char* demosaic_method_name(DemosaicMethod method);
/// Method for a command-line name (bilinear, mhc, pan-guided; case-insensitive).
std::optional<DemosaicMethod> demosaic_method_from_name(std::string_view name);
/// Whether `method` applies to `pattern` (bilinear and mhc: Bayer; pan-guided: TrueSense).
bool method_supports(DemosaicMethod method, CfaPattern pattern);
/// The default method of a pattern: bilinear for Bayer, pan-guided for TrueSense.
DemosaicMethod default_method(CfaPattern pattern);

/// A one-band image: width × height values, line by line from the top.
struct Plane {
    std::size_t width = 0;
    std::size_t height = 0;
    std::vector<double> values;

    double at(std::size_t x, std::size_t y) const { return values[y * width + x]; }
    double& at(std::size_t x, std::size_t y) { return values[y * width + x]; }
};

/// A three-band image: width × height pixels of R, G, B, line by line, interleaved.
struct RgbImage {
    std::size_t width = 0;
    std::size_t height = 0;
    std::vector<double> rgb;

    double at(std::size_t x, std::size_t y, std::size_t channel) const {
        return rgb[(y * width + x) * 3 + channel];
    }
};

/// What to demosaic with.
struct DemosaicOptions {
    CfaPattern pattern = CfaPattern::bayer;
    BayerPhase phase = BayerPhase::rggb;  ///< Bayer only
    DemosaicMethod method = DemosaicMethod::bilinear;
};

/// Reads line `y` of a mosaic (width values, line 0 at the top) into `out`.
using MosaicLineReader = std::function<void(std::size_t y, std::span<double> out)>;

namespace internal {
class LineDemosaicker;
}

/// Demosaics an image line by line. An output line depends only on the mosaic lines within a
/// few lines of it (2 for the Bayer methods, 4 for pan-guided), so the stream asks `read` for
/// each mosaic line once, in increasing order, as the output reaches it, and holds a window
/// of lines (bytes_held), whatever the image's height. The values equal a whole-image
/// computation's to the bit.
class DemosaicStream {
public:
    /// Throws glint::Error: usage when the method does not apply to the pattern, input when
    /// the image is smaller than one block of the pattern (cfa_period).
    DemosaicStream(std::size_t width, std::size_t height, const DemosaicOptions& options,
                   MosaicLineReader read);
    ~DemosaicStream();
    DemosaicStream(const DemosaicStream&) = delete;
    DemosaicStream& operator=(const DemosaicStream&) = delete;

    std::size_t width() const { return m_width; }
    std::size_t height() const { return m_height; }
    /// The next output line, 0 first: width × 3 values R, G, B. `rgb` must hold exactly that
    /// many; asking past the last line is an internal error.
    void next_line(std::span<double> rgb);

    /// The most bytes a stream over an image `width` pixels wide holds with `method` (its
    /// windows of lines; the caller's output line is not included).
    static std::size_t bytes_held(std::size_t width, DemosaicMethod method);

private:
    std::size_t m_width;
    std::size_t m_height;
    std::size_t m_next = 0;
    std::unique_ptr<internal::LineDemosaicker> m_lines;
};

/// Throws glint::Error (usage) when `options.method` does not apply to `options.pattern`.
void check_method(const DemosaicOptions& options);

/// Demosaics `mosaic` in memory (through a DemosaicStream). Throws glint::Error: usage when
/// the method does not apply to the pattern, input when the plane is smaller than one block of
/// the pattern (cfa_period), internal when its values do not match its size, cancelled when
/// `cancel` is raised (polled once per line).
RgbImage demosaic(const Plane& mosaic, const DemosaicOptions& options,
                  const CancelToken* cancel = nullptr);

/// Bayer, bilinear (see the top of this file). Requires at least 2 × 2 pixels.
RgbImage demosaic_bayer_bilinear(const Plane& mosaic, BayerPhase phase,
                                 const CancelToken* cancel = nullptr);
/// Bayer, Malvar–He–Cutler. Requires at least 2 × 2 pixels.
RgbImage demosaic_bayer_mhc(const Plane& mosaic, BayerPhase phase,
                            const CancelToken* cancel = nullptr);
/// TrueSense, pan-guided colour differences. Requires at least 4 × 4 pixels.
RgbImage demosaic_truesense(const Plane& mosaic, const CancelToken* cancel = nullptr);

}  // namespace glint::demosaic
