// SPDX-License-Identifier: Apache-2.0
// The gas-absorption band model (glint/atmosphere/gas_absorption.h): the LOWTRAN 7 fit read
// from its CSV, and its band means on a spectral grid tabulated against ln(amount).
#include "glint/atmosphere/gas_absorption.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::atmosphere {
namespace {

/// Columns: wavelength, wavenumber, then τ₁ and a of each group.
constexpr std::size_t kColumns = 2 + 2 * GasBandModel::kGroups;

/// One band's rows and their weights (summing to 1).
struct BandRows {
    std::vector<std::size_t> rows;
    std::vector<double> weights;
};

/// The rows that make up band `i` of `grid`: those inside its cell, weighted by the
/// wavelength interval each stands for; with none inside, the two rows around the band's
/// wavelength, weighted for linear interpolation; outside the table, the nearest row.
BandRows band_rows(std::span<const double> table_um, const SpectralGrid& grid, std::size_t i) {
    const std::size_t n = grid.size();
    const double wl = grid.wavelength_um(i);
    const double lo = i > 0 ? 0.5 * (grid.wavelength_um(i - 1) + wl)
                            : (n > 1 ? wl - 0.5 * (grid.wavelength_um(1) - wl) : wl);
    const double hi = i + 1 < n ? 0.5 * (wl + grid.wavelength_um(i + 1))
                                : (n > 1 ? wl + 0.5 * (wl - grid.wavelength_um(n - 2)) : wl);
    BandRows out;
    const auto first = std::lower_bound(table_um.begin(), table_um.end(), lo);
    const auto last = std::lower_bound(table_um.begin(), table_um.end(), hi);
    const std::size_t rows = table_um.size();
    if (last - first >= 2) {
        double total = 0.0;
        for (auto it = first; it != last; ++it) {
            const std::size_t j = static_cast<std::size_t>(it - table_um.begin());
            const double left = j > 0 ? table_um[j - 1] : table_um[j];
            const double right = j + 1 < rows ? table_um[j + 1] : table_um[j];
            const double w = std::max(0.5 * (right - left), 1e-12);
            out.rows.push_back(j);
            out.weights.push_back(w);
            total += w;
        }
        for (double& w : out.weights) w /= total;
        return out;
    }
    const auto above = std::lower_bound(table_um.begin(), table_um.end(), wl);
    if (above == table_um.begin() || above == table_um.end()) {
        out.rows.push_back(above == table_um.begin() ? 0 : rows - 1);
        out.weights.push_back(1.0);
        return out;
    }
    const std::size_t j = static_cast<std::size_t>(above - table_um.begin());
    const double f = (wl - table_um[j - 1]) / (table_um[j] - table_um[j - 1]);
    out.rows = {j - 1, j};
    out.weights = {1.0 - f, f};
    return out;
}

}  // namespace

GasBandModel GasBandModel::from_csv(const std::string& text, const std::string& file) {
    GasBandModel out;
    int line_number = 0;
    bool header = false;
    for (const std::string_view line : split_lines(text)) {
        ++line_number;
        if (line.empty() || line.front() == '#') continue;
        const ErrorContext where{file, line_number, {}};
        if (!header) {
            if (line.substr(0, 13) != "wavelength_um") {
                throw input_error("expected the header line wavelength_um,wavenumber_cm1,...",
                                  where);
            }
            header = true;
            continue;
        }
        const std::vector<std::string> fields = split_list(line, ',');
        std::vector<double> values;
        for (const std::string& f : fields) {
            const auto v = parse_double(f);
            if (!v || !std::isfinite(*v)) break;
            values.push_back(*v);
        }
        if (fields.size() != kColumns || values.size() != kColumns) {
            throw input_error("expected " + std::to_string(kColumns) + " numbers, found '" +
                                  std::string(line) + "'",
                              where);
        }
        if (values[0] <= 0.0 ||
            (!out.m_wavelengths_um.empty() && values[0] <= out.m_wavelengths_um.back())) {
            throw input_error("wavelengths must be > 0 and increase", where);
        }
        out.m_wavelengths_um.push_back(values[0]);
        for (std::size_t g = 0; g < kGroups; ++g) {
            const double tau1 = values[2 + 2 * g];
            const double exponent = values[3 + 2 * g];
            if (tau1 < 0.0 || exponent <= 0.0 || exponent > 2.0) {
                throw input_error("expected tau1 >= 0 and an exponent in (0, 2]", where);
            }
            out.m_tau1[g].push_back(tau1);
            out.m_exponent[g].push_back(exponent);
        }
    }
    if (out.m_wavelengths_um.size() < 2) {
        throw input_error("gas band-model table has fewer than 2 rows", ErrorContext{file, 0, {}});
    }
    return out;
}

