// SPDX-License-Identifier: Apache-2.0
// The slab of glint/thermal/slab.h: nodes from the exposed face to the back, each holding the
// heat of its share of the thickness (half a spacing at either face), backward Euler in time
// with the face's emission linearised and iterated (Newton) to convergence, a tridiagonal
// solve per iteration.
#include "glint/thermal/slab.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/error.h"

namespace glint::thermal {

namespace {

/// Newton iterations on the face temperature stop below this change, K.
constexpr double kConvergedK = 1e-10;
constexpr int kMaxIterations = 50;

void check(bool ok, const std::string& what) {
    if (!ok) throw input_error("thermal slab: " + what);
}

}  // namespace

Slab::Slab(const SlabMaterial& material, std::size_t nodes, double initial_temperature_k)
    : m_material(material) {
    const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    const auto fraction = [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 1.0; };
    check(positive(material.thickness_m), "the thickness must be > 0 m");
    check(positive(material.density_kg_per_m3), "the density must be > 0 kg/m³");
    check(positive(material.specific_heat_j_per_kg_k), "the specific heat must be > 0 J/(kg K)");
    check(positive(material.conductivity_w_per_m_k), "the conductivity must be > 0 W/(m K)");
    check(fraction(material.solar_absorptance), "the solar absorptance must lie in [0, 1]");
    check(fraction(material.thermal_emissivity), "the thermal emissivity must lie in [0, 1]");
    check(fraction(material.exposed_area), "the exposed area must lie in [0, 1]");
    check(std::isfinite(material.internal_heat_w_per_m2), "the internal heat must be finite");
    check(nodes >= 2, "at least 2 nodes");
    check(positive(initial_temperature_k), "the initial temperature must be > 0 K");
    m_dz = material.thickness_m / static_cast<double>(nodes - 1);
    m_t.assign(nodes, initial_temperature_k);
    m_lower.resize(nodes);
    m_diag.resize(nodes);
    m_upper.resize(nodes);
    m_rhs.resize(nodes);
}

double Slab::face_flux_w_per_m2(const SurfaceForcing& f, double surface_k) const noexcept {
    const double a = m_material.exposed_area;
    const double e = m_material.thermal_emissivity;
    const double t2 = surface_k * surface_k;
    return f.absorbed_sun_w_per_m2 + e * (f.longwave_down_w_per_m2 - kStefanBoltzmann * t2 * t2) +
           a * f.convection_w_per_m2_k * (f.air_temperature_k - surface_k);
}

double Slab::stored_heat_j_per_m2() const noexcept {
    const double rho_c = m_material.density_kg_per_m3 * m_material.specific_heat_j_per_kg_k;
    double sum = 0.0;
    for (std::size_t i = 0; i < m_t.size(); ++i) {
        const double width = (i == 0 || i + 1 == m_t.size()) ? 0.5 * m_dz : m_dz;
        sum += m_t[i] * width;
    }
    return rho_c * sum;
}

void Slab::step(const SurfaceForcing& f, double dt_s) {
    check(std::isfinite(dt_s) && dt_s > 0.0, "the time step must be > 0 s");
    const std::size_t n = m_t.size();
    const double rho_c = m_material.density_kg_per_m3 * m_material.specific_heat_j_per_kg_k;
    const double k_dz = m_material.conductivity_w_per_m_k / m_dz;
    const double q_per_m = m_material.internal_heat_w_per_m2 / m_material.thickness_m;
    const double a = m_material.exposed_area;
    const double e = m_material.thermal_emissivity;
    const std::vector<double> old = m_t;
    const auto width = [&](std::size_t i) { return (i == 0 || i + 1 == n) ? 0.5 * m_dz : m_dz; };

    double surface = old.front();  // the linearisation point of the face's flux
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        for (std::size_t i = 0; i < n; ++i) {
            const double c = rho_c * width(i) / dt_s;
            m_lower[i] = i > 0 ? -k_dz : 0.0;
            m_upper[i] = i + 1 < n ? -k_dz : 0.0;
            m_diag[i] = c + (i > 0 ? k_dz : 0.0) + (i + 1 < n ? k_dz : 0.0);
            m_rhs[i] = c * old[i] + q_per_m * width(i);
        }
        // The face: F(T) ≈ F(T*) + F'(T*)(T − T*).
        const double derivative =
            -4.0 * e * kStefanBoltzmann * surface * surface * surface - a * f.convection_w_per_m2_k;
        m_diag[0] -= derivative;
        m_rhs[0] += face_flux_w_per_m2(f, surface) - derivative * surface;
        if (m_material.back_held) {
            m_lower[n - 1] = 0.0;
            m_diag[n - 1] = 1.0;
            m_rhs[n - 1] = f.back_temperature_k;
        }
        // Thomas algorithm.
        for (std::size_t i = 1; i < n; ++i) {
            const double w = m_lower[i] / m_diag[i - 1];
            m_diag[i] -= w * m_upper[i - 1];
            m_rhs[i] -= w * m_rhs[i - 1];
        }
        m_t[n - 1] = m_rhs[n - 1] / m_diag[n - 1];
        for (std::size_t i = n - 1; i-- > 0;) {
            m_t[i] = (m_rhs[i] - m_upper[i] * m_t[i + 1]) / m_diag[i];
        }
        const double change = std::abs(m_t[0] - surface);
        surface = m_t[0];
        if (change < kConvergedK) break;
    }
    // What entered over the step: through the face (at the converged temperature), from
    // inside, and through the back (the back node's balance when it is held).
    double heat_in = face_flux_w_per_m2(f, m_t[0]) + m_material.internal_heat_w_per_m2;
    if (m_material.back_held) {
        const double stored = rho_c * width(n - 1) * (m_t[n - 1] - old[n - 1]) / dt_s;
        const double conducted = k_dz * (m_t[n - 2] - m_t[n - 1]);
        heat_in += stored - conducted - q_per_m * width(n - 1);
    }
    m_last_heat_in = heat_in * dt_s;
}

double Slab::penetration_depth_m(const SlabMaterial& m, double period_s) noexcept {
    const double diffusivity =
        m.conductivity_w_per_m_k / (m.density_kg_per_m3 * m.specific_heat_j_per_kg_k);
    return std::sqrt(2.0 * diffusivity / (2.0 * std::numbers::pi / period_s));
}

double steady_surface_temperature_k(const SlabMaterial& material, const SurfaceForcing& forcing) {
    const Slab slab(material, 2, 300.0);
    const double q = material.internal_heat_w_per_m2;
    // Increasing in T: insulated, −(F(T) + q); held, T − T_back − L (F(T) + q/2) / k.
    const auto balance = [&](double t) {
        const double flux = slab.face_flux_w_per_m2(forcing, t);
        if (!material.back_held) return -(flux + q);
        return t - forcing.back_temperature_k -
               material.thickness_m * (flux + 0.5 * q) / material.conductivity_w_per_m_k;
    };
    double lo = 1.0;
    double hi = 2000.0;
    if (!(balance(lo) < 0.0 && balance(hi) > 0.0)) {
        throw input_error("thermal slab: no equilibrium between 1 K and 2000 K");
    }
    while (hi - lo > 1e-9) {
        const double mid = 0.5 * (lo + hi);
        (balance(mid) < 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace glint::thermal
