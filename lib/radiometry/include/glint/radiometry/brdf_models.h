// SPDX-License-Identifier: Apache-2.0
// The directional reflectance models beyond the Lambertian and GGX lobes (brdf.h), in the
// same local shading frame and conventions: Ward's (1992) anisotropic Gaussian lobe, mixed
// with a Lambertian part as DIRSIG's Ward BRDF is, and the Ross–Li kernel-driven model
// (Ross-Thick volume kernel and Li-Sparse-Reciprocal geometric kernel, the model of the MODIS
// BRDF/albedo product). Formulas, units and tests: docs/materials.md.
//
// `wo` points towards the viewer, `wi` towards the light, both away from the surface; BRDF
// values are per steradian; pdfs are per steradian of wi; only reflection (wo.z > 0 and
// wi.z > 0) is modelled here.
#pragma once

#include <optional>

#include "glint/radiometry/brdf.h"

namespace glint::radiometry {

/// Ward's anisotropic specular lobe with unit weight (G. J. Ward, "Measuring and modeling
/// anisotropic reflection", SIGGRAPH 1992, eq. 5a):
///   f(wo, wi) = exp(−tan²θh (cos²φh/αx² + sin²φh/αy²)) / (4π αx αy √(cos θo cos θi)),
/// with h the half vector and φh its azimuth from the local +x axis. Symmetric in (wo, wi).
/// Sampling draws h from the normalised slope distribution
///   p_h(h) = exp(−tan²θh (cos²φh/αx² + sin²φh/αy²)) / (π αx αy cos³θh)  (∫ p_h dω_h = 1)
/// and reflects wo about it (B. Walter, "Notes on the Ward BRDF", Cornell PCG-05-06, 2005):
/// pdf(wi) = p_h(h) / (4 wo·h).
class WardLobe {
public:
    /// Throws glint::Error (input) unless both widths lie in (0, 1].
    WardLobe(double alpha_x, double alpha_y);

    double alpha_x() const noexcept { return m_alpha_x; }
    double alpha_y() const noexcept { return m_alpha_y; }
    /// Whether αx ≠ αy (the lobe then depends on the tangent's azimuth).
    bool anisotropic() const noexcept { return m_alpha_x != m_alpha_y; }
    /// The slope distribution p_h(h) per steradian of h; 0 for h.z ≤ 0.
    double half_vector_pdf_per_sr(const Vec3& h) const noexcept;
    /// f(wo, wi) in sr⁻¹.
    double eval(const Vec3& wo, const Vec3& wi) const noexcept;
    /// The density of sample()'s wi per steradian.
    double pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept;
    /// A half vector drawn from p_h.
    Vec3 sample_half_vector(double u1, double u2) const noexcept;
    /// Samples wi by reflecting wo about a drawn half vector; nothing when wo or the
    /// reflected direction is below the surface.
    std::optional<BrdfSample> sample(const Vec3& wo, double u1, double u2) const noexcept;

private:
    double m_alpha_x;
    double m_alpha_y;
};

/// DIRSIG's Ward BRDF: f = ρd/π + ρs f_Ward(αx, αy). As a lobe shape it is held with the
/// shares d = ρd/(ρd + ρs) and s = ρs/(ρd + ρs) (the reflectance ρd + ρs scales it, as ρ(λ)
/// scales every shape). Sampling picks the Ward lobe with probability s and weights by the
/// whole f cos θi / pdf (one-sample MIS, balance heuristic), as SurfaceBrdf does.
class WardBrdf {
public:
    /// Throws glint::Error (input) unless the shares lie in [0, 1] and sum to 1 (to 10⁻⁹).
    WardBrdf(double diffuse_share, double specular_share, double alpha_x, double alpha_y);

    const WardLobe& lobe() const noexcept { return m_lobe; }
    double specular_share() const noexcept { return m_specular_share; }
    double eval(const Vec3& wo, const Vec3& wi) const noexcept;
    double pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept;
    std::optional<BrdfSample> sample(const Vec3& wo, double u_lobe, double u1,
                                     double u2) const noexcept;

private:
    WardLobe m_lobe;
    double m_diffuse_share;
    double m_specular_share;
};

/// The Ross-Thick volumetric kernel (Roujean et al. 1992 as given by W. Lucht, C. B. Schaaf
/// and A. H. Strahler, "An algorithm for the retrieval of albedo from space using
/// semiempirical BRDF models", IEEE TGRS 38(2), 977–998, 2000, eq. 38):
///   K_vol = ((π/2 − ξ) cos ξ + sin ξ) / (cos θi + cos θv) − π/4,
/// ξ the phase angle between the two directions (both pointing away from the surface).
double ross_thick_kernel(const Vec3& wo, const Vec3& wi) noexcept;

/// The Li-Sparse-Reciprocal geometric kernel (Lucht et al. 2000, eqs. 39–44) with crown
/// shape h/b and b/r:
///   K_geo = O − sec θi' − sec θv' + ½ (1 + cos ξ') sec θi' sec θv',
///   O = (1/π)(t − sin t cos t)(sec θi' + sec θv'),
///   cos t = (h/b) √(D² + (tan θi' tan θv' sin φ)²) / (sec θi' + sec θv'), clamped to [−1, 1],
///   D² = tan²θi' + tan²θv' − 2 tan θi' tan θv' cos φ,  θ' = atan((b/r) tan θ),
/// φ the relative azimuth (0 when both directions lie on the same side of the normal).
double li_sparse_reciprocal_kernel(const Vec3& wo, const Vec3& wi, double height_over_breadth,
                                   double breadth_over_radius) noexcept;

/// The MODIS crown shape: h/b = 2, b/r = 1 (Lucht et al. 2000).
inline constexpr double kRossLiHeightOverBreadth = 2.0;
inline constexpr double kRossLiBreadthOverRadius = 1.0;

/// The largest zenith angle at which RossLiBrdf evaluates the kernels: 80°. The kernel-driven
/// model is fitted to (and MODIS retrieves it from) sun and view zeniths up to about 70–80°;
/// beyond, the Li kernel grows like sec θi sec θv near the hot spot without bound (its albedo
/// at 89.9° exceeds 50 for common weights). Directions lower than 80° are evaluated as at 80°,
/// same azimuth, for both directions alike (so reciprocity holds).
inline constexpr double kRossLiMaxZenithDeg = 80.0;

/// The Ross–Li BRDF as a shape relative to the isotropic weight:
///   f = max(0, 1 + k_vol K_vol + k_geo K_geo) / π,  k_vol = f_vol/f_iso, k_geo = f_geo/f_iso,
/// so that ρ(λ) = f_iso(λ) scales it; zeniths beyond kRossLiMaxZenithDeg are evaluated at it.
/// Sampled with the cosine-weighted hemisphere (weight f cos θi / pdf = π f). Reciprocal
/// (both kernels are).
class RossLiBrdf {
public:
    /// Throws glint::Error (input) for a non-finite weight.
    RossLiBrdf(double volumetric, double geometric);

    double volumetric() const noexcept { return m_volumetric; }
    double geometric() const noexcept { return m_geometric; }
    double eval(const Vec3& wo, const Vec3& wi) const noexcept;
    double pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept;
    std::optional<BrdfSample> sample(const Vec3& wo, double u1, double u2) const noexcept;

private:
    double m_volumetric;
    double m_geometric;
};

}  // namespace glint::radiometry
