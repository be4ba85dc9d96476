// SPDX-License-Identifier: Apache-2.0
// The transient surface energy balance of one facet: a slab of the material's thickness,
// density, specific heat and conductivity, heated at its exposed face by the absorbed sun,
// the sky's and the surroundings' longwave and convection with the air, losing its own
// emission, with its back face held at a deep temperature or insulated. One-dimensional
// conduction on nodes through the thickness, implicit (backward Euler) in time, the emission
// linearised about the last iterate and iterated to convergence; the scheme conserves energy
// to rounding (what enters the faces is what the nodes store). SI units throughout: W/m²,
// K, m, s, kg/m³, J/(kg K), W/(m K). Formulas and validation: docs/thermal.md.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace glint::thermal {

/// Stefan–Boltzmann constant, W/(m² K⁴).
inline constexpr double kStefanBoltzmann = 5.670374419e-8;

/// The material of a slab and how its faces exchange heat.
struct SlabMaterial {
    double thickness_m = 0.1;
    double density_kg_per_m3 = 2000.0;
    double specific_heat_j_per_kg_k = 900.0;
    double conductivity_w_per_m_k = 1.0;
    double solar_absorptance = 0.7;   ///< of the broadband sun (1 − solar reflectance)
    double thermal_emissivity = 0.9;  ///< broadband longwave emissivity (= absorptance)
    /// Fraction of the face that exchanges heat with the air by convection (DIRSIG's exposed
    /// area); the sun and the longwave reach the whole face.
    double exposed_area = 1.0;
    /// Heat generated inside the slab per unit face area (engines, people), W/m².
    double internal_heat_w_per_m2 = 0.0;
    /// The back face: held at back_temperature_k of the forcing (true) or insulated (false).
    bool back_held = true;
};

/// What reaches the exposed face at one instant.
struct SurfaceForcing {
    double absorbed_sun_w_per_m2 = 0.0;   ///< already × absorptance, cosine and shadow
    double longwave_down_w_per_m2 = 0.0;  ///< sky (and surroundings) irradiance on the face
    double air_temperature_k = 290.0;
    double convection_w_per_m2_k = 10.0;  ///< heat transfer coefficient with the air
    double back_temperature_k = 290.0;    ///< the deep temperature, when back_held
};

/// One slab's temperatures through its thickness, advanced in time.
class Slab {
public:
    /// `nodes` ≥ 2 equally spaced nodes from the face (0) to the back, all at
    /// `initial_temperature_k`. Throws glint::Error (input) for a non-positive or non-finite
    /// property, absorptance or emissivity outside [0, 1], exposed area outside [0, 1].
    Slab(const SlabMaterial& material, std::size_t nodes, double initial_temperature_k);

    /// Advances by `dt_s` under `forcing` (held over the step).
    void step(const SurfaceForcing& forcing, double dt_s);

    /// The exposed face's temperature, K.
    double surface_temperature_k() const noexcept { return m_t.front(); }
    /// Every node's temperature, face first, K.
    std::span<const double> temperatures_k() const noexcept { return m_t; }
    /// Depth of node `i`, m.
    double depth_m(std::size_t i) const noexcept { return static_cast<double>(i) * m_dz; }
    /// Heat stored per unit face area above 0 K, J/m² (ρ c Σ T_i × each node's share).
    double stored_heat_j_per_m2() const noexcept;
    /// Net heat that entered through both faces and from inside over the last step, per
    /// unit face area, J/m² (for the energy balance).
    double last_step_heat_in_j_per_m2() const noexcept { return m_last_heat_in; }

    /// The net flux into the exposed face at temperature `surface_k`, W/m²: sun + ε·(L↓ −
    /// σT⁴) + a·h·(T_air − T), a the exposed area.
    double face_flux_w_per_m2(const SurfaceForcing& forcing, double surface_k) const noexcept;

    /// The thermal penetration depth of a period `period_s`, √(2κ/ω), m.
    static double penetration_depth_m(const SlabMaterial& material, double period_s) noexcept;

private:
    SlabMaterial m_material;
    double m_dz = 0.0;
    std::vector<double> m_t;
    double m_last_heat_in = 0.0;
    // Scratch of the tridiagonal solve.
    std::vector<double> m_lower, m_diag, m_upper, m_rhs;
};

/// The temperature of a face in equilibrium with `forcing` (insulated back: net face flux 0;
/// held back: face flux = conduction to the back, k (T − T_back)/L), by bisection to 1e-9 K.
double steady_surface_temperature_k(const SlabMaterial& material, const SurfaceForcing& forcing);

}  // namespace glint::thermal
