// SPDX-License-Identifier: Apache-2.0
// TrueSense demosaicing, pan-guided: pan at every pixel, then each colour as pan plus its
// colour difference spread by normalized convolution (demosaic.h gives the method). Only
// pixels inside the image are used, so borders need no padding.
#include <array>
#include <cstddef>

#include "glint/demosaic/demosaic.h"
#include "validate.h"

namespace glint::demosaic {
namespace {

/// Half-width of the normalized-convolution window and the tent's base: weights
/// (kTent - |d|) for |d| <= kRadius along each axis.
constexpr std::ptrdiff_t kRadius = 3;
constexpr double kTent = 4.0;

void poll(const CancelToken* cancel) {
    if (cancel != nullptr) cancel->throw_if_cancelled();
}

/// Pan at every pixel: the sample at pan pixels, the mean of the edge neighbours inside the
/// image at colour pixels (all of them pan: pan lies on a checkerboard).
Plane interpolate_pan(const Plane& m, const CancelToken* cancel) {
    Plane pan{m.width, m.height, m.values};
    for (std::size_t y = 0; y < m.height; ++y) {
        poll(cancel);
        for (std::size_t x = 0; x < m.width; ++x) {
            if (truesense_color(x, y) == CfaColor::pan) continue;
            double sum = 0.0;
            double count = 0.0;
            if (x > 0) sum += m.at(x - 1, y), count += 1.0;
            if (x + 1 < m.width) sum += m.at(x + 1, y), count += 1.0;
            if (y > 0) sum += m.at(x, y - 1), count += 1.0;
            if (y + 1 < m.height) sum += m.at(x, y + 1), count += 1.0;
            pan.at(x, y) = sum / count;
        }
    }
    return pan;
}

/// Separable tent filter of `in` (zero outside the image) along x (`along_x`) or y.
Plane tent_pass(const Plane& in, bool along_x, const CancelToken* cancel) {
    Plane out{in.width, in.height, std::vector<double>(in.values.size(), 0.0)};
    const auto w = static_cast<std::ptrdiff_t>(in.width);
    const auto h = static_cast<std::ptrdiff_t>(in.height);
    for (std::ptrdiff_t y = 0; y < h; ++y) {
        poll(cancel);
        for (std::ptrdiff_t x = 0; x < w; ++x) {
            double sum = 0.0;
            for (std::ptrdiff_t d = -kRadius; d <= kRadius; ++d) {
                const std::ptrdiff_t xx = along_x ? x + d : x;
                const std::ptrdiff_t yy = along_x ? y : y + d;
                if (xx < 0 || xx >= w || yy < 0 || yy >= h) continue;
                const double weight = kTent - static_cast<double>(d < 0 ? -d : d);
                sum += weight * in.values[static_cast<std::size_t>(yy * w + xx)];
            }
            out.values[static_cast<std::size_t>(y * w + x)] = sum;
        }
    }
    return out;
}

/// The colour difference C - pan of `color`, spread to every pixel.
Plane spread_difference(const Plane& m, const Plane& pan, CfaColor color,
                        const CancelToken* cancel) {
    Plane weighted{m.width, m.height, std::vector<double>(m.values.size(), 0.0)};
    Plane mask{m.width, m.height, std::vector<double>(m.values.size(), 0.0)};
    for (std::size_t y = 0; y < m.height; ++y) {
        for (std::size_t x = 0; x < m.width; ++x) {
            if (truesense_color(x, y) != color) continue;
            weighted.at(x, y) = m.at(x, y) - pan.at(x, y);
            mask.at(x, y) = 1.0;
        }
    }
    const Plane numerator = tent_pass(tent_pass(weighted, true, cancel), false, cancel);
    const Plane denominator = tent_pass(tent_pass(mask, true, cancel), false, cancel);
    Plane out{m.width, m.height, std::vector<double>(m.values.size())};
    for (std::size_t i = 0; i < out.values.size(); ++i) {
        // Every window of at least 4 × 4 pixels holds every colour: the denominator is > 0.
        out.values[i] = numerator.values[i] / denominator.values[i];
    }
    return out;
}

}  // namespace

RgbImage demosaic_truesense(const Plane& mosaic, const CancelToken* cancel) {
    internal::check_plane(mosaic, CfaPattern::truesense);
    const Plane pan = interpolate_pan(mosaic, cancel);
    RgbImage out{mosaic.width, mosaic.height, std::vector<double>(mosaic.values.size() * 3)};
    for (const CfaColor color : {CfaColor::red, CfaColor::green, CfaColor::blue}) {
        const Plane difference = spread_difference(mosaic, pan, color, cancel);
        const auto channel = static_cast<std::size_t>(color);
        for (std::size_t y = 0; y < mosaic.height; ++y) {
            for (std::size_t x = 0; x < mosaic.width; ++x) {
                const std::size_t i = y * mosaic.width + x;
                out.rgb[i * 3 + channel] = truesense_color(x, y) == color
                                               ? mosaic.values[i]
                                               : pan.values[i] + difference.values[i];
            }
        }
    }
    return out;
}

}  // namespace glint::demosaic
