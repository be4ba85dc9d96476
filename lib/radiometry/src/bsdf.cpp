// SPDX-License-Identifier: Apache-2.0
// The material scattering shape and its directional albedo (glint/radiometry/bsdf.h).
#include "glint/radiometry/bsdf.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::radiometry {
namespace {

/// The lobe's own draw (u_lobe is unused by the single-lobe models).
std::optional<BrdfSample> draw(const Bsdf::Reflection& lobe, const Vec3& wo, double u_lobe,
                               double u1, double u2) noexcept {
    return std::visit(
        [&](const auto& model) -> std::optional<BrdfSample> {
            using Model = std::decay_t<decltype(model)>;
            if constexpr (std::is_same_v<Model, RossLiBrdf>) {
                return model.sample(wo, u1, u2);
            } else {
                return model.sample(wo, u_lobe, u1, u2);
            }
        },
        lobe);
}

}  // namespace

Bsdf::Bsdf(Reflection reflection, double transmission_probability, bool straight)
    : m_reflection(std::move(reflection)),
      m_transmission_probability(transmission_probability),
      m_straight(straight && transmission_probability > 0.0) {
    if (!(transmission_probability >= 0.0 && transmission_probability <= 1.0)) {
        throw input_error("transmission probability " + format_shortest(transmission_probability) +
                          " must lie in [0, 1]");
    }
    if (const auto* surface = std::get_if<SurfaceBrdf>(&m_reflection)) {
        m_mirror = surface->mirror();
        m_glossy = surface->specular_fraction() > 0.0 && !m_mirror;
        m_unit_albedo = !m_glossy;
    } else if (const auto* ward = std::get_if<WardBrdf>(&m_reflection)) {
        m_glossy = ward->specular_share() > 0.0;
        m_anisotropic = m_glossy && ward->lobe().anisotropic();
        m_unit_albedo = !m_glossy;
    } else {
        const auto& ross_li = std::get<RossLiBrdf>(m_reflection);
        m_unit_albedo = ross_li.volumetric() == 0.0 && ross_li.geometric() == 0.0;
    }
}

double Bsdf::reflection(const Vec3& wo, const Vec3& wi) const noexcept {
    return std::visit([&](const auto& model) { return model.eval(wo, wi); }, m_reflection);
}

double Bsdf::pdf_per_sr(const Vec3& wo, const Vec3& wi) const noexcept {
    if (wo.z <= 0.0) return 0.0;
    const double pt = m_transmission_probability;
    if (wi.z < 0.0) return m_straight ? 0.0 : pt * cosine_hemisphere_pdf_per_sr(-wi.z);
    const double pdf =
        std::visit([&](const auto& model) { return model.pdf_per_sr(wo, wi); }, m_reflection);
    return pt > 0.0 ? (1.0 - pt) * pdf : pdf;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3& wo, double u_side, double u_lobe, double u1,
                                       double u2) const noexcept {
    const double pt = m_transmission_probability;
    if (pt > 0.0 && u_side < pt) {
        if (m_straight) {
            return BsdfSample{-1.0 * wo, 1.0 / pt, 0.0, ScatterSide::transmitted, true};
        }
        const Vec3 local = sample_cosine_hemisphere(u1, u2);
        return BsdfSample{{local.x, local.y, -local.z},
                          1.0 / pt,
                          pt * cosine_hemisphere_pdf_per_sr(local.z),
                          ScatterSide::transmitted,
                          false};
    }
    const auto drawn = draw(m_reflection, wo, u_lobe, u1, u2);
    if (!drawn) return std::nullopt;
    BsdfSample s{drawn->wi, drawn->weight, drawn->pdf_per_sr, ScatterSide::reflected, drawn->delta};
    if (pt > 0.0) {
        s.weight = drawn->weight / (1.0 - pt);
        s.pdf_per_sr = drawn->pdf_per_sr * (1.0 - pt);
    }
    return s;
}

Frame shading_frame(const Bsdf& bsdf, const Vec3& normal) noexcept {
    if (!bsdf.anisotropic()) return Frame::from_normal(normal);
    const Vec3 hint = std::abs(normal.x) > 0.99999 ? Vec3{0.0, 1.0, 0.0} : Vec3{1.0, 0.0, 0.0};
    Frame frame;
    frame.n = normal;
    frame.s = normalized(hint - dot(hint, normal) * normal);
    frame.t = cross(normal, frame.s);
    return frame;
}

