// SPDX-License-Identifier: Apache-2.0
// MaterialTable: scene materials sampled on a spectral grid (glint/radiometry/materials.h).
#include "glint/radiometry/materials.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::radiometry {
namespace {

/// Tolerance on ε + ρ ≤ 1 and on the [0, 1] ranges (interpolation rounding).
constexpr double kRangeSlack = 1e-9;
/// Tolerance on ρ A(θo) ≤ 1: the tabulated albedo's estimation error (bsdf.h).
constexpr double kAlbedoSlack = 2e-3;

/// The table sampled at the grid's wavelengths, held constant beyond its ends; `covered` is
/// cleared when the grid reaches outside the table.
std::vector<double> sample_held(const model::SpectralTable& table, const SpectralGrid& grid,
                                bool& covered) {
    const std::vector<double>& x = table.wavelengths_um;
    std::vector<double> out(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double w = grid.wavelength_um(i);
        if (w < x.front() || w > x.back()) covered = false;
        out[i] = model::sample_held(table, w);
    }
    return out;
}

void check_unit_range(const std::vector<double>& values, const model::Material& material,
                      const char* what, const SpectralGrid& grid) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!(values[i] >= -kRangeSlack && values[i] <= 1.0 + kRangeSlack)) {
            throw input_error(
                "material '" + material.id + "': " + what + " " + format_shortest(values[i]) +
                    " at " + format_shortest(grid.wavelength_um(i)) + " um lies outside [0, 1]",
                material.where);
        }
    }
}

/// The material's reflection lobe as a shape (ρ = 1); Ward's weights become shares of ρd + ρs.
Bsdf::Reflection reflection_lobe(const model::Material& material) {
    switch (material.model) {
        case model::ReflectionModel::ward: {
            const model::WardParameters& w = material.ward;
            const double sum = w.diffuse + w.specular;
            const double specular = sum > 0.0 ? w.specular / sum : 0.0;
            return WardBrdf(1.0 - specular, specular, w.alpha_x, w.alpha_y);
        }
        case model::ReflectionModel::ross_li:
            return RossLiBrdf(material.ross_li.volumetric, material.ross_li.geometric);
        case model::ReflectionModel::lambertian:
            break;
    }
    return SurfaceBrdf(1.0, material.specular.fraction, material.specular.roughness);
}

}  // namespace

void MaterialTable::add_directional_emission(const model::Material& material,
                                             const SpectralGrid& grid,
                                             const std::vector<double>& rho) {
    const Bsdf& shape = m_shapes.back();
    if (shape.unit_albedo()) {
        m_albedo_slot.push_back(kNoSlot);
        return;
    }
    DirectionalAlbedo albedo(shape.reflection_lobe());
    const double largest_rho = *std::max_element(rho.begin(), rho.end());
    if (largest_rho * albedo.max() > 1.0 + kAlbedoSlack) {
        throw input_error("material '" + material.id + "': its lobe's directional albedo reaches " +
                              format_shortest(albedo.max()) + ", times its reflectance " +
                              format_shortest(largest_rho) +
                              " above 1 (it would reflect more than it receives)",
                          material.where);
    }
    if (!material.emissivity_is_default) {
        // A given emissivity is the material's, in every direction.
        m_albedo_slot.push_back(kNoSlot);
        return;
    }
    m_albedo_slot.push_back(m_albedos.size());
    m_albedos.push_back(albedo);
    for (std::size_t i = 0; i < m_bands; ++i) {
        m_reflected_planck.push_back(rho[i] * planck_radiance_w_per_cm2_sr_um(
                                                  grid.wavelength_um(i), material.temperature_k));
    }
    m_emits.back() = 1;
}

