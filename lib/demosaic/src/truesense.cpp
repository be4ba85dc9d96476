// SPDX-License-Identifier: Apache-2.0
// TrueSense demosaicing, pan-guided: pan at every pixel, then each colour as pan plus its
// colour difference spread by normalized convolution (demosaic.h gives the method). Only
// pixels inside the image are used, so borders need no padding.
//
// Line by line: output line y needs the tent-filtered differences of lines y - 3 ... y + 3,
// line y' of those needs pan on line y', and pan on y' needs mosaic lines y' - 1 ... y' + 1.
// Three windows (line_window.h) hold them: mosaic lines, pan lines, and per line the
// differences and colour masks filtered along x; the filter along y sums the latter. The sums
// run in the order of the separable filter over whole planes (x first, then y, offsets from
// -3 to 3), so the values do not depend on how the image is streamed.
#include <algorithm>
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

/// Half-width of the normalized-convolution window and the tent's base: weights
/// (kTent - |d|) for |d| <= kRadius along each axis.
constexpr std::ptrdiff_t kRadius = 3;
constexpr double kTent = 4.0;
constexpr std::array<CfaColor, 3> kColors = {CfaColor::red, CfaColor::green, CfaColor::blue};

double tent_weight(std::ptrdiff_t d) { return kTent - static_cast<double>(d < 0 ? -d : d); }

/// One line filtered along x: for each colour, the differences C - pan at the colour's own
/// pixels (zero elsewhere) and the colour's mask (1 at its pixels, else 0).
struct FilteredLine {
    std::array<std::vector<double>, 3> difference;
    std::array<std::vector<double>, 3> mask;
};

class TrueSenseLines final : public internal::LineDemosaicker {
public:
    TrueSenseLines(std::size_t width, std::size_t height, MosaicLineReader read)
        : m_width(width),
          m_height(height),
          m_mosaic([this, read = std::move(read)](std::size_t y, std::vector<double>& line) {
              line.resize(m_width);
              read(y, line);
          }),
          m_pan([this](std::size_t y, std::vector<double>& line) { make_pan(y, line); }),
          m_filtered([this](std::size_t y, FilteredLine& line) { make_filtered(y, line); }),
          m_weighted(width),
          m_unit(width) {}

    void line(std::size_t y, std::span<double> rgb) override {
        const std::size_t first = y >= kRadius ? y - kRadius : 0;
        const std::size_t last = std::min(m_height - 1, y + kRadius);
        std::array<const FilteredLine*, 2 * kRadius + 1> window{};
        for (std::size_t yy = first; yy <= last; ++yy) window[yy - first] = &m_filtered.at(yy);
        const std::vector<double>& mosaic = m_mosaic.at(y);
        const std::vector<double>& pan = m_pan.at(y);
        for (std::size_t c = 0; c < kColors.size(); ++c) {
            for (std::size_t x = 0; x < m_width; ++x) {
                double numerator = 0.0;
                double denominator = 0.0;
                for (std::size_t yy = first; yy <= last; ++yy) {
                    const double weight = tent_weight(static_cast<std::ptrdiff_t>(yy) -
                                                      static_cast<std::ptrdiff_t>(y));
                    numerator += weight * window[yy - first]->difference[c][x];
                    denominator += weight * window[yy - first]->mask[c][x];
                }
                // Every window of at least 4 × 4 pixels holds every colour: the denominator
                // is > 0.
                rgb[x * 3 + c] = truesense_color(x, y) == kColors[c]
                                     ? mosaic[x]
                                     : pan[x] + numerator / denominator;
            }
        }
        // Line y + 1 reads filtered lines from y + 1 - kRadius on, pan and mosaic from y + 1.
        if (y + 1 > kRadius) m_filtered.drop_below(y + 1 - kRadius);
        m_pan.drop_below(y + 1);
        m_mosaic.drop_below(y + 1);
    }

private:
    /// Pan at every pixel of line y: the sample at pan pixels, the mean of the edge neighbours
    /// inside the image at colour pixels (all of them pan: pan lies on a checkerboard).
    void make_pan(std::size_t y, std::vector<double>& pan) {
        const std::vector<double>* above = y > 0 ? &m_mosaic.at(y - 1) : nullptr;
        const std::vector<double>* below = y + 1 < m_height ? &m_mosaic.at(y + 1) : nullptr;
        const std::vector<double>& m = m_mosaic.at(y);
        pan = m;
        for (std::size_t x = 0; x < m_width; ++x) {
            if (truesense_color(x, y) == CfaColor::pan) continue;
            double sum = 0.0;
            double count = 0.0;
            if (x > 0) sum += m[x - 1], count += 1.0;
            if (x + 1 < m_width) sum += m[x + 1], count += 1.0;
            if (above != nullptr) sum += (*above)[x], count += 1.0;
            if (below != nullptr) sum += (*below)[x], count += 1.0;
            pan[x] = sum / count;
        }
    }

    void make_filtered(std::size_t y, FilteredLine& line) {
        const std::vector<double>& m = m_mosaic.at(y);
        const std::vector<double>& pan = m_pan.at(y);
        for (std::size_t c = 0; c < kColors.size(); ++c) {
            for (std::size_t x = 0; x < m_width; ++x) {
                const bool own = truesense_color(x, y) == kColors[c];
                m_weighted[x] = own ? m[x] - pan[x] : 0.0;
                m_unit[x] = own ? 1.0 : 0.0;
            }
            tent_along_x(m_weighted, line.difference[c]);
            tent_along_x(m_unit, line.mask[c]);
        }
    }

    /// The tent filter of `in` along the line, zero outside the image.
    void tent_along_x(const std::vector<double>& in, std::vector<double>& out) const {
        out.resize(m_width);
        const auto w = static_cast<std::ptrdiff_t>(m_width);
        for (std::ptrdiff_t x = 0; x < w; ++x) {
            double sum = 0.0;
            for (std::ptrdiff_t d = -kRadius; d <= kRadius; ++d) {
                const std::ptrdiff_t xx = x + d;
                if (xx < 0 || xx >= w) continue;
                sum += tent_weight(d) * in[static_cast<std::size_t>(xx)];
            }
            out[static_cast<std::size_t>(x)] = sum;
        }
    }

    std::size_t m_width;
    std::size_t m_height;
    internal::LineWindow<std::vector<double>> m_mosaic;
    internal::LineWindow<std::vector<double>> m_pan;
    internal::LineWindow<FilteredLine> m_filtered;
    std::vector<double> m_weighted;  ///< scratch of make_filtered
    std::vector<double> m_unit;
};

}  // namespace

namespace internal {

std::unique_ptr<LineDemosaicker> make_truesense(std::size_t width, std::size_t height,
                                                MosaicLineReader read) {
    return std::make_unique<TrueSenseLines>(width, height, std::move(read));
}

std::size_t truesense_values_held(std::size_t width) {
    // Windows plus one spare each: mosaic lines y ... y + kRadius + 1 (5 + 1), pan lines
    // y ... y + kRadius (4 + 1), filtered lines y - kRadius ... y + kRadius (7 + 1) of six
    // values per pixel; two scratch lines.
    constexpr std::size_t kMosaicLines = kRadius + 3;
    constexpr std::size_t kPanLines = kRadius + 2;
    constexpr std::size_t kFilteredLines = 2 * kRadius + 2;
    return (kMosaicLines + kPanLines + 6 * kFilteredLines + 2) * width;
}

}  // namespace internal
}  // namespace glint::demosaic
