// SPDX-License-Identifier: Apache-2.0
// Multiple scattering in a plane-parallel atmosphere by successive orders of scattering:
// homogeneous layers (optical depth, single-scatter albedo, Legendre moments of the phase
// function) over a Lambertian ground, lit by a parallel beam. Scalar radiance (polarization
// ignored), Gauss–Legendre directions in each hemisphere, a Fourier series in azimuth, the
// direct beam's first scattering integrated exactly through each sublayer and the diffuse
// sources linear in optical depth within sublayers of at most max_sublayer_depth.
// Formulas and tests: docs/physics.md ("Multiple scattering").
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace glint::atmosphere {

/// One homogeneous layer.
struct ScatteringLayer {
    double optical_depth = 0.0;          ///< vertical extinction optical depth, ≥ 0
    double single_scatter_albedo = 0.0;  ///< [0, 1]
    /// Legendre moments χ_l of the phase function, P(cos Θ) = Σ_l (2l + 1) χ_l P_l(cos Θ),
    /// normalized so that χ_0 = 1 (Rayleigh: {1, 0, 0.1}; Henyey–Greenstein: χ_l = g^l).
    std::vector<double> moments{1.0};
};

/// A problem; the beam's irradiance is `beam_irradiance` (1 by default) on a surface normal to
/// it at the top. Thermal sources, in any unit of radiance (the fluxes and radiances then
/// come out in it): the layers' own emission (1 − ω) B(τ), B given at every level and linear
/// in optical depth within a layer; the ground's (1 − A) B_ground; an isotropic radiance
/// entering at the top.
struct ScatteringProblem {
    std::vector<ScatteringLayer> layers;  ///< from the top of the atmosphere down
    double sun_cos_zenith = 1.0;          ///< μ₀ in (0, 1]
    double ground_albedo = 0.0;           ///< Lambertian, [0, 1]
    double beam_irradiance = 1.0;         ///< ≥ 0; 0: no beam
    /// B at each level (layers.size() + 1 values, top first); empty: the layers do not emit.
    std::vector<double> level_planck;
    double ground_planck = 0.0;           ///< B of the ground (it emits (1 − A) of it)
    double top_isotropic_radiance = 0.0;  ///< entering downward at the top, every direction
    int streams = 8;                      ///< Gauss–Legendre directions per hemisphere
    int azimuth_modes = 1;                ///< Fourier terms cos(mφ), m < azimuth_modes
    double max_sublayer_depth = 0.02;     ///< optical depth of the integration sublayers
    double tolerance = 1e-6;              ///< stop when the rest of the series is below this
                                          ///< share of the field (geometric estimate)
    int max_orders = 2000;
};

/// The solution. Levels are the layer boundaries: 0 at the top, layers.size() at the ground.
/// Fluxes are in the units of the beam's irradiance normal to it at the top (1 by default)
/// and of the thermal sources.
class ScatteringSolution {
public:
    std::size_t levels() const noexcept { return m_level_boundary.size(); }
    /// Optical depth from the top to `level`.
    double optical_depth(std::size_t level) const noexcept;
    /// Direct-beam flux on a horizontal surface at `level`: μ₀ e^(−τ/μ₀).
    double direct_flux(std::size_t level) const noexcept;
    /// Downward and upward diffuse fluxes at `level` (hemispheric integrals of μ·I).
    double diffuse_down_flux(std::size_t level) const noexcept;
    double diffuse_up_flux(std::size_t level) const noexcept;
    /// Upward radiance at `level` in direction cos(zenith) = `mu` (> 0), at azimuth
    /// `relative_azimuth_rad` from the beam's direction of travel (0: light travelling away
    /// from the sun), from all scattering except the direct beam's first (the layers' own
    /// thermal emission is not in it: the fluxes and the field hold it): the diffuse field,
    /// including the light the ground reflected, scattered once more between the ground and
    /// `level`. The light reflected by the ground reaching `level` unscattered is not in it.
    double multiple_scatter_up_radiance(std::size_t level, double mu,
                                        double relative_azimuth_rad) const;
    /// Downward radiance at `level` travelling at cos(zenith) = `mu` (> 0, the direction it
    /// comes from seen from below), at `relative_azimuth_rad`, from all scattering except the
    /// direct beam's first, between the top and `level`: the in-scattered part of the sky.
    /// Neither the layers' own emission nor the radiance entering at the top unscattered is
    /// in it. With thermal sources and no beam it is what thermal multiple scattering adds
    /// to a sky the emission integral already holds.
    double multiple_scatter_down_radiance(std::size_t level, double mu,
                                          double relative_azimuth_rad) const;
    /// The same radiance from the first scattering of the direct beam alone, with the
    /// truncated phase function of the problem (for checks against the exact one).
    double single_scatter_up_radiance(std::size_t level, double mu,
                                      double relative_azimuth_rad) const;
    /// The Fourier terms of multiple_scatter_up_radiance at `level` and `mu`: the radiance at
    /// azimuth φ is Σ_m terms[m] cos(mφ).
    std::vector<double> multiple_scatter_up_modes(std::size_t level, double mu) const;
    /// The Fourier terms of multiple_scatter_down_radiance at `level` and `mu`, as
    /// multiple_scatter_up_modes'.
    std::vector<double> multiple_scatter_down_modes(std::size_t level, double mu) const;
    /// Orders of scattering summed, per azimuth mode.
    const std::vector<int>& orders() const noexcept { return m_orders; }

private:
    friend ScatteringSolution solve_scattering_orders(const ScatteringProblem& problem);
    std::vector<double> up_modes(std::size_t level, double mu, bool diffuse) const;
    std::vector<double> down_modes(std::size_t level, double mu) const;

    ScatteringProblem m_problem;
    std::vector<double> m_mu;                   ///< Gauss nodes in (0, 1)
    std::vector<double> m_weight;               ///< Gauss weights (sum 1)
    std::vector<double> m_tau;                  ///< sublayer boundaries, top (0) to ground
    std::vector<std::size_t> m_layer_of;        ///< layer of each sublayer
    std::vector<std::size_t> m_level_boundary;  ///< sublayer boundary of each level
    /// Total field per mode: [mode][boundary][direction], directions 0..N−1 upward (+μᵢ),
    /// N..2N−1 downward (−μᵢ).
    std::vector<std::vector<double>> m_field;
    std::vector<int> m_orders;
};

/// Σ_m terms[m] cos(m φ): a radiance from its Fourier terms (the *_modes functions) at
/// relative azimuth `phi` (rad). Throws glint::Error (input) for a non-finite φ.
double sum_modes(std::span<const double> terms, double phi);

/// The n-point Gauss–Legendre rule on (0, 1), weights summing to 1 (exact for polynomials of degree
/// ≤ 2n − 1).
void gauss_legendre_unit(int n, std::vector<double>& nodes, std::vector<double>& weights);

/// Solves `problem`. Throws glint::Error (input) for an empty layer list, a negative or
/// non-finite optical depth, an albedo or single-scatter albedo outside [0, 1], μ₀ outside
/// (0, 1], streams < 2, azimuth_modes < 1, a moment list without χ_0 = 1.
ScatteringSolution solve_scattering_orders(const ScatteringProblem& problem);

}  // namespace glint::atmosphere
