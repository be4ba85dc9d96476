// SPDX-License-Identifier: Apache-2.0
// Bayer demosaicing: bilinear and Malvar–He–Cutler gradient-corrected linear interpolation,
// line by line over a window of five mosaic lines extended by reflect-101 mirroring
// (line_demosaicker.h). The kernels are written out below as sums over neighbours;
// docs/tools/glint-demosaic.md draws them.
#include <array>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "glint/demosaic/demosaic.h"
#include "line_demosaicker.h"
#include "line_window.h"

namespace glint::demosaic {
namespace {

/// The neighbours a kernel reads around one pixel of a padded plane.
struct Neighbours {
    const double* const* rows;  ///< mosaic lines y - 2 ... y + 2, each padded by 2 values
    std::ptrdiff_t x;

    double at(std::ptrdiff_t dx, std::ptrdiff_t dy) const { return rows[dy + 2][x + dx]; }
    double centre() const { return at(0, 0); }
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

/// Kernels reach 2 pixels from their centre along each axis.
constexpr std::ptrdiff_t kMargin = 2;
constexpr std::size_t kRows = 2 * kMargin + 1;

using PixelFunction = void (*)(const Neighbours&, const Site&, double*);

/// Bayer output lines from a window of mosaic lines, each padded by kMargin mirrored values at
/// both ends.
class BayerLines final : public internal::LineDemosaicker {
public:
    BayerLines(std::size_t width, std::size_t height, BayerPhase phase,
               PixelFunction pixel_function, MosaicLineReader read)
        : m_width(width),
          m_height(height),
          m_phase(phase),
          m_pixel(pixel_function),
          m_mosaic([this, read = std::move(read)](std::size_t y, std::vector<double>& line) {
              read_padded(read, y, line);
          }) {}

    void line(std::size_t y, std::span<double> rgb) override {
        const auto h = static_cast<std::ptrdiff_t>(m_height);
        std::array<const double*, kRows> rows{};
        for (std::ptrdiff_t dy = -kMargin; dy <= kMargin; ++dy) {
            const auto source = internal::reflect101(static_cast<std::ptrdiff_t>(y) + dy, h);
            rows[static_cast<std::size_t>(dy + kMargin)] =
                m_mosaic.at(static_cast<std::size_t>(source)).data() + kMargin;
        }
        double* out = rgb.data();
        for (std::size_t x = 0; x < m_width; ++x, out += 3) {
            m_pixel(Neighbours{rows.data(), static_cast<std::ptrdiff_t>(x)},
                    site_of(m_phase, x, y), out);
        }
        // Line y + 1 reads mosaic lines from y + 1 - kMargin on (mirrored ones included).
        if (y + 1 > static_cast<std::size_t>(kMargin)) m_mosaic.drop_below(y + 1 - kMargin);
    }

private:
    void read_padded(const MosaicLineReader& read, std::size_t y, std::vector<double>& line) const {
        line.resize(m_width + 2 * kMargin);
        read(y, std::span<double>(line).subspan(kMargin, m_width));
        const auto w = static_cast<std::ptrdiff_t>(m_width);
        for (std::ptrdiff_t x = -kMargin; x < 0; ++x) {
            line[static_cast<std::size_t>(x + kMargin)] =
                line[static_cast<std::size_t>(internal::reflect101(x, w) + kMargin)];
        }
        for (std::ptrdiff_t x = w; x < w + kMargin; ++x) {
            line[static_cast<std::size_t>(x + kMargin)] =
                line[static_cast<std::size_t>(internal::reflect101(x, w) + kMargin)];
        }
    }

    std::size_t m_width;
    std::size_t m_height;
    BayerPhase m_phase;
    PixelFunction m_pixel;
    internal::LineWindow<std::vector<double>> m_mosaic;
};

}  // namespace

namespace internal {

std::unique_ptr<LineDemosaicker> make_bayer(std::size_t width, std::size_t height,
                                            BayerPhase phase, DemosaicMethod method,
                                            MosaicLineReader read) {
    const PixelFunction pixel = method == DemosaicMethod::mhc ? mhc_pixel : bilinear_pixel;
    return std::make_unique<BayerLines>(width, height, phase, pixel, std::move(read));
}

std::size_t bayer_values_held(std::size_t width) {
    // kRows lines in the window and one spare, each padded.
    return (kRows + 1) * (width + 2 * kMargin);
}

}  // namespace internal

}  // namespace glint::demosaic
