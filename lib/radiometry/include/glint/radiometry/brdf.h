// SPDX-License-Identifier: Apache-2.0
// Surface reflectance models in the local shading frame (normal = +z): a Lambertian lobe, a
// GGX (Trowbridge–Reitz) microfacet specular lobe with Smith height-correlated masking-
// shadowing and visible-normal importance sampling (Heitz 2018), and SurfaceBrdf, the
// material model the path tracer uses: a mix of the two set by a reflectance, a specular
// fraction and a roughness. Formulas, units and tests: docs/physics.md, "Radiometry:
// sampling and BRDFs".
//
// Conventions: `wo` is the unit direction towards the viewer (previous path vertex), `wi`
// the unit direction towards the light (next vertex); both point away from the surface.
// Only reflection is modelled: f = 0 unless wo.z > 0 and wi.z > 0. BRDF values are per
// steradian (sr⁻¹); pdfs are per steradian of wi.
//
// Material parameters (SurfaceBrdf):
// | name              | type   | unit | range   | meaning                                   |
// |-------------------|--------|------|---------|-------------------------------------------|
// | reflectance       | double | 1    | [0, 1]  | reflectance ρ scaling both lobes           |
// | specular_fraction | double | 1    | [0, 1]  | s: share of ρ in the GGX lobe, 1 − s diffuse|
// | roughness         | double | 1    | [0, 1]  | r: GGX α = max(r², 10⁻³)                   |
#pragma once

#include <optional>

#include "glint/radiometry/sampling.h"

namespace glint::radiometry {

/// Smallest GGX α used: a roughness of 0 gives this near-mirror lobe (a true delta lobe is
/// not modelled).
inline constexpr double kMinGgxAlpha = 1e-3;

/// wo reflected about the unit vector h: 2 (wo·h) h − wo.
inline Vec3 reflect_about(const Vec3& wo, const Vec3& h) noexcept {
    return 2.0 * dot(wo, h) * h - wo;
}

/// A sampled incident direction with its Monte Carlo weight.
struct BrdfSample {
    Vec3 wi;                  ///< sampled unit direction towards the light (local frame)
    double weight = 0.0;      ///< f(wo, wi) · cos θi / pdf: the factor applied to L(wi)
    double pdf_per_sr = 0.0;  ///< density of wi per steradian (of the whole sampler)
    /// wi was drawn from a delta lobe (a mirror): `pdf_per_sr` is 0, eval() cannot give it,
    /// and `weight` is the lobe's share of the reflectance over its probability.
    bool delta = false;
};

/// The Lambertian BRDF f = ρ / π, sampled with the cosine-weighted hemisphere (weight = ρ).
class LambertianBrdf {
public:
    /// A Lambertian lobe of reflectance `reflectance` in [0, 1]; throws glint::Error (input)
    /// otherwise.
    explicit LambertianBrdf(double reflectance);

    /// The reflectance ρ.
    double reflectance() const noexcept { return m_reflectance; }
    /// f(wo, wi) in sr⁻¹: ρ / π when both directions are above the surface, else 0.
    double eval(const Vec3& wo, const Vec3& wi) const noexcept;
    /// The sampling density of wi: cos θi / π for wi above the surface, else 0.
    double pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept;
    /// Samples wi ∝ cos θi from two uniforms in [0, 1); nothing when wo is below the surface.
    std::optional<BrdfSample> sample(const Vec3& wo, double u1, double u2) const noexcept;

private:
    double m_reflectance;
};

/// The GGX microfacet specular lobe with white (unit) Fresnel:
///   f(wo, wi) = D(h) G₂(wo, wi) / (4 cos θo cos θi),  h = (wo + wi)/|wo + wi|,
///   D(h) = α² / (π (cos²θh (α² − 1) + 1)²),
///   Λ(w) = (√(1 + α² tan²θ) − 1) / 2,  G₁(w) = 1/(1 + Λ(w)),
///   G₂(wo, wi) = 1/(1 + Λ(wo) + Λ(wi))  (Smith, height-correlated).
/// f is symmetric in (wo, wi); its directional albedo ∫ f cos θi dωi is ≤ 1 (single
/// scattering loses the energy of rays that hit a second microfacet).
/// Sampling draws a visible normal (Heitz, "Sampling the GGX distribution of visible
/// normals", JCGT 7(4), 2018) and reflects wo about it, giving
///   pdf(wi) = G₁(wo) D(h) / (4 cos θo),   weight = G₂(wo, wi) / G₁(wo);
/// a reflected direction below the surface is returned as no sample.
class GgxBrdf {
public:
    /// A GGX lobe of width `alpha` in [kMinGgxAlpha, 1]; throws glint::Error (input)
    /// otherwise.
    explicit GgxBrdf(double alpha);

