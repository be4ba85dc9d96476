// SPDX-License-Identifier: Apache-2.0
// PsfSampler: the Gaussian draw and the 2-D table of an image PSF (psf.h).
#include "glint/sensor/psf.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/io/image.h"

namespace glint::sensor {
namespace {

/// The largest PSF image read: a PSF is a small pattern; 4096² doubles are 128 MB.
constexpr std::size_t kMaxPsfPixels = std::size_t{4096} * 4096;

/// The index i of `cdf` (ascending, cdf.front() = 0, cdf.back() = 1) with cdf[i] <= r <
/// cdf[i + 1], skipping empty cells, and where r falls inside it (0 … 1).
std::pair<std::size_t, double> locate(const double* cdf, std::size_t cells, double r) {
    const double* upper = std::upper_bound(cdf + 1, cdf + cells + 1, r);
    std::size_t i = static_cast<std::size_t>(upper - cdf) - 1;
    if (i >= cells) i = cells - 1;  // r at the top (rounding)
    const double width = cdf[i + 1] - cdf[i];
    const double inside = width > 0.0 ? std::clamp((r - cdf[i]) / width, 0.0, 1.0) : 0.5;
    return {i, inside};
}

/// Turns `sums` (cells values >= 0) into a CDF of cells + 1 values; false when all are 0.
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

PsfSampler PsfSampler::gaussian(double sigma_px) {
    if (!std::isfinite(sigma_px) || !(sigma_px > 0.0)) {
        throw input_error("the PSF width (1 sigma, pixels) must be a finite number > 0, got " +
                          format_shortest(sigma_px));
    }
    PsfSampler psf;
    psf.m_sigma_px = sigma_px;
    psf.m_description = "gaussian sigma " + format_shortest(sigma_px) + " px";
    return psf;
}

PsfSampler PsfSampler::table(std::vector<double> weights, std::size_t width, std::size_t height,
                             double extent_px) {
    if (!std::isfinite(extent_px) || !(extent_px > 0.0)) {
        throw input_error("the PSF scale (the image's extent in pixels) must be a finite number "
                          "> 0, got " +
                          format_shortest(extent_px));
    }
    if (width == 0 || height == 0 || weights.size() != width * height) {
        throw input_error("the PSF image is empty");
    }
    for (const double w : weights) {
        if (!std::isfinite(w) || w < 0.0) {
            throw input_error("the PSF image holds a negative or non-finite value (" +
                              format_shortest(w) + ")");
        }
    }
    PsfSampler psf;
    psf.m_width = width;
    psf.m_height = height;
    psf.m_pixel_px = extent_px / static_cast<double>(width);
    psf.m_column_cdf.resize(height * (width + 1));
    std::vector<double> line_sums(height, 0.0);
    for (std::size_t y = 0; y < height; ++y) {
        const double* line = weights.data() + y * width;
        for (std::size_t x = 0; x < width; ++x) line_sums[y] += line[x];
        if (!to_cdf(line, width, psf.m_column_cdf.data() + y * (width + 1))) {
            // An empty line is never chosen (its marginal probability is 0).
            std::fill_n(psf.m_column_cdf.data() + y * (width + 1), width + 1, 0.0);
        }
    }
    psf.m_line_cdf.resize(height + 1);
    if (!to_cdf(line_sums.data(), height, psf.m_line_cdf.data())) {
        throw input_error("the PSF image is all zero");
    }
    psf.m_description = std::to_string(width) + " x " + std::to_string(height) +
                        " image over " + format_shortest(extent_px) + " px";
    return psf;
}

PsfSampler PsfSampler::from_model(const model::Psf& psf) {
    try {
        if (psf.width_px) return gaussian(*psf.width_px);
        io::ImageReader reader(psf.image.resolved);
        const io::ImageInfo& info = reader.info();
        if (info.width * info.height > kMaxPsfPixels) {
            throw input_error("the PSF image " + quote(psf.image.text) + " is " +
                              std::to_string(info.width) + " x " + std::to_string(info.height) +
                              " pixels; a PSF image holds at most 4096 x 4096");
        }
        std::vector<double> line(info.width * info.channels);
        std::vector<double> weights(info.width * info.height);
        for (std::size_t y = 0; y < info.height; ++y) {
            reader.read_line(y, line);
            for (std::size_t x = 0; x < info.width; ++x) {
                weights[y * info.width + x] = line[x * info.channels];
            }
        }
        PsfSampler sampler = table(std::move(weights), info.width, info.height, psf.scale_px);
        sampler.m_description = "image " + psf.image.text + " " + sampler.m_description;
        return sampler;
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input && e.category() != ErrorCategory::io) throw;
        const std::string what = psf.width_px ? "<psf>" : "<psf><image> " + quote(psf.image.text);
        throw input_error(what + ": " + e.message(), psf.where);
    }
}

std::array<double, 2> PsfSampler::offset_px(double r1, double r2) const noexcept {
    if (m_sigma_px > 0.0) {
        // Box–Muller: 1 − r1 in (0, 1], so the logarithm is finite.
        const double radius = m_sigma_px * std::sqrt(-2.0 * std::log(1.0 - r1));
        const double angle = 2.0 * std::numbers::pi * r2;
        return {radius * std::cos(angle), radius * std::sin(angle)};
    }
    const auto [line, in_line] = locate(m_line_cdf.data(), m_height, r1);
    const auto [column, in_column] =
        locate(m_column_cdf.data() + line * (m_width + 1), m_width, r2);
    const double x = (static_cast<double>(column) + in_column) - 0.5 * static_cast<double>(m_width);
    const double y = (static_cast<double>(line) + in_line) - 0.5 * static_cast<double>(m_height);
    return {x * m_pixel_px, y * m_pixel_px};
}

double PsfSampler::reach_px() const noexcept {
    if (m_sigma_px > 0.0) return 4.0 * m_sigma_px;
    return 0.5 * m_pixel_px * std::hypot(static_cast<double>(m_width), static_cast<double>(m_height));
}

}  // namespace glint::sensor