MaterialTable::MaterialTable(std::span<const model::Material> materials, const SpectralGrid& grid,
                             Log log)
    : m_bands(grid.size()) {
    for (std::size_t i = 0; i < m_bands; ++i) m_wavelengths_um.push_back(grid.wavelength_um(i));
    m_reflectance.reserve(materials.size() * m_bands);
    m_transmittance.reserve(materials.size() * m_bands);
    m_emission.reserve(materials.size() * m_bands);
    m_shapes.reserve(materials.size());
    for (const model::Material& material : materials) {
        if (material.reflectance.empty()) {
            throw input_error("material '" + material.id + "' has no reflectance", material.where);
        }
        if (!(material.temperature_k > 0.0) || !std::isfinite(material.temperature_k)) {
            throw input_error("material '" + material.id + "': temperature " +
                                  format_shortest(material.temperature_k) +
                                  " K must be a finite number > 0",
                              material.where);
        }
        bool covered = true;
        std::vector<double> rho = sample_held(material.reflectance, grid, covered);
        const bool thin = !material.transmittance.empty();
        std::vector<double> tau(rho.size(), 0.0);
        if (thin) tau = sample_held(material.transmittance, grid, covered);
        std::vector<double> eps;
        if (material.emissivity.empty()) {
            eps.resize(rho.size());
            for (std::size_t i = 0; i < rho.size(); ++i) eps[i] = 1.0 - rho[i] - tau[i];
        } else {
            eps = sample_held(material.emissivity, grid, covered);
        }
        check_unit_range(rho, material, "reflectance", grid);
        check_unit_range(tau, material, "transmittance", grid);
        check_unit_range(eps, material, "emissivity", grid);
        bool emits = false;
        bool reflects = false;
        bool transmits = false;
        double rho_sum = 0.0;
        double tau_sum = 0.0;
        // Where both curves are measured, model::check_material (every loader) has refused
        // ε + ρ > 1 + kEmissivityReflectanceSlack, and a sum within that slack (rounding) lowers
        // ρ to 1 − ε silently; beyond that, both are held end values — a guess — and ε is
        // lowered to 1 − ρ there, with one warning.
        const auto [measured_lo_um, measured_hi_um] = model::measured_range_um(material);
        std::optional<double> lowered_at_um;
        for (std::size_t i = 0; i < m_bands; ++i) {
            const double w = grid.wavelength_um(i);
            const bool measured = w >= measured_lo_um && w <= measured_hi_um;
            if (thin && rho[i] + tau[i] > 1.0 && !measured) {
                // Held end values beyond the measured curves: τ gives way, as ε does below.
                tau[i] = std::max(0.0, 1.0 - rho[i]);
                if (!lowered_at_um) lowered_at_um = w;
            }
            if (eps[i] + rho[i] + tau[i] > 1.0) {
                if (measured) {
                    if (eps[i] + rho[i] + tau[i] > 1.0 + model::kEmissivityReflectanceSlack) {
                        throw input_error(
                            "material '" + material.id + "': emissivity " +
                                format_shortest(eps[i]) + " + reflectance " +
                                format_shortest(rho[i]) +
                                (thin ? " + transmittance " + format_shortest(tau[i]) : "") +
                                " exceed 1 at " + format_shortest(w) +
                                " um (an opaque surface cannot emit and reflect more than a "
                                "blackbody)",
                            material.where);
                    }
                    rho[i] = std::max(0.0, 1.0 - eps[i] - tau[i]);
                } else if (eps[i] + rho[i] + tau[i] > 1.0 + kRangeSlack) {
                    eps[i] = 1.0 - rho[i] - tau[i];
                    if (!lowered_at_um) lowered_at_um = w;
                }
            }
            rho[i] = std::clamp(rho[i], 0.0, 1.0);
            tau[i] = std::clamp(tau[i], 0.0, 1.0);
            transmits = transmits || tau[i] > 0.0;
            rho_sum += rho[i];
            tau_sum += tau[i];
            m_transmittance.push_back(tau[i]);
            m_emissivity.push_back(std::clamp(eps[i], 0.0, 1.0));
            const double e =
                m_emissivity.back() *
                planck_radiance_w_per_cm2_sr_um(grid.wavelength_um(i), material.temperature_k);
            emits = emits || e > 0.0;
            reflects = reflects || rho[i] > 0.0;
            m_reflectance.push_back(rho[i]);
            m_emission.push_back(e);
        }
        if (lowered_at_um) {
            log.warning(
                format_located(material.where, "material '" + material.id +
                                                   "': beyond its measured curves (from " +
                                                   format_shortest(*lowered_at_um) +
                                                   " um) the held end values give emissivity + "
                                                   "reflectance (+ transmittance) > 1; "
                                                   "emissivity (and transmittance) lowered "
                                                   "there"));
        }
        if (!covered) {
            const std::string where =
                material.where.file.empty() ? std::string() : material.where.file + ": ";
            log.warning(where + "material '" + material.id + "': its curves do not cover " +
                        format_shortest(grid.min_um()) + "-" + format_shortest(grid.max_um()) +
                        " um; the end values are held beyond them");
        }
        m_emits.push_back(emits ? 1 : 0);
        m_reflects.push_back(reflects ? 1 : 0);
        m_transmits.push_back(transmits ? 1 : 0);
        m_double_sided.push_back(material.double_sided ? 1 : 0);
        // Transmission is drawn in proportion to the band-mean τ against ρ + τ (0 for an
        // opaque material: its paths draw exactly what they drew before transmission existed).
        m_shapes.emplace_back(reflection_lobe(material),
                              transmits ? tau_sum / (rho_sum + tau_sum) : 0.0,
                              material.straight_transmission);
        m_any_straight = m_any_straight || m_shapes.back().straight();
        add_directional_emission(material, grid, rho);
    }
}

}  // namespace glint::radiometry
