// SPDX-License-Identifier: Apache-2.0
// Molecular absorption as band transmittances: a band model fitted to LOWTRAN 7
// (data/atmosphere/gas_band_model.csv; how it was fitted: docs/physics.md), three
// absorber groups each with T(u) = exp(−τ₁ u^a) at every 5 cm⁻¹ (20 cm⁻¹ resolution) from
// 0.28 to 14.3 µm:
//   water  u = precipitable water along the path, cm
//   ozone  u = ozone along the path, atm-cm
//   mixed  u = air masses at 1013.25 hPa (O₂, CO₂, CH₄, N₂O, CO, the N₂ and O₂ continua, trace
//          gases)
// On a spectral grid each band's transmittance is the mean of the table's transmittances over
// the band's cell (half-way to each neighbour), per group; the groups multiply. Formulas,
// data and limits: docs/physics.md ("Gas absorption").
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "glint/core/spectral.h"

namespace glint::atmosphere {

/// Slant absorber amounts of one path.
struct GasAmounts {
    double water_cm = 0.0;          ///< precipitable water, cm
    double ozone_atm_cm = 0.0;      ///< ozone, atm-cm
    double mixed_air_masses = 0.0;  ///< uniformly mixed gases, air masses at 1013.25 hPa
};

/// The band-model table.
class GasBandModel {
public:
    /// The table's path below glint's data folder.
    static constexpr const char* kRelativePath = "atmosphere/gas_band_model.csv";
    /// Absorber groups, in the order of the table's columns.
    static constexpr std::size_t kGroups = 3;

    /// Parses the text of the CSV named `file` (`#` comment lines, a header line, then
    /// `wavelength_um,wavenumber_cm1,` and τ₁, a for water, ozone and mixed gases;
    /// glint/inputs/data_tables.h reads it). Throws glint::Error (input with file:line for a
    /// malformed row, wavelengths not increasing, negative τ₁ or an exponent outside (0, 2],
    /// fewer than 2 rows).
    static GasBandModel from_csv(const std::string& text, const std::string& file);

    /// Row wavelengths, µm, increasing.
    std::span<const double> wavelengths_um() const noexcept { return m_wavelengths_um; }
    /// Transmittance of group `group` at row `row` for amount `amount` (≥ 0).
    double transmittance(std::size_t group, std::size_t row, double amount) const noexcept;

private:
    std::vector<double> m_wavelengths_um;
    std::vector<double> m_tau1[kGroups];
    std::vector<double> m_exponent[kGroups];
};

/// The band model on one spectral grid: per band and group, the band-mean transmittance
/// tabulated against the logarithm of the amount, so that a query costs a few operations per
/// band. Immutable after construction; queries are thread-safe.
class GasTransmittance {
public:
    /// Amount nodes: kNodesPerDecade per decade from kMinAmount to kMaxAmount (in the group's
    /// unit). Below kMinAmount the band's optical depth falls linearly to 0; above kMaxAmount
    /// the transmittance stays at its last node.
    static constexpr double kMinAmount = 1e-5;
    static constexpr double kMaxAmount = 1e3;
    static constexpr int kNodesPerDecade = 8;

    GasTransmittance(const GasBandModel& table, const SpectralGrid& grid);

    /// Number of bands.
    std::size_t bands() const noexcept { return m_bands; }
    /// Writes the transmittance of every band for `amounts` into `out` (size bands()).
    void transmittance(const GasAmounts& amounts, std::span<double> out) const noexcept;
    std::vector<double> transmittance(const GasAmounts& amounts) const;
    /// ln of transmittance(), without the exponential (for callers that add it to an
    /// optical depth they exponentiate anyway).
    void log_transmittance(const GasAmounts& amounts, std::span<double> out) const noexcept;

private:
    std::size_t m_bands = 0;
    std::size_t m_nodes = 0;
    /// [group][band][node]: ln T of the band at the node's amount.
    std::vector<double> m_log_t[GasBandModel::kGroups];
};

}  // namespace glint::atmosphere
