// SPDX-License-Identifier: Apache-2.0
// Ward's lobe, DIRSIG's Ward BRDF and the Ross–Li kernels (glint/radiometry/brdf_models.h).
// Checked by tests/unit/radiometry/brdf_models_test.cpp.
#include "glint/radiometry/brdf_models.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::radiometry {
namespace {

/// cos φ between the horizontal projections of two local directions (1 when either is
/// vertical).
double cos_relative_azimuth(const Vec3& a, const Vec3& b) noexcept {
    const double la = std::hypot(a.x, a.y);
    const double lb = std::hypot(b.x, b.y);
    if (la <= 0.0 || lb <= 0.0) return 1.0;
    return std::clamp((a.x * b.x + a.y * b.y) / (la * lb), -1.0, 1.0);
}

}  // namespace

// ---- Ward ------------------------------------------------------------------------------

WardLobe::WardLobe(double alpha_x, double alpha_y) : m_alpha_x(alpha_x), m_alpha_y(alpha_y) {
    for (const double a : {alpha_x, alpha_y}) {
        if (!(a > 0.0 && a <= 1.0)) {
            throw input_error("Ward roughness (sigma) must lie in (0, 1], got " +
                              format_shortest(a));
        }
    }
}

double WardLobe::half_vector_pdf_per_sr(const Vec3& h) const noexcept {
    if (h.z <= 0.0) return 0.0;
    const double c2 = h.z * h.z;
    const double e = (h.x * h.x / (m_alpha_x * m_alpha_x) + h.y * h.y / (m_alpha_y * m_alpha_y)) /
                     c2;  // tan²θh (cos²φ/αx² + sin²φ/αy²)
    return std::exp(-e) / (kPi * m_alpha_x * m_alpha_y * c2 * h.z);
}

double WardLobe::eval(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    const Vec3 h = normalized(wo + wi);
    const double e =
        (h.x * h.x / (m_alpha_x * m_alpha_x) + h.y * h.y / (m_alpha_y * m_alpha_y)) / (h.z * h.z);
    return std::exp(-e) / (4.0 * kPi * m_alpha_x * m_alpha_y * std::sqrt(wo.z * wi.z));
}

double WardLobe::pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    const Vec3 h = normalized(wo + wi);
    const double wo_h = dot(wo, h);
    if (!(wo_h > 0.0)) return 0.0;
    return half_vector_pdf_per_sr(h) / (4.0 * wo_h);
}

Vec3 WardLobe::sample_half_vector(double u1, double u2) const noexcept {
    // φ from tan φ = (αy/αx) tan 2πu2, kept in u2's quadrant; tan²θ = −ln u / (cos²φ/αx² +
    // sin²φ/αy²) with u = 1 − u1 in (0, 1].
    const CosSin turn = cos_sin_turn(u2);
    const double phi = std::atan2(m_alpha_y * turn.sin, m_alpha_x * turn.cos);
    const double c = std::cos(phi);
    const double s = std::sin(phi);
    const double a = c * c / (m_alpha_x * m_alpha_x) + s * s / (m_alpha_y * m_alpha_y);
    const double tan2 = -std::log(1.0 - u1) / a;
    const double cos_theta = 1.0 / std::sqrt(1.0 + tan2);
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return {sin_theta * c, sin_theta * s, cos_theta};
}

std::optional<BrdfSample> WardLobe::sample(const Vec3& wo, double u1, double u2) const noexcept {
    if (wo.z <= 0.0) return std::nullopt;
    const Vec3 h = sample_half_vector(u1, u2);
    if (dot(wo, h) <= 0.0) return std::nullopt;
    const Vec3 wi = reflect_about(wo, h);
    if (wi.z <= 0.0) return std::nullopt;
    const double pdf = pdf_per_sr(wo, wi);
    if (!(pdf > 0.0)) return std::nullopt;
    return BrdfSample{wi, eval(wo, wi) * wi.z / pdf, pdf};
}

WardBrdf::WardBrdf(double diffuse_share, double specular_share, double alpha_x, double alpha_y)
    : m_lobe(alpha_x, alpha_y), m_diffuse_share(diffuse_share), m_specular_share(specular_share) {
    if (!(diffuse_share >= 0.0 && specular_share >= 0.0 &&
          std::abs(diffuse_share + specular_share - 1.0) <= 1e-9)) {
        throw input_error("Ward shares " + format_shortest(diffuse_share) + " and " +
                          format_shortest(specular_share) + " must be >= 0 and sum to 1");
    }
}

double WardBrdf::eval(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    return m_diffuse_share / kPi + m_specular_share * m_lobe.eval(wo, wi);
}

double WardBrdf::pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    double pdf = 0.0;
    if (m_specular_share < 1.0)
        pdf += (1.0 - m_specular_share) * cosine_hemisphere_pdf_per_sr(wi.z);
    if (m_specular_share > 0.0) pdf += m_specular_share * m_lobe.pdf_per_sr(wo, wi);
    return pdf;
}

