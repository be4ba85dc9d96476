// SPDX-License-Identifier: Apache-2.0
// The stratified wavelength draw of a path (glint/radiometry/spectral_draw.h).
#include "glint/radiometry/spectral_draw.h"

#include <algorithm>
#include <limits>
#include <string>

#include "glint/core/error.h"

namespace glint::radiometry {

SpectralDraw::SpectralDraw(std::size_t first, std::size_t count, std::size_t reference,
                           unsigned samples)
    : m_first(first), m_count(count), m_reference(reference) {
    if (samples == 1) {
        throw usage_error(
            "1 spectral sample per path cannot be drawn: use 0 (every band) or at least 2 (the "
            "reference band and one more)");
    }
    if (count > std::numeric_limits<std::uint32_t>::max() - first) {
        throw usage_error("spectral sampling supports up to 2^32 - 1 bands, not " +
                          std::to_string(first + count));
    }
    if (reference >= count) {
        throw usage_error("reference band " + std::to_string(reference) + " is out of range for " +
                          std::to_string(count) + " bands");
    }
    if (samples < 2 || samples >= count) return;  // every band
    const std::size_t remaining = count - 1;
    const std::size_t others = samples - 1;
    m_offsets.resize(others);
    for (std::size_t j = 0; j < others; ++j) {
        m_offsets[j] = static_cast<std::uint32_t>(j * remaining / others);
    }
    m_weight = static_cast<double>(remaining) / static_cast<double>(others);
}

void SpectralDraw::draw(double u, std::span<std::uint32_t> grid_bands,
                        std::span<std::uint32_t> bands) const noexcept {
    const std::size_t remaining = m_count - 1;
    const std::size_t offset =
        std::min(remaining - 1, static_cast<std::size_t>(u * static_cast<double>(remaining)));
    bands[0] = static_cast<std::uint32_t>(m_reference);
    for (std::size_t j = 0; j < m_offsets.size(); ++j) {
        std::size_t i = offset + m_offsets[j];
        if (i >= remaining) i -= remaining;
        bands[j + 1] = static_cast<std::uint32_t>(i < m_reference ? i : i + 1);
    }
    for (std::size_t j = 0; j < bands.size(); ++j) {
        grid_bands[j] = static_cast<std::uint32_t>(m_first + bands[j]);
    }
}

}  // namespace glint::radiometry
