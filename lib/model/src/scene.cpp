// SPDX-License-Identifier: Apache-2.0
// Scene data built in code (glint/model/scene.h).
#include "glint/model/scene.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "glint/core/text.h"

namespace glint::model {

Material flat_material(const std::string& id, double reflectance, double temperature_k,
                       std::optional<double> emissivity, SpecularLobe specular,
                       double transmittance) {
    Material m;
    m.id = id;
    m.name = id;
    m.reflectance.wavelengths_um = {0.1, 100.0};
    m.reflectance.values = {reflectance, reflectance};
    if (transmittance > 0.0) {
        m.transmittance.wavelengths_um = {0.1, 100.0};
        m.transmittance.values = {transmittance, transmittance};
    }
    const double e = emissivity.value_or(1.0 - reflectance - transmittance);
    m.emissivity.wavelengths_um = {0.1, 100.0};
    m.emissivity.values = {e, e};
    m.emissivity_is_default = !emissivity.has_value();
    m.temperature_k = temperature_k;
    m.specular = specular;
    return m;
}

double sample_held(const SpectralTable& table, double wavelength_um) {
    const std::vector<double>& x = table.wavelengths_um;
    const std::vector<double>& y = table.values;
    if (wavelength_um <= x.front()) return y.front();
    if (wavelength_um >= x.back()) return y.back();
    const auto hi =
        static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), wavelength_um) - x.begin());
    const std::size_t lo = hi - 1;
    const double f = (wavelength_um - x[lo]) / (x[hi] - x[lo]);
    return y[lo] + f * (y[hi] - y[lo]);
}

std::pair<double, double> measured_range_um(const Material& material) {
    double lo = material.reflectance.wavelengths_um.front();
    double hi = material.reflectance.wavelengths_um.back();
    for (const SpectralTable* table : {&material.transmittance, &material.emissivity}) {
        if (table->empty()) continue;
        lo = std::max(lo, table->wavelengths_um.front());
        hi = std::min(hi, table->wavelengths_um.back());
    }
    return {lo, hi};
}

namespace {

/// The reflection model's parameters: Ward's weights in [0, 1] summing to at most 1 and its
/// widths in (0, 1]; Ross–Li's weights finite.
bool check_reflection_model(const Material& material, const std::string& name,
                            Diagnostics& diagnostics) {
    if (material.model == ReflectionModel::ward) {
        const WardParameters& w = material.ward;
        if (!(w.diffuse >= 0.0 && w.specular >= 0.0 && w.diffuse + w.specular <= 1.0)) {
            diagnostics.error(material.where, name + ": Ward weights diffuse " +
                                                  format_shortest(w.diffuse) + " and specular " +
                                                  format_shortest(w.specular) +
                                                  " must be >= 0 with a sum of at most 1");
            return false;
        }
        if (!(w.alpha_x > 0.0 && w.alpha_x <= 1.0 && w.alpha_y > 0.0 && w.alpha_y <= 1.0)) {
            diagnostics.error(material.where,
                              name + ": Ward widths (sigma) " + format_shortest(w.alpha_x) +
                                  " and " + format_shortest(w.alpha_y) + " must lie in (0, 1]");
            return false;
        }
        if (material.specular.fraction != 0.0) {
            diagnostics.error(material.where,
                              name + ": a Ward material has no separate specular lobe");
            return false;
        }
    }
    if (material.model == ReflectionModel::ross_li) {
        if (!std::isfinite(material.ross_li.volumetric) ||
            !std::isfinite(material.ross_li.geometric)) {
            diagnostics.error(material.where, name + ": Ross-Li weights must be finite numbers");
            return false;
        }
        if (material.specular.fraction != 0.0) {
            diagnostics.error(material.where,
                              name + ": a Ross-Li material has no separate specular lobe");
            return false;
        }
    }
    return true;
}

}  // namespace