    /// The width parameter α.
    double alpha() const noexcept { return m_alpha; }
    /// The normal distribution D(h) per steradian of h (local unit vector); 0 for h.z ≤ 0.
    double distribution(const Vec3& h) const noexcept;
    /// Smith's Λ(w) for the local unit direction w (w.z > 0).
    double lambda(const Vec3& w) const noexcept;
    /// Smith's masking G₁(w) = 1/(1 + Λ(w)); 0 for w.z ≤ 0.
    double masking(const Vec3& w) const noexcept;
    /// Height-correlated masking-shadowing G₂(wo, wi); 0 unless both are above the surface.
    double masking_shadowing(const Vec3& wo, const Vec3& wi) const noexcept;
    /// f(wo, wi) in sr⁻¹ (formula above).
    double eval(const Vec3& wo, const Vec3& wi) const noexcept;
    /// The density of sample()'s wi per steradian; 0 for wi or wo below the surface.
    double pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept;
    /// A microfacet normal drawn from the distribution of normals visible from `wo`
    /// (wo.z > 0), density G₁(wo) max(0, wo·h) D(h) / cos θo.
    Vec3 sample_visible_normal(const Vec3& wo, double u1, double u2) const noexcept;
    /// Samples wi by reflecting wo about a visible normal; nothing when wo or the reflected
    /// direction is below the surface.
    std::optional<BrdfSample> sample(const Vec3& wo, double u1, double u2) const noexcept;

private:
    double m_alpha;
};

/// The material BRDF: f = ρ [(1 − s) / π + s f_GGX(α)], with ρ the reflectance, s the
/// specular fraction (the share of the reflectance that goes into the lobe) and α =
/// max(roughness², kMinGgxAlpha); a roughness of exactly 0 makes the lobe a mirror,
/// f = ρ [(1 − s)/π + s δ(wi − R(wo)) / cos θi] with R(wo) = (−wo.x, −wo.y, wo.z): eval() and
/// pdf_per_sr() then hold the diffuse part only, and sample() gives the mirror direction
/// (delta = true, weight ρ) with probability s. Its directional albedo is ρ [(1 − s) + s E_GGX(wo)]
/// ≤ ρ. Because ρ scales the whole BRDF, a spectral reflectance ρ(λ) keeps the lobe shape and
/// sampling independent of wavelength (the path tracer samples once for all bands).
/// Sampling picks the GGX lobe with probability P_s = s and the cosine lobe otherwise, and
/// weights the sample by the full f cos θi / pdf with pdf = (1 − s) cos θi/π + s pdf_GGX
/// (one-sample MIS with the balance heuristic), so a direction either lobe could give is
/// weighted consistently.
class SurfaceBrdf {
public:
    /// Throws glint::Error (input) unless all three parameters lie in [0, 1].
    SurfaceBrdf(double reflectance, double specular_fraction, double roughness);

    /// The diffuse lobe.
    const LambertianBrdf& diffuse() const noexcept { return m_diffuse; }
    /// The specular lobe.
    const GgxBrdf& specular() const noexcept { return m_specular; }
    /// The specular fraction s.
    double specular_fraction() const noexcept { return m_specular_fraction; }
    /// The probability P_s with which sample() picks the specular lobe.
    double specular_probability() const noexcept { return m_specular_probability; }
    /// Whether the specular lobe is a mirror (roughness 0 and s > 0).
    bool mirror() const noexcept { return m_mirror; }

    /// f(wo, wi) in sr⁻¹.
    double eval(const Vec3& wo, const Vec3& wi) const noexcept;
    /// The density of sample()'s wi per steradian.
    double pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept;
    /// Samples wi: `u_lobe` picks the lobe, (u1, u2) the direction; all in [0, 1). Nothing
    /// for a black material, for wo below the surface, or for a specular sample reflected
    /// below the surface.
    std::optional<BrdfSample> sample(const Vec3& wo, double u_lobe, double u1,
                                     double u2) const noexcept;

private:
    LambertianBrdf m_diffuse;
    GgxBrdf m_specular;
    double m_specular_fraction;
    double m_specular_probability;
    bool m_mirror;
};

}  // namespace glint::radiometry
