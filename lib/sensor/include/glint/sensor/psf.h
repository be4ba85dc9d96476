// SPDX-License-Identifier: Apache-2.0
// A focal plane's point spread function (the BasicPlatform manual's "Point Spread Function
// (PSF)", docs/camera.md §PSF): a distribution of offsets on the focal plane, in pixels,
// wavelength-constant and the same over the array. The renderer samples it in the second of
// two steps — a point on the pixel's active area, then an offset drawn from the PSF — so each
// pixel's response is its area convolved with the PSF, by importance sampling with weight 1.
//
// Offsets are in output-pixel units (dx along the columns, dy along the lines, as the ENVI
// image is drawn); PixelRaySource applies them before the array's flips, so a PSF image
// appears in the output as drawn.
//   Gaussian   <width> σ: dx, dy independent normals of standard deviation σ, drawn exactly
//              (Box–Muller on two uniforms).
//   image      a grey image (any type OpenImageIO reads; values linear), centred on the
//              point, its width spanning <scale> pixels (square pixels: its height spans
//              scale × height / width), normalised to unit volume, drawn from its PixelTable
//              (pixel_table.h).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "glint/model/capture.h"
#include "glint/sensor/pixel_table.h"

namespace glint::sensor {

class PsfSampler {
public:
    /// A Gaussian of standard deviation `sigma_px` (> 0, finite) pixels.
    static PsfSampler gaussian(double sigma_px);
    /// A tabulated PSF: `weights` row-major, `width` × `height`, line 0 at the top, all finite
    /// and >= 0 with a positive sum; its width spans `extent_px` (> 0) pixels. Throws
    /// glint::Error (input, no context) otherwise (PixelTable's messages).
    static PsfSampler table(std::vector<double> weights, std::size_t width, std::size_t height,
                            double extent_px);
    /// The PSF a focal plane's <psf> describes: its Gaussian, or the table of its image's
    /// values (Psf::weights, read with the platform by glint/inputs/load.h). Throws
    /// glint::Error (input, at the element) for weights PixelTable refuses, (internal) when
    /// the image was not read.
    static PsfSampler from_model(const model::Psf& psf);

    /// The offset (dx, dy) in pixels for two uniforms in [0, 1).
    std::array<double, 2> offset_px(double r1, double r2) const noexcept;
    /// How far from the point the PSF reaches, in pixels: 4σ for a Gaussian (6·10⁻⁴ of the
    /// draws lie beyond, per axis), the half-diagonal of an image's extent.
    double reach_px() const noexcept;
    /// A one-line description for headers and logs: "gaussian sigma 3.8 px", "image
    /// airy.png 64 x 64 over 10 px".
    const std::string& description() const noexcept { return m_description; }

private:
    PsfSampler() = default;

    double m_sigma_px = 0.0;  ///< > 0 for a Gaussian
    std::optional<PixelTable> m_table;
    double m_pixel_px = 0.0;  ///< the focal-plane size of one image pixel
    std::string m_description;
};

}  // namespace glint::sensor
