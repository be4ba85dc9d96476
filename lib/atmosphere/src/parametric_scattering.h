// SPDX-License-Identifier: Apache-2.0
// The parametric model's multiple-scattering solutions of one geometry (private to
// lib/atmosphere: parametric_scattering.cpp makes them, parametric_atmosphere.cpp reads the
// diffuse sky from them).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "glint/atmosphere/atmosphere.h"
#include "glint/atmosphere/scattering_orders.h"

namespace glint::atmosphere {

/// Multiple-scattering solutions of one geometry at wavelength nodes, and how each band of
/// the grid interpolates between them.
struct ParametricAtmosphereModel::Scattering {
    std::vector<double> grid;  ///< the grid's wavelengths (part of the key)
    double sun_zenith_deg = 0.0;
    double surface_altitude_m = 0.0;
    double sensor_altitude_m = 0.0;
    std::vector<ScatteringSolution> solutions;  ///< one per node
    /// Per node, per unit beam irradiance: the forward-scattered light δ-M moved into the
    /// direct beam, reaching a horizontal ground (μ₀ (e^(−τ'/μ₀) − e^(−τ/μ₀))), part of the
    /// diffuse sky.
    std::vector<double> forward_peak;
    std::size_t sensor_level = 0;    ///< level of the sensor altitude
    std::vector<std::size_t> lower;  ///< per band: the node below
    std::vector<double> fraction;    ///< per band: weight of the node above

    /// Per band, the value of `at_node` interpolated in ln λ.
    template <typename PerNode>
    std::vector<double> per_band(PerNode&& at_node) const {
        std::vector<double> nodes(solutions.size());
        for (std::size_t k = 0; k < solutions.size(); ++k) nodes[k] = at_node(k);
        std::vector<double> out(lower.size());
        for (std::size_t i = 0; i < lower.size(); ++i) {
            const std::size_t k = lower[i];
            const double f = fraction[i];
            out[i] = f == 0.0 ? nodes[k] : (1.0 - f) * nodes[k] + f * nodes[k + 1];
        }
        return out;
    }
};

/// The layer boundaries of the solutions, ascending: the surface `z0` to 100 km spaced
/// ∝ (k/K)³ (K = kScatteringLayers, denser near the ground), and the sensor's altitude `z1`;
/// and the sensor's level, counted from the top as the solver counts them.
struct ScatteringLevels {
    std::vector<double> bounds;
    std::size_t sensor_level = 0;
};
ScatteringLevels scattering_levels(double z0, double z1);

/// One aerosol regime's part of a solver layer: its extinction optical depth, albedo and
/// phase-function moments χ₀ … χ_2N (N the solver's streams).
struct AerosolShare {
    double optical_depth = 0.0;
    double single_scatter_albedo = 1.0;
    std::span<const double> moments;
};

/// A solver layer holding the Rayleigh optical depth `rayleigh`, the aerosol `aerosols` and
/// `absorption` more of a pure absorber, for `streams` streams: the mixed phase function's
/// moments χ₀ … χ_2N−1 after δ-M scaling (W. J. Wiscombe, "The delta-M method: rapid yet
/// accurate radiative flux calculations for strongly asymmetric phase functions", Journal of
/// the Atmospheric Sciences 34, 1977, 1408–1422): the forward peak f = χ_2N of the mix is cut
/// off, χ'_l = (χ_l − f)/(1 − f), τ' = (1 − ω f) τ, ω' = ω (1 − f)/(1 − ω f). The optical
/// depth it removes (τ − τ', the peak's light, which travels on with the direct beam) is
/// returned in `truncated_depth` when given.
ScatteringLayer scattering_layer(double rayleigh, std::span<const AerosolShare> aerosols,
                                 double absorption, int streams, double* truncated_depth = nullptr);

/// The aerosol of `column` at `wavelength_um` for a solver of `streams` streams: per regime,
/// its optics with 2N + 1 moments.
std::vector<RegimeOptics> solver_aerosol_optics(const AerosolColumn& column, double wavelength_um,
                                                int streams);

/// Thermal multiple-scattering solutions of one pair of altitudes, one per band where it is
/// solved (thermal_scattering.cpp).
struct ParametricAtmosphereModel::ThermalScattering {
    std::vector<double> grid;  ///< the grid's wavelengths (part of the key)
    double surface_altitude_m = 0.0;
    double sensor_altitude_m = 0.0;
    std::size_t sensor_level = 0;                          ///< level of the sensor altitude
    std::size_t ground_level = 0;                          ///< level of the surface (the last)
    std::vector<std::optional<ScatteringSolution>> bands;  ///< empty: not solved
};

}  // namespace glint::atmosphere