// ---- Directional albedo ----------------------------------------------------------------

namespace {

constexpr int kAlbedoStrata = 64;

/// ∫ R cos θi dωi at wo for Ross–Li by the midpoint rule in (cos θi, φi): 256 × 64 cells.
/// The kernels grow like sec θi towards the horizon, where a sampler's strata resolve them
/// poorly; R cos θi is bounded there, so the rule in cos θi converges (to 10⁻⁵ here).
double ross_li_albedo_at(const RossLiBrdf& lobe, const Vec3& wo) {
    constexpr int kCosines = 256;
    constexpr int kAzimuths = 64;
    double sum = 0.0;
    for (int i = 0; i < kCosines; ++i) {
        const double mu = (i + 0.5) / kCosines;
        const double sin_theta = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < kAzimuths; ++j) {
            const double phi = (j + 0.5) * 2.0 * kPi / kAzimuths;
            const Vec3 wi{sin_theta * std::cos(phi), sin_theta * std::sin(phi), mu};
            sum += lobe.eval(wo, wi) * mu;
        }
    }
    return sum * (1.0 / kCosines) * (2.0 * kPi / kAzimuths);
}

/// ∫ R cos θi dωi at wo by the lobe's sampler over a stratified grid of (u1, u2) (and of
/// u_lobe, in the same strata order, for the mixed lobes); Ross–Li by quadrature.
double albedo_at(const Bsdf::Reflection& lobe, const Vec3& wo) {
    if (const auto* ross_li = std::get_if<RossLiBrdf>(&lobe))
        return ross_li_albedo_at(*ross_li, wo);
    double sum = 0.0;
    for (int i = 0; i < kAlbedoStrata; ++i) {
        for (int j = 0; j < kAlbedoStrata; ++j) {
            const double u1 = (i + 0.5) / kAlbedoStrata;
            const double u2 = (j + 0.5) / kAlbedoStrata;
            // The lobe choice walks its own stratified sequence, decorrelated from (u1, u2).
            const double u_lobe = ((j * kAlbedoStrata + i) * 0.6180339887498949) -
                                  std::floor((j * kAlbedoStrata + i) * 0.6180339887498949);
            if (const auto s = draw(lobe, wo, u_lobe, u1, u2)) sum += s->weight;
        }
    }
    return sum / (kAlbedoStrata * kAlbedoStrata);
}

}  // namespace

DirectionalAlbedo::DirectionalAlbedo(const Bsdf::Reflection& lobe) {
    const bool anisotropic =
        std::holds_alternative<WardBrdf>(lobe) && std::get<WardBrdf>(lobe).lobe().anisotropic();
    for (std::size_t k = 0; k < kAlbedoNodes; ++k) {
        // Node 0 is grazing: evaluated just above the surface.
        const double c = std::max(static_cast<double>(k) / (kAlbedoNodes - 1), 1e-3);
        const double s = std::sqrt(1.0 - c * c);
        if (!anisotropic) {
            m_nodes[k] = albedo_at(lobe, Vec3{s, 0.0, c});
            continue;
        }
        constexpr int kAzimuths = 8;
        double sum = 0.0;
        for (int a = 0; a < kAzimuths; ++a) {
            const double phi = (a + 0.5) * 2.0 * kPi / kAzimuths;
            sum += albedo_at(lobe, Vec3{s * std::cos(phi), s * std::sin(phi), c});
        }
        m_nodes[k] = sum / kAzimuths;
    }
}

double DirectionalAlbedo::at(double cos_o) const noexcept {
    const double x = std::clamp(cos_o, 0.0, 1.0) * (kAlbedoNodes - 1);
    const auto k = std::min(static_cast<std::size_t>(x), kAlbedoNodes - 2);
    const double f = x - static_cast<double>(k);
    return (1.0 - f) * m_nodes[k] + f * m_nodes[k + 1];
}

double DirectionalAlbedo::max() const noexcept {
    return *std::max_element(m_nodes.begin(), m_nodes.end());
}

}  // namespace glint::radiometry
