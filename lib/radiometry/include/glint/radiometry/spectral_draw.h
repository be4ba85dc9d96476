// SPDX-License-Identifier: Apache-2.0
// Spectral sampling (docs/physics.md, "Spectral sampling"): the wavelengths one path follows
// when a tracer's TracerSettings::spectral_samples K is below its band count B. The
// reference band (the one the convergence rule watches) is followed by every path with
// weight 1; the other K − 1 are drawn from the remaining M = B − 1 bands as a stratified
// rotation: from one uniform u, o = ⌊u M⌋ and band i_j = (o + ⌊j M / (K − 1)⌋) mod M for
// j = 0 … K − 2 (counted over the remaining bands). The offsets ⌊j M / (K − 1)⌋ are distinct,
// so every remaining band is drawn with probability exactly (K − 1) / M and its radiance is
// weighted M / (K − 1): the estimator of every band is unbiased, and the K − 1 wavelengths
// of a path are spread evenly over the spectrum.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace glint::radiometry {

/// The draw for one tracer: `first`, `count` its bands (indices into the grid), `reference`
/// the reference band relative to `first`, `samples` the TracerSettings value.
class SpectralDraw {
public:
    SpectralDraw(std::size_t first, std::size_t count, std::size_t reference, unsigned samples);

    /// Whether paths follow a subset of the bands (2 <= samples < count).
    bool active() const noexcept { return !m_offsets.empty(); }
    /// Wavelengths per path: K when active, else the band count.
    std::size_t size() const noexcept { return active() ? m_offsets.size() + 1 : m_count; }
    /// The weight of each drawn band but the reference: M / (K − 1).
    double weight() const noexcept { return m_weight; }

    /// For `u` in [0, 1): writes the K bands, the reference band first, as grid indices to
    /// `grid_bands` and relative to `first` to `bands` (both size() long; active() only).
    void draw(double u, std::span<std::uint32_t> grid_bands,
              std::span<std::uint32_t> bands) const noexcept;

private:
    std::size_t m_first = 0;
    std::size_t m_count = 0;
    std::size_t m_reference = 0;
    std::vector<std::uint32_t> m_offsets;  ///< ⌊j M / (K − 1)⌋, j = 0 … K − 2
    double m_weight = 1.0;
};

}  // namespace glint::radiometry