double GasBandModel::transmittance(std::size_t group, std::size_t row,
                                   double amount) const noexcept {
    if (!(amount > 0.0)) return 1.0;
    return std::exp(-m_tau1[group][row] * std::pow(amount, m_exponent[group][row]));
}

GasTransmittance::GasTransmittance(const GasBandModel& table, const SpectralGrid& grid)
    : m_bands(grid.size()) {
    const int decades = static_cast<int>(std::lround(std::log10(kMaxAmount / kMinAmount)));
    m_nodes = static_cast<std::size_t>(decades * kNodesPerDecade + 1);
    std::vector<double> amounts(m_nodes);
    for (std::size_t k = 0; k < m_nodes; ++k) {
        amounts[k] = kMinAmount * std::pow(10.0, static_cast<double>(k) / kNodesPerDecade);
    }
    for (std::size_t g = 0; g < GasBandModel::kGroups; ++g) {
        m_log_t[g].assign(m_bands * m_nodes, 0.0);
    }
    for (std::size_t i = 0; i < m_bands; ++i) {
        const BandRows rows = band_rows(table.wavelengths_um(), grid, i);
        for (std::size_t g = 0; g < GasBandModel::kGroups; ++g) {
            double* out = &m_log_t[g][i * m_nodes];
            for (std::size_t k = 0; k < m_nodes; ++k) {
                double t = 0.0;
                for (std::size_t r = 0; r < rows.rows.size(); ++r) {
                    t += rows.weights[r] * table.transmittance(g, rows.rows[r], amounts[k]);
                }
                out[k] = std::log(std::max(t, 1e-300));
            }
        }
    }
}

void GasTransmittance::transmittance(const GasAmounts& amounts,
                                     std::span<double> out) const noexcept {
    log_transmittance(amounts, out);
    for (double& v : out) v = std::exp(v);
}

void GasTransmittance::log_transmittance(const GasAmounts& amounts,
                                         std::span<double> out) const noexcept {
    const double group_amounts[GasBandModel::kGroups] = {amounts.water_cm, amounts.ozone_atm_cm,
                                                         amounts.mixed_air_masses};
    std::fill(out.begin(), out.end(), 0.0);  // ln T, summed over the groups
    for (std::size_t g = 0; g < GasBandModel::kGroups; ++g) {
        const double u = group_amounts[g];
        if (!(u > 0.0)) continue;
        // Node position: below the first node the optical depth scales with u.
        std::size_t k = 0;
        double f = 0.0;
        double scale = 1.0;
        if (u < kMinAmount) {
            scale = u / kMinAmount;
        } else {
            const double x = std::log10(u / kMinAmount) * kNodesPerDecade;
            const double last = static_cast<double>(m_nodes - 1);
            if (x >= last) {
                k = m_nodes - 2;
                f = 1.0;
            } else {
                k = static_cast<std::size_t>(x);
                f = x - static_cast<double>(k);
            }
        }
        const std::vector<double>& table = m_log_t[g];
        for (std::size_t i = 0; i < m_bands; ++i) {
            const double* node = &table[i * m_nodes + k];
            const double log_t =
                u < kMinAmount ? node[0] * scale : (1.0 - f) * node[0] + f * node[1];
            out[i] += log_t;
        }
    }
}

std::vector<double> GasTransmittance::transmittance(const GasAmounts& amounts) const {
    std::vector<double> out(m_bands);
    transmittance(amounts, out);
    return out;
}

}  // namespace glint::atmosphere
