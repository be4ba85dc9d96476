// SPDX-License-Identifier: Apache-2.0
// Bayer demosaicing: bilinear and Malvar–He–Cutler gradient-corrected linear interpolation,
// over a plane padded by reflect-101 mirroring (padded.h). The kernels are written out below
// as sums over neighbours; docs/tools/glint-demosaic.md draws them.
#include <cstddef>

#include "glint/demosaic/demosaic.h"
#include "padded.h"
#include "validate.h"

namespace glint::demosaic {
namespace {

using internal::PaddedPlane;

/// The neighbours a kernel reads around one pixel of a padded plane.
struct Neighbours {
    const double* p;
    std::ptrdiff_t s;  // stride

    double at(std::ptrdiff_t dx, std::ptrdiff_t dy) const { return p[dy * s + dx]; }
    double centre() const { return p[0]; }
    double west_east() const { return at(-1, 0) + at(1, 0); }
    double north_south() const { return at(0, -1) + at(0, 1); }
    double diagonals() const { return at(-1, -1) + at(1, -1) + at(-1, 1) + at(1, 1); }
    double west_east_2() const { return at(-2, 0) + at(2, 0); }
    double north_south_2() const { return at(0, -2) + at(0, 2); }
};

/// One output pixel: the filter at it, and the filters of its east and south neighbours
/// (which, at a green pixel, say where the red and the blue samples are).
struct Site {
    CfaColor own;
    CfaColor east;
    CfaColor south;
};

Site site_of(BayerPhase phase, std::size_t x, std::size_t y) {
    return {bayer_color(phase, x, y), bayer_color(phase, x + 1, y), bayer_color(phase, x, y + 1)};
}

/// The other chroma filter: red ↔ blue.
CfaColor other_chroma(CfaColor c) { return c == CfaColor::red ? CfaColor::blue : CfaColor::red; }

void bilinear_pixel(const Neighbours& n, const Site& site, double* rgb) {
    const double v = n.centre();
    rgb[static_cast<int>(site.own)] = v;
    if (site.own == CfaColor::green) {
        rgb[static_cast<int>(site.east)] = 0.5 * n.west_east();
        rgb[static_cast<int>(site.south)] = 0.5 * n.north_south();
    } else {
        rgb[1] = 0.25 * (n.west_east() + n.north_south());
        rgb[static_cast<int>(other_chroma(site.own))] = 0.25 * n.diagonals();
    }
}

void mhc_pixel(const Neighbours& n, const Site& site, double* rgb) {
    const double v = n.centre();
    rgb[static_cast<int>(site.own)] = v;
    if (site.own == CfaColor::green) {
        // Chroma at green: the chroma along the line (or column) that holds it.
        const double common = 5.0 * v - n.diagonals();
        rgb[static_cast<int>(site.east)] =
            (common + 4.0 * n.west_east() - n.west_east_2() + 0.5 * n.north_south_2()) / 8.0;
        rgb[static_cast<int>(site.south)] =
            (common + 4.0 * n.north_south() - n.north_south_2() + 0.5 * n.west_east_2()) / 8.0;
    } else {
        const double axial_2 = n.west_east_2() + n.north_south_2();
        rgb[1] = (4.0 * v + 2.0 * (n.west_east() + n.north_south()) - axial_2) / 8.0;
        rgb[static_cast<int>(other_chroma(site.own))] =
            (6.0 * v + 2.0 * n.diagonals() - 1.5 * axial_2) / 8.0;
    }
}

template <typename PixelFunction>
RgbImage run_bayer(const Plane& mosaic, BayerPhase phase, const CancelToken* cancel,
                   PixelFunction&& pixel_function) {
    internal::check_plane(mosaic, CfaPattern::bayer);
    const PaddedPlane padded(mosaic, 2);
    RgbImage out{mosaic.width, mosaic.height, std::vector<double>(mosaic.values.size() * 3)};
    for (std::size_t y = 0; y < mosaic.height; ++y) {
        if (cancel != nullptr) cancel->throw_if_cancelled();
        double* rgb = out.rgb.data() + y * mosaic.width * 3;
        for (std::size_t x = 0; x < mosaic.width; ++x, rgb += 3) {
            pixel_function(Neighbours{padded.pixel(x, y), padded.stride()}, site_of(phase, x, y),
                           rgb);
        }
    }
    return out;
}

}  // namespace

RgbImage demosaic_bayer_bilinear(const Plane& mosaic, BayerPhase phase, const CancelToken* cancel) {
    return run_bayer(mosaic, phase, cancel, bilinear_pixel);
}

RgbImage demosaic_bayer_mhc(const Plane& mosaic, BayerPhase phase, const CancelToken* cancel) {
    return run_bayer(mosaic, phase, cancel, mhc_pixel);
}

}  // namespace glint::demosaic
