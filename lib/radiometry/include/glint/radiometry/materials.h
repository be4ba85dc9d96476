// SPDX-License-Identifier: Apache-2.0
// A scene's materials sampled on one spectral grid, as the path tracer uses them: per band
// the reflectance ρ(λ), the diffuse transmittance τ(λ) of a thin sheet (0 when opaque) and
// the emitted radiance ε(λ) B(λ, T); per material the wavelength-independent lobe shape
// (SurfaceBrdf with ρ = 1, so f_λ = ρ(λ) · shape) and the transmission f_λ = τ(λ)/π. Tables are
// held flat ([material][band]) so a path touches no allocation. Curves are linearly interpolated
// and held constant beyond their first and last wavelength (a warning names each material
// whose curve does not cover the grid). Units: emitted radiance W/(cm² sr µm).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "glint/core/log.h"
#include "glint/core/spectral.h"
#include "glint/model/scene.h"
#include "glint/radiometry/brdf.h"

namespace glint::radiometry {

/// The materials of a scene on a spectral grid.
class MaterialTable {
public:
    /// Samples every material of `materials` on `grid`. Throws glint::Error (input, at the
    /// material) for a reflectance or emissivity outside [0, 1] after interpolation, ε + ρ > 1
    /// + model::kEmissivityReflectanceSlack at a band inside both curves' range (within the
    /// slack ρ is lowered to 1 − ε), or a non-positive temperature.
    MaterialTable(std::span<const model::Material> materials, const SpectralGrid& grid,
                  Log log = {});

    /// Number of materials.
    std::size_t size() const noexcept { return m_shapes.size(); }
    /// Number of bands.
    std::size_t bands() const noexcept { return m_bands; }
    /// ρ(λ) of material `m`, one value per band.
    std::span<const double> reflectance(std::size_t m) const noexcept {
        return {m_reflectance.data() + m * m_bands, m_bands};
    }
    /// ε(λ) B(λ, T) of material `m`, W/(cm² sr µm), one value per band.
    std::span<const double> emission_w_per_cm2_sr_um(std::size_t m) const noexcept {
        return {m_emission.data() + m * m_bands, m_bands};
    }
    /// Whether material `m` emits anything on the grid (skips a loop per hit when not).
    bool emits(std::size_t m) const noexcept { return m_emits[m] != 0; }
    /// Whether material `m` reflects anything on the grid.
    bool reflects(std::size_t m) const noexcept { return m_reflects[m] != 0; }
    /// τ(λ) of material `m`, one value per band: 0 for an opaque material.
    std::span<const double> transmittance(std::size_t m) const noexcept {
        return {m_transmittance.data() + m * m_bands, m_bands};
    }
    /// Whether material `m` (a thin sheet) transmits anything on the grid.
    bool transmits(std::size_t m) const noexcept { return m_transmits[m] != 0; }
    /// Whether both faces of material `m` have its properties (false: the back face, against
    /// the triangle's winding, is black).
    bool double_sided(std::size_t m) const noexcept { return m_double_sided[m] != 0; }
    /// Whether a path goes on from material `m`: it reflects or transmits.
    bool scatters(std::size_t m) const noexcept { return reflects(m) || transmits(m); }
    /// The probability with which a path leaving material `m` is transmitted rather than
    /// reflected: Σ τ / Σ (ρ + τ) over the bands; 0 for an opaque material.
    double transmission_probability(std::size_t m) const noexcept {
        return m_transmission_probability[m];
    }
    /// The lobe shape of material `m`: SurfaceBrdf(1, s, roughness).
    const SurfaceBrdf& shape(std::size_t m) const noexcept { return m_shapes[m]; }

private:
    std::size_t m_bands = 0;
    std::vector<double> m_reflectance;
    std::vector<double> m_emission;
    std::vector<unsigned char> m_emits;
    std::vector<unsigned char> m_reflects;
    std::vector<double> m_transmittance;
    std::vector<unsigned char> m_transmits;
    std::vector<unsigned char> m_double_sided;
    std::vector<double> m_transmission_probability;
    std::vector<SurfaceBrdf> m_shapes;
};

}  // namespace glint::radiometry
