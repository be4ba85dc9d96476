// SPDX-License-Identifier: Apache-2.0
// The exo-atmospheric solar spectrum (glint/atmosphere/solar.h): reads the ASTM G173 CSV, converts
// nm → µm and W·m⁻²·nm⁻¹ → W·cm⁻²·µm⁻¹ (× 0.1), and joins a Planck tail at 4 µm.
#include "glint/atmosphere/solar.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::atmosphere {
namespace {

/// W·m⁻²·nm⁻¹ → W·cm⁻²·µm⁻¹: × 1000 nm/µm × 1e-4 m²/cm².
constexpr double kAstmToInternal = 0.1;

}  // namespace

SolarSpectrum SolarSpectrum::from_astm_g173(const std::string& text, const std::string& file) {
    std::vector<double> wavelengths_um;
    std::vector<double> values;
    int line_number = 0;
    for (const std::string_view line : split_lines(text)) {
        ++line_number;
        if (line_number <= 2) continue;  // title and column names
        if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
        const std::vector<std::string> fields = split_list(line, ',');
        const ErrorContext where{file, line_number, {}};
        if (fields.size() < 2) {
            throw input_error(
                "expected wavelength_nm,extraterrestrial,... found '" + std::string(line) + "'",
                where);
        }
        const auto nm = parse_double(fields[0]);
        const auto value = parse_double(fields[1]);
        if (!nm || !value || *nm <= 0.0 || *value < 0.0) {
            throw input_error("expected a wavelength > 0 nm and an irradiance >= 0, found '" +
                                  std::string(line) + "'",
                              where);
        }
        const double um = *nm * 1e-3;
        if (!wavelengths_um.empty() && um <= wavelengths_um.back()) {
            throw input_error("wavelengths must increase", where);
        }
        wavelengths_um.push_back(um);
        values.push_back(*value * kAstmToInternal);
    }
    if (wavelengths_um.size() < 2) {
        throw input_error("solar table has fewer than 2 rows", ErrorContext{file, 0, {}});
    }
    if (std::abs(wavelengths_um.back() - kTailStartUm) > 1e-3) {
        throw input_error("solar table ends at " + format_shortest(wavelengths_um.back()) +
                              " um, expected " + format_shortest(kTailStartUm) + " um",
                          ErrorContext{file, line_number, {}});
    }
    return SolarSpectrum(
        SpectralCurve(std::move(wavelengths_um), std::move(values), ErrorContext{file, 0, {}}));
}

SolarSpectrum::SolarSpectrum(SpectralCurve table_w_per_cm2_um)
    : m_table(std::move(table_w_per_cm2_um)) {
    const double last_um = m_table.wavelengths_um().back();
    const double last_value = m_table.values().back();
    if (m_table.wavelengths_um().size() < 2 || !(last_value > 0.0)) {
        throw input_error("solar table needs at least 2 rows and a last value > 0");
    }
    m_tail_scale_sr = last_value / planck_radiance_w_per_cm2_sr_um(last_um, kTailTemperatureK);
}

double SolarSpectrum::irradiance_w_per_cm2_um(double wavelength_um, double distance_au) const {
    if (!std::isfinite(distance_au) || distance_au <= 0.0) {
        throw input_error("Earth-Sun distance must be > 0 AU, got " + format_shortest(distance_au));
    }
    const double scale = 1.0 / (distance_au * distance_au);
    if (!std::isfinite(wavelength_um) || wavelength_um <= 0.0) return 0.0;
    if (wavelength_um <= m_table.wavelengths_um().back()) {
        return m_table.value_at(wavelength_um) * scale;
    }
    return m_tail_scale_sr * planck_radiance_w_per_cm2_sr_um(wavelength_um, kTailTemperatureK) *
           scale;
}

std::vector<double> SolarSpectrum::resample(const SpectralGrid& grid, double distance_au) const {
    std::vector<double> out;
    out.reserve(grid.size());
    for (double wavelength_um : grid.wavelengths_um()) {
        out.push_back(irradiance_w_per_cm2_um(wavelength_um, distance_au));
    }
    return out;
}

}  // namespace glint::atmosphere
