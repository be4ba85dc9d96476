// SPDX-License-Identifier: Apache-2.0
// The Lambertian and GGX lobes and the mixed material BRDF: evaluation, pdfs and importance
// sampling. Checked by tests/unit/radiometry/brdf_test.cpp (chi-square fits of the samplers,
// reciprocity, white-furnace albedo bounds, sample weights).
#include "glint/radiometry/brdf.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "glint/core/error.h"

namespace glint::radiometry {

namespace {

bool in_unit_interval(double v) noexcept { return v >= 0.0 && v <= 1.0; }  // false for NaN

void require_unit_interval(double v, const char* name) {
    if (!in_unit_interval(v)) {
        throw input_error(std::string(name) + " must lie in [0, 1], got " + std::to_string(v));
    }
}

}  // namespace

// ---- Lambertian ------------------------------------------------------------------------

LambertianBrdf::LambertianBrdf(double reflectance) : m_reflectance(reflectance) {
    require_unit_interval(reflectance, "reflectance");
}

double LambertianBrdf::eval(const Vec3& wo, const Vec3& wi) const noexcept {
    return (wo.z > 0.0 && wi.z > 0.0) ? m_reflectance / kPi : 0.0;
}

double LambertianBrdf::pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept {
    return wo.z > 0.0 ? cosine_hemisphere_pdf_per_sr(wi.z) : 0.0;
}

std::optional<BrdfSample> LambertianBrdf::sample(const Vec3& wo, double u1,
                                                 double u2) const noexcept {
    if (wo.z <= 0.0) return std::nullopt;
    const Vec3 wi = sample_cosine_hemisphere(u1, u2);
    const double pdf = cosine_hemisphere_pdf_per_sr(wi.z);
    if (pdf <= 0.0) return std::nullopt;
    return BrdfSample{wi, m_reflectance, pdf};
}

// ---- GGX -------------------------------------------------------------------------------

GgxBrdf::GgxBrdf(double alpha) : m_alpha(alpha) {
    if (!(alpha >= kMinGgxAlpha && alpha <= 1.0)) {
        throw input_error("GGX alpha must lie in [0.001, 1], got " + std::to_string(alpha));
    }
}

double GgxBrdf::distribution(const Vec3& h) const noexcept {
    if (h.z <= 0.0) return 0.0;
    const double a2 = m_alpha * m_alpha;
    const double c2 = h.z * h.z;
    const double d = c2 * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}

double GgxBrdf::lambda(const Vec3& w) const noexcept {
    const double c2 = w.z * w.z;
    const double s2 = std::max(0.0, w.x * w.x + w.y * w.y);  // sin²θ for unit w
    if (c2 <= 0.0) return 0.0;
    const double a2_tan2 = m_alpha * m_alpha * s2 / c2;
    // (√(1 + x) − 1)/2 = x / (2 (√(1 + x) + 1)), stable for small x.
    return a2_tan2 / (2.0 * (std::sqrt(1.0 + a2_tan2) + 1.0));
}

double GgxBrdf::masking(const Vec3& w) const noexcept {
    return w.z > 0.0 ? 1.0 / (1.0 + lambda(w)) : 0.0;
}

double GgxBrdf::masking_shadowing(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    return 1.0 / (1.0 + lambda(wo) + lambda(wi));
}

double GgxBrdf::eval(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    const Vec3 h = normalized(wo + wi);
    return distribution(h) * masking_shadowing(wo, wi) / (4.0 * wo.z * wi.z);
}

double GgxBrdf::pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    const Vec3 h = normalized(wo + wi);
    // pdf_h = G₁(wo) (wo·h) D(h) / cos θo; dωh/dωi = 1 / (4 wo·h).
    return masking(wo) * distribution(h) / (4.0 * wo.z);
}

