// SPDX-License-Identifier: Apache-2.0
// A material's scattering shape, the one interface the path tracer and the lidar tracer use:
// a reflection lobe (SurfaceBrdf — Lambertian, GGX or mirror —, DIRSIG's Ward BRDF, or
// Ross–Li) and, for a thin two-sided sheet, diffuse transmission. The shape is wavelength-
// independent; the material's spectra scale it, so the BSDF at wavelength λ is
//   f_λ(wo, wi) = ρ(λ) R(wo, wi)   when wo and wi lie on the same side of the surface,
//   f_λ(wo, wi) = τ(λ) / π         when they lie on opposite sides (diffusing sheet),
//   f_λ(wo, wi) = τ(λ) δ(wi + wo)/|cos θi|   straight through a clear sheet (a pane),
// with R the reflection lobe's shape (brdf.h, brdf_models.h). Local frame, normal +z facing
// wo; directions point away from the surface; values per steradian. docs/materials.md.
#pragma once

#include <array>
#include <optional>
#include <variant>

#include "glint/radiometry/brdf.h"
#include "glint/radiometry/brdf_models.h"

namespace glint::radiometry {

/// On which side of the surface a sampled direction lies.
enum class ScatterSide : unsigned char { reflected, transmitted };

/// A direction drawn by Bsdf::sample().
struct BsdfSample {
    Vec3 wi;                  ///< local unit direction
    double weight = 0.0;      ///< shape · |cos θi| / pdf: the spectrum (ρ or τ) multiplies it
    double pdf_per_sr = 0.0;  ///< density of wi per steradian; 0 for a delta (mirror) draw
    ScatterSide side = ScatterSide::reflected;
    bool delta = false;  ///< drawn from a mirror lobe
};

/// A material's wavelength-independent scattering shape.
class Bsdf {
public:
    using Reflection = std::variant<SurfaceBrdf, WardBrdf, RossLiBrdf>;

    /// The shape with reflection lobe `reflection`; a path is transmitted with probability
    /// `transmission_probability` in [0, 1] (0: opaque; 1: a sheet that reflects nothing). Throws
    /// glint::Error (input) outside that range.
    Bsdf(Reflection reflection, double transmission_probability, bool straight = false);

    /// The reflection lobe.
    const Reflection& reflection_lobe() const noexcept { return m_reflection; }
    /// R(wo, wi) in sr⁻¹, 0 unless both lie above the surface (a mirror's delta is not in it).
    double reflection(const Vec3& wo, const Vec3& wi) const noexcept;
    /// The transmission shape 1/π (sr⁻¹) of a diffusing thin sheet.
    static constexpr double transmission() noexcept { return 1.0 / kPi; }
    /// Whether the transmission is straight through (a delta: wi = −wo, weight 1/P_t; no
    /// value for next-event estimates, which pass the sheet along shadow rays instead).
    bool straight() const noexcept { return m_straight; }
    /// The probability with which sample() transmits.
    double transmission_probability() const noexcept { return m_transmission_probability; }
    /// The density of sample()'s non-delta draws at wi, per steradian (both sides).
    double pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept;
    /// Draws wi: `u_side` < transmission_probability() transmits (cosine-weighted on the far
    /// side, weight 1/P_t); otherwise the reflection lobe draws with (u_lobe, u1, u2) and the
    /// weight is divided by 1 − P_t (not when P_t = 0, so an opaque shape's numbers are the
    /// lobe's own). Nothing when the lobe draws nothing (wo below, or a direction lost).
    std::optional<BsdfSample> sample(const Vec3& wo, double u_side, double u_lobe, double u1,
                                     double u2) const noexcept;
    /// Whether the lobe is narrower than the cosine somewhere (GGX or Ward with a specular
    /// share): the path tracer then weights the sun by multiple importance sampling, since a
    /// drawn direction may find the sun's disc as well as a shadow ray does.
    bool glossy() const noexcept { return m_glossy; }
    /// Whether the lobe has a mirror part (drawn directions that eval cannot give).
    bool has_mirror() const noexcept { return m_mirror; }
    /// Whether the lobe depends on the azimuth of the local +x axis (anisotropic Ward).
    bool anisotropic() const noexcept { return m_anisotropic; }
    /// Whether the directional albedo ∫ R cos θi dωi is 1 for every wo (Lambertian, or
    /// Lambertian mixed with a mirror): Kirchhoff's emissivity is then direction-free.
    bool unit_albedo() const noexcept { return m_unit_albedo; }

private:
    Reflection m_reflection;
    double m_transmission_probability = 0.0;
    bool m_straight = false;
    bool m_glossy = false;
    bool m_mirror = false;
    bool m_anisotropic = false;
    bool m_unit_albedo = true;
};

/// The shading frame at a vertex with facing normal `normal`: any tangent for an isotropic
/// lobe (Frame::from_normal); for an anisotropic one, local +x is scene east (+x) projected
/// onto the surface (north, +y, where the normal is within 0.26° of the x axis), so the
/// lobe's x axis is the same on every facet.
Frame shading_frame(const Bsdf& bsdf, const Vec3& normal) noexcept;

/// Number of nodes of a DirectionalAlbedo table.
inline constexpr std::size_t kAlbedoNodes = 33;

/// The directional albedo A(cos θo) = ∫ R(wo, wi) cos θi dωi of a reflection lobe, tabulated
/// at kAlbedoNodes evenly spaced cos θo in [0, 1] (linear between them). Each node is a
/// 64 × 64 stratified estimate with the lobe's own sampler (exact for the Lambertian and
/// mirror parts; within 2 × 10⁻³ for the GGX and Ward lobes), or for Ross–Li the midpoint
/// rule over 256 cos θi × 64 φi (tests/unit/radiometry/bsdf_test.cpp). For an anisotropic
/// lobe the albedo is averaged over the azimuth of wo.
class DirectionalAlbedo {
public:
    explicit DirectionalAlbedo(const Bsdf::Reflection& lobe);
    /// A at cos θo (clamped to [0, 1]).
    double at(double cos_o) const noexcept;
    /// The largest tabulated value.
    double max() const noexcept;

private:
    std::array<double, kAlbedoNodes> m_nodes{};
};

}  // namespace glint::radiometry
