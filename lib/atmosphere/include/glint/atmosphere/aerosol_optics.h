// SPDX-License-Identifier: Apache-2.0
// The optics of a population of homogeneous spherical particles: Mie's solution
// (glint/atmosphere/mie.h) averaged over a truncated lognormal size distribution, as the
// aerosol components of M. Hess, P. Koepke, I. Schult, "Optical Properties of Aerosols and
// Clouds: The Software Package OPAC", Bulletin of the American Meteorological Society 79,
// 1998, 831–844, define them. The per-particle cross sections, the single-scattering albedo,
// the phase function at chosen angles and its Legendre moments. data/atmosphere/
// aerosol_optics.csv is written from these by tests/tools/aerosol_tables.cpp; the formulas and
// the checks against OPAC's own tables: docs/physics.md ("Aerosol optics").
#pragma once

#include <complex>
#include <span>
#include <vector>

namespace glint::atmosphere {

/// A lognormal number distribution, dN/d ln r = N/(√(2π) ln σ) exp(−(ln r − ln r_mod)² /
/// (2 ln² σ)), σ = `sigma` the geometric standard deviation (> 1), whose optics are integrated
/// over [min_radius_um, max_radius_um] only: N counts the whole lognormal, the particles
/// outside the bounds add nothing (OPAC's convention).
struct LogNormalSizes {
    double mode_radius_um = 0.0;
    double sigma = 0.0;
    double min_radius_um = 0.0;
    double max_radius_um = 0.0;
};

/// The mean optics of one particle of a population at one wavelength.
struct ParticleOptics {
    double extinction_um2 = 0.0;  ///< mean extinction cross section per particle, µm²
    double scattering_um2 = 0.0;  ///< mean scattering cross section per particle, µm²
    double asymmetry = 0.0;       ///< g = ⟨cos Θ⟩ of the scattered light
    /// The phase function at the requested angles, normalised to ∫P dΩ / 4π = 1.
    std::vector<double> phase;
    /// Its Legendre moments χ_l = ½ ∫ P(μ) P_l(μ) dμ, l = 0 … requested − 1 (χ₀ = 1, χ₁ = g).
    std::vector<double> legendre;
    /// The angular quadrature's ∫P dΩ / 4π before normalisation, against the Mie series'
    /// scattering cross section: how well the angle grid resolves the forward peak (1 exact).
    double angular_closure = 0.0;
};

/// The optics of the population `sizes` of spheres of refractive index `index` (n + i k, k ≥ 0)
/// at `wavelength_um`: cross sections integrated over ln r (trapezoid, nodes closer where the
/// size parameter is large), the phase function from the size-summed (|S1|² + |S2|²)/2 on a
/// fixed fine grid of scattering angles (finest at the forward peak), interpolated to
/// `angles_deg` and integrated for `legendre_count` moments. Throws glint::Error (input) for a
/// distribution that is not one (sigma ≤ 1, radii not 0 < min < max, mode ≤ 0), a
/// non-positive wavelength, or angles outside [0, 180].
ParticleOptics size_averaged_optics(const LogNormalSizes& sizes, std::complex<double> index,
                                    double wavelength_um, std::span<const double> angles_deg,
                                    int legendre_count);

/// The mean volume of one particle of `sizes`, µm³: (4π/3) ∫ r³ over the bounds per particle
/// of the whole lognormal (OPAC's convention, as for the optics; closed form). A particle's
/// mean mass is this × its material's density. Throws glint::Error (input) as
/// size_averaged_optics() does for a distribution that is not one.
double mean_particle_volume_um3(const LogNormalSizes& sizes);

}  // namespace glint::atmosphere