void check_material(const Material& material, Diagnostics& diagnostics) {
    // Rounding slack of the [0, 1] ranges; the renderer allows the same.
    constexpr double kSlack = 1e-9;
    const std::string name = "material '" + material.id + "'";
    if (material.reflectance.empty()) {
        diagnostics.error(material.where, name + " has no reflectance");
        return;
    }
    if (!(material.temperature_k > 0.0) || !std::isfinite(material.temperature_k)) {
        diagnostics.error(material.where, name + ": temperature " +
                                              format_shortest(material.temperature_k) +
                                              " K must be a finite number > 0");
    }
    if (!material.double_sided && !material.transmittance.empty()) {
        diagnostics.error(material.where,
                          name +
                              " is single-sided and has a transmittance: light cannot pass "
                              "a surface whose back face is black");
        return;
    }
    if (!check_reflection_model(material, name, diagnostics)) return;
    if (material.straight_transmission && material.transmittance.empty()) {
        diagnostics.error(material.where, name + ": straight transmission needs a transmittance");
        return;
    }
    std::set<double> wavelengths(material.reflectance.wavelengths_um.begin(),
                                 material.reflectance.wavelengths_um.end());
    for (const SpectralTable* table : {&material.transmittance, &material.emissivity}) {
        wavelengths.insert(table->wavelengths_um.begin(), table->wavelengths_um.end());
    }
    const std::pair<double, double> measured = measured_range_um(material);
    const bool thin = !material.transmittance.empty();
    for (const double w : wavelengths) {
        const double rho = sample_held(material.reflectance, w);
        const double tau = thin ? sample_held(material.transmittance, w) : 0.0;
        const double eps =
            material.emissivity.empty() ? 1.0 - rho - tau : sample_held(material.emissivity, w);
        const std::string at = " at " + format_shortest(w) + " um";
        if (!(rho >= -kSlack && rho <= 1.0 + kSlack)) {
            diagnostics.error(material.where, name + ": reflectance " + format_shortest(rho) + at +
                                                  " lies outside [0, 1]");
            return;
        }
        if (!(tau >= -kSlack && tau <= 1.0 + kSlack)) {
            diagnostics.error(material.where, name + ": transmittance " + format_shortest(tau) +
                                                  at + " lies outside [0, 1]");
            return;
        }
        if (thin && rho + tau > 1.0 + kEmissivityReflectanceSlack && w >= measured.first &&
            w <= measured.second) {
            diagnostics.error(material.where,
                              name + ": reflectance " + format_shortest(rho) + " + transmittance " +
                                  format_shortest(tau) + " exceed 1" + at +
                                  " (a sheet cannot scatter more than it receives)");
            return;
        }
        if (!(eps >= -kSlack && eps <= 1.0 + kSlack)) {
            diagnostics.error(material.where, name + ": emissivity " + format_shortest(eps) + at +
                                                  " lies outside [0, 1]");
            return;
        }
        if (eps + rho + tau > 1.0 + kEmissivityReflectanceSlack && w >= measured.first &&
            w <= measured.second) {
            diagnostics.error(
                material.where,
                name + ": emissivity " + format_shortest(eps) + " + reflectance " +
                    format_shortest(rho) +
                    (thin ? " + transmittance " + format_shortest(tau) : "") + " exceed 1" + at +
                    (thin ? " (Kirchhoff: a sheet absorbs, so emits, only 1 - reflectance - "
                            "transmittance)"
                          : " (an opaque surface cannot emit and reflect more than a "
                            "blackbody)"));
            return;
        }
    }
}

SpectralTable kirchhoff_emissivity(const Material& material) {
    std::vector<double> at = material.reflectance.wavelengths_um;
    at.insert(at.end(), material.transmittance.wavelengths_um.begin(),
              material.transmittance.wavelengths_um.end());
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    SpectralTable table;
    const bool thin = !material.transmittance.empty();
    for (const double w : at) {
        table.wavelengths_um.push_back(w);
        const double rho = sample_held(material.reflectance, w);
        const double tau = thin ? sample_held(material.transmittance, w) : 0.0;
        table.values.push_back(thin ? std::max(0.0, 1.0 - rho - tau) : 1.0 - rho);
    }
    table.where = material.reflectance.where;
    return table;
}

}  // namespace glint::model