Vec3 GgxBrdf::sample_visible_normal(const Vec3& wo, double u1, double u2) const noexcept {
    // Heitz (2018), listing 1, isotropic α. Stretch wo to the hemisphere configuration.
    const Vec3 vh = normalized(Vec3{m_alpha * wo.x, m_alpha * wo.y, wo.z});
    const double len2 = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = len2 > 0.0 ? Vec3{-vh.y, vh.x, 0.0} / std::sqrt(len2) : Vec3{1.0, 0.0, 0.0};
    const Vec3 t2 = cross(vh, t1);
    // A uniform disk point, its second coordinate warped onto the projected hemisphere.
    const double r = std::sqrt(u1);
    const double phi = 2.0 * kPi * u2;
    const double p1 = r * std::cos(phi);
    const double s = 0.5 * (1.0 + vh.z);
    const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    // Unstretch back to the ellipsoid configuration.
    return normalized(Vec3{m_alpha * nh.x, m_alpha * nh.y, std::max(0.0, nh.z)});
}

std::optional<BrdfSample> GgxBrdf::sample(const Vec3& wo, double u1, double u2) const noexcept {
    if (wo.z <= 0.0) return std::nullopt;
    const Vec3 h = sample_visible_normal(wo, u1, u2);
    const Vec3 wi = reflect_about(wo, h);
    if (wi.z <= 0.0) return std::nullopt;
    const double pdf = pdf_per_sr(wo, wi);
    if (!(pdf > 0.0)) return std::nullopt;
    return BrdfSample{wi, masking_shadowing(wo, wi) / masking(wo), pdf};
}

// ---- Mixed material --------------------------------------------------------------------

namespace {

GgxBrdf make_ggx(double roughness) {
    require_unit_interval(roughness, "roughness");
    return GgxBrdf(std::max(roughness * roughness, kMinGgxAlpha));
}

double checked_fraction(double specular_fraction) {
    require_unit_interval(specular_fraction, "specular fraction");
    return specular_fraction;
}

}  // namespace

SurfaceBrdf::SurfaceBrdf(double reflectance, double specular_fraction, double roughness)
    : m_diffuse(reflectance),
      m_specular(make_ggx(roughness)),
      m_specular_fraction(checked_fraction(specular_fraction)),
      m_specular_probability(specular_fraction),
      m_mirror(roughness == 0.0 && specular_fraction > 0.0) {}

double SurfaceBrdf::eval(const Vec3& wo, const Vec3& wi) const noexcept {
    // A Lambertian surface: the GGX lobe weighs nothing (same value: 1·d + 0 = d).
    if (m_specular_fraction == 0.0) return m_diffuse.eval(wo, wi);
    if (m_mirror) return (1.0 - m_specular_fraction) * m_diffuse.eval(wo, wi);
    return (1.0 - m_specular_fraction) * m_diffuse.eval(wo, wi) +
           m_specular_fraction * m_diffuse.reflectance() * m_specular.eval(wo, wi);
}

double SurfaceBrdf::pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    const double ps = m_specular_probability;
    double pdf = 0.0;
    if (ps < 1.0) pdf += (1.0 - ps) * m_diffuse.pdf_per_sr(wo, wi);
    if (ps > 0.0 && !m_mirror) pdf += ps * m_specular.pdf_per_sr(wo, wi);
    return pdf;
}

std::optional<BrdfSample> SurfaceBrdf::sample(const Vec3& wo, double u_lobe, double u1,
                                              double u2) const noexcept {
    if (wo.z <= 0.0) return std::nullopt;
    const double ps = m_specular_probability;
    if (m_diffuse.reflectance() <= 0.0) return std::nullopt;  // black
    Vec3 wi;
    if (u_lobe < ps && m_mirror) {
        // The mirror: weight ρ s / P_s = ρ.
        return BrdfSample{Vec3{-wo.x, -wo.y, wo.z}, m_diffuse.reflectance(), 0.0, true};
    }
    if (u_lobe < ps) {
        const auto s = m_specular.sample(wo, u1, u2);
        if (!s) return std::nullopt;
        wi = s->wi;
    } else {
        wi = sample_cosine_hemisphere(u1, u2);
    }
    const double pdf = pdf_per_sr(wo, wi);
    if (!(pdf > 0.0)) return std::nullopt;
    return BrdfSample{wi, eval(wo, wi) * wi.z / pdf, pdf};
}

}  // namespace glint::radiometry