std::optional<BrdfSample> WardBrdf::sample(const Vec3& wo, double u_lobe, double u1,
                                           double u2) const noexcept {
    if (wo.z <= 0.0) return std::nullopt;
    Vec3 wi;
    if (u_lobe < m_specular_share) {
        const Vec3 h = m_lobe.sample_half_vector(u1, u2);
        if (dot(wo, h) <= 0.0) return std::nullopt;
        wi = reflect_about(wo, h);
        if (wi.z <= 0.0) return std::nullopt;
    } else {
        wi = sample_cosine_hemisphere(u1, u2);
    }
    const double pdf = pdf_per_sr(wo, wi);
    if (!(pdf > 0.0)) return std::nullopt;
    return BrdfSample{wi, eval(wo, wi) * wi.z / pdf, pdf};
}

// ---- Ross–Li ---------------------------------------------------------------------------

double ross_thick_kernel(const Vec3& wo, const Vec3& wi) noexcept {
    const double cos_xi = std::clamp(dot(wo, wi), -1.0, 1.0);
    const double xi = std::acos(cos_xi);
    const double sin_xi = std::sqrt(std::max(0.0, 1.0 - cos_xi * cos_xi));
    return ((kPi / 2.0 - xi) * cos_xi + sin_xi) / (wo.z + wi.z) - kPi / 4.0;
}

double li_sparse_reciprocal_kernel(const Vec3& wo, const Vec3& wi, double height_over_breadth,
                                   double breadth_over_radius) noexcept {
    // tan θ' = (b/r) tan θ for each direction.
    const auto primed_tan = [&](const Vec3& w) {
        return breadth_over_radius * std::hypot(w.x, w.y) / w.z;
    };
    const double ti = primed_tan(wi);
    const double tv = primed_tan(wo);
    const double cos_phi = cos_relative_azimuth(wo, wi);
    const double sin_phi = std::sqrt(std::max(0.0, 1.0 - cos_phi * cos_phi));
    const double sec_i = std::sqrt(1.0 + ti * ti);
    const double sec_v = std::sqrt(1.0 + tv * tv);
    const double d2 = std::max(0.0, ti * ti + tv * tv - 2.0 * ti * tv * cos_phi);
    const double cos_t =
        std::clamp(height_over_breadth * std::sqrt(d2 + (ti * tv * sin_phi) * (ti * tv * sin_phi)) /
                       (sec_i + sec_v),
                   -1.0, 1.0);
    const double t = std::acos(cos_t);
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
    const double overlap = (t - sin_t * cos_t) * (sec_i + sec_v) / kPi;
    // cos ξ' = cos θi' cos θv' + sin θi' sin θv' cos φ = (1 + tan θi' tan θv' cos φ) / (sec sec).
    const double cos_xi = (1.0 + ti * tv * cos_phi) / (sec_i * sec_v);
    return overlap - sec_i - sec_v + 0.5 * (1.0 + cos_xi) * sec_i * sec_v;
}

RossLiBrdf::RossLiBrdf(double volumetric, double geometric)
    : m_volumetric(volumetric), m_geometric(geometric) {
    if (!std::isfinite(volumetric) || !std::isfinite(geometric)) {
        throw input_error("Ross-Li kernel weights must be finite numbers");
    }
}

namespace {

/// `w` with its zenith angle limited to kRossLiMaxZenithDeg (same azimuth).
Vec3 within_ross_li_zenith(const Vec3& w) noexcept {
    static const double cos_max = std::cos(kRossLiMaxZenithDeg * kPi / 180.0);
    if (w.z >= cos_max) return w;
    const double horizontal = std::hypot(w.x, w.y);
    const double sin_max = std::sqrt(1.0 - cos_max * cos_max);
    if (horizontal <= 0.0) return w;
    return {w.x / horizontal * sin_max, w.y / horizontal * sin_max, cos_max};
}

}  // namespace

double RossLiBrdf::eval(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    const Vec3 o = within_ross_li_zenith(wo);
    const Vec3 i = within_ross_li_zenith(wi);
    const double r = 1.0 + m_volumetric * ross_thick_kernel(o, i) +
                     m_geometric * li_sparse_reciprocal_kernel(o, i, kRossLiHeightOverBreadth,
                                                               kRossLiBreadthOverRadius);
    return std::max(0.0, r) / kPi;
}

double RossLiBrdf::pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept {
    return wo.z > 0.0 ? cosine_hemisphere_pdf_per_sr(wi.z) : 0.0;
}

std::optional<BrdfSample> RossLiBrdf::sample(const Vec3& wo, double u1, double u2) const noexcept {
    if (wo.z <= 0.0) return std::nullopt;
    const Vec3 wi = sample_cosine_hemisphere(u1, u2);
    const double pdf = cosine_hemisphere_pdf_per_sr(wi.z);
    if (!(pdf > 0.0)) return std::nullopt;
    return BrdfSample{wi, eval(wo, wi) * wi.z / pdf, pdf};
}

}  // namespace glint::radiometry
