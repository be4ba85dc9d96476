// SPDX-License-Identifier: Apache-2.0
// PsfSampler: the Gaussian draw and the 2-D table of an image PSF (psf.h).
#include "glint/sensor/psf.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::sensor {

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
        throw input_error(
            "the PSF scale (the image's extent in pixels) must be a finite number "
            "> 0, got " +
            format_shortest(extent_px));
    }
    PsfSampler psf;
    psf.m_table.emplace(weights, width, height);
    psf.m_pixel_px = extent_px / static_cast<double>(width);
    psf.m_description = std::to_string(width) + " x " + std::to_string(height) + " image over " +
                        format_shortest(extent_px) + " px";
    return psf;
}

PsfSampler PsfSampler::from_model(const model::Psf& psf) {
    try {
        if (psf.width_px) return gaussian(*psf.width_px);
        if (psf.weights.empty()) {
            throw internal_error(format_located(
                psf.where, "<psf><image> " + quote(psf.image.text) + " was not read"));
        }
        PsfSampler sampler =
            table(psf.weights.values, psf.weights.width, psf.weights.height, psf.scale_px);
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
    const std::array<double, 2> at = m_table->sample(r1, r2);
    return {(at[0] - 0.5 * static_cast<double>(m_table->width())) * m_pixel_px,
            (at[1] - 0.5 * static_cast<double>(m_table->height())) * m_pixel_px};
}

double PsfSampler::reach_px() const noexcept {
    if (m_sigma_px > 0.0) return 4.0 * m_sigma_px;
    return 0.5 * m_pixel_px *
           std::hypot(static_cast<double>(m_table->width()),
                      static_cast<double>(m_table->height()));
}

}  // namespace glint::sensor
