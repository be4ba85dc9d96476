// SPDX-License-Identifier: Apache-2.0
// A scene's materials sampled on one spectral grid, as the path tracer uses them: per band
// the reflectance ρ(λ), the diffuse transmittance τ(λ) of a thin sheet (0 when opaque) and
// the emitted radiance ε(λ) B(λ, T); per material the wavelength-independent scattering
// shape (Bsdf: f_λ = ρ(λ) · R on the side of wo, τ(λ)/π through a thin sheet). A directional
// lobe whose albedo A(θo) is not 1 and whose emissivity is Kirchhoff's emits
// [1 − τ(λ) − ρ(λ) A(θo)] B(λ, T) towards θo (emission_at). Tables are
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
#include "glint/radiometry/bsdf.h"

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
    /// Whether material `m` is a clear sheet: its transmittance passes straight through.
    bool straight(std::size_t m) const noexcept { return m_shapes[m].straight(); }
    /// Whether any material is a clear sheet (shadow rays must then pass them).
    bool any_straight() const noexcept { return m_any_straight; }
    /// Whether both faces of material `m` have its properties (false: the back face, against
    /// the triangle's winding, is black).
    bool double_sided(std::size_t m) const noexcept { return m_double_sided[m] != 0; }
    /// Whether a path goes on from material `m`: it reflects or transmits.
    bool scatters(std::size_t m) const noexcept { return reflects(m) || transmits(m); }
    /// The probability with which a path leaving material `m` is transmitted rather than
    /// reflected: Σ τ / Σ (ρ + τ) over the bands; 0 for an opaque material.
    double transmission_probability(std::size_t m) const noexcept {
        return m_shapes[m].transmission_probability();
    }
    /// The scattering shape of material `m`.
    const Bsdf& bsdf(std::size_t m) const noexcept { return m_shapes[m]; }
    /// Whether material `m`'s emission depends on the direction (Kirchhoff's emissivity of a
    /// lobe whose albedo is not 1): use emission_at().
    bool directional_emission(std::size_t m) const noexcept { return m_albedo_slot[m] != kNoSlot; }
    /// Material `m`'s emission towards a direction at cos θo from its normal, W/(cm² sr µm),
    /// at the bands `bands` (indices into the grid) written into `out` at the same indices:
    /// ε(λ) B + ρ(λ) B (1 − A(θo)) with ε = 1 − ρ − τ the table's.
    template <typename Bands>
    void emission_at(std::size_t m, double cos_o, const Bands& bands,
                     std::span<double> out) const noexcept {
        const double absorbed = 1.0 - m_albedos[m_albedo_slot[m]].at(cos_o);
        const double* e = m_emission.data() + m * m_bands;
        const double* rb = m_reflected_planck.data() + m_albedo_slot[m] * m_bands;
        for (std::size_t j = 0; j < bands.size(); ++j) {
            const std::size_t b = bands[j];
            out[b] = e[b] + rb[b] * absorbed;
        }
    }

    /// Material `m`'s emission at temperature `temperature_k` (a temperature map's) instead of
    /// its own, towards cos θo, at the bands `bands`, written into `out` at the same indices:
    /// ε(λ) B(λ, T), plus ρ(λ) B(λ, T) (1 − A(θo)) for a directional lobe.
    template <typename Bands>
    void emission_at_temperature(std::size_t m, double temperature_k, double cos_o,
                                 const Bands& bands, std::span<double> out) const {
        const double* eps = m_emissivity.data() + m * m_bands;
        const double* rho = m_reflectance.data() + m * m_bands;
        const double absorbed =
            directional_emission(m) ? 1.0 - m_albedos[m_albedo_slot[m]].at(cos_o) : 0.0;
        for (std::size_t j = 0; j < bands.size(); ++j) {
            const std::size_t b = bands[j];
            const double planck =
                planck_radiance_w_per_cm2_sr_um(m_wavelengths_um[b], temperature_k);
            out[b] = (eps[b] + rho[b] * absorbed) * planck;
        }
    }

    /// What material `m` emits towards cos θo at the bands `bands`: nullptr when it emits
    /// nothing on the grid; its table's emission; or, when it depends on the direction
    /// (emission_at) or a temperature map gives `temperature_k` > 0 in place of the
    /// material's (emission_at_temperature), `scratch` filled at those bands.
    template <typename Bands>
    const double* emission_towards(std::size_t m, double temperature_k, double cos_o,
                                   const Bands& bands, std::span<double> scratch) const {
        if (temperature_k > 0.0) {
            emission_at_temperature(m, temperature_k, cos_o, bands, scratch);
            return scratch.data();
        }
        if (!emits(m)) return nullptr;
        if (!directional_emission(m)) return emission_w_per_cm2_sr_um(m).data();
        // Kirchhoff towards wo of a lobe whose albedo depends on the direction.
        emission_at(m, cos_o, bands, scratch);
        return scratch.data();
    }

private:
    /// Completes the last material added (its Bsdf is m_shapes.back()): refuses a lobe that
    /// reflects more than it receives and, for Kirchhoff's emissivity of a lobe whose albedo is
    /// not 1, keeps the albedo table and ρ B for emission_at().
    void add_directional_emission(const model::Material& material, const SpectralGrid& grid,
                                  const std::vector<double>& rho);

    std::size_t m_bands = 0;
    std::vector<double> m_reflectance;
    std::vector<double> m_emission;
    std::vector<double> m_emissivity;      ///< ε(λ) per material and band, as emission uses it
    std::vector<double> m_wavelengths_um;  ///< the grid's
    std::vector<unsigned char> m_emits;
    std::vector<unsigned char> m_reflects;
    std::vector<double> m_transmittance;
    std::vector<unsigned char> m_transmits;
    std::vector<unsigned char> m_double_sided;
    std::vector<Bsdf> m_shapes;
    bool m_any_straight = false;
    static constexpr std::size_t kNoSlot = static_cast<std::size_t>(-1);
    std::vector<std::size_t> m_albedo_slot;    ///< per material: index into m_albedos
    std::vector<DirectionalAlbedo> m_albedos;  ///< of the directional-emission materials
    std::vector<double> m_reflected_planck;    ///< ρ(λ) B(λ, T) per slot and band
};

}  // namespace glint::radiometry
