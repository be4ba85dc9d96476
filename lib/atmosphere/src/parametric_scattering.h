// SPDX-License-Identifier: Apache-2.0
// The parametric model's multiple-scattering solutions of one geometry (private to
// lib/atmosphere: parametric_scattering.cpp makes them, parametric_atmosphere.cpp reads the
// diffuse sky from them).
#pragma once

#include <cstddef>
#include <optional>
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
    std::size_t sensor_level = 0;               ///< level of the sensor altitude
    std::vector<std::size_t> lower;             ///< per band: the node below
    std::vector<double> fraction;               ///< per band: weight of the node above

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

/// A solver layer holding Rayleigh (`rayleigh`) and aerosol (`aerosol`) optical depths, the
/// aerosol of single-scatter albedo `omega_a` and Henyey–Greenstein asymmetry `g`, and
/// `absorption` more of a pure absorber; its phase function's moments for `streams`.
ScatteringLayer rayleigh_aerosol_layer(double rayleigh, double aerosol, double absorption,
                                       double omega_a, double g, int streams);

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
