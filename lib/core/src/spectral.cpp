// SPDX-License-Identifier: Apache-2.0
// SpectralGrid, SpectralCurve, trapezoid integration, wavelength-unit names, Planck's law and
// photon conversions (docs/physics.md).
#include "glint/core/spectral.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

#include "glint/core/text.h"
#include "glint/core/units.h"

namespace glint {

namespace {

void check_wavelengths(std::span<const double> wavelengths_um, const ErrorContext& context) {
    if (wavelengths_um.empty())
        throw input_error("no wavelengths given, expected at least one", context);
    if (wavelengths_um.size() > SpectralGrid::kMaxSize) {
        throw input_error(std::to_string(wavelengths_um.size()) +
                              " wavelengths are too many, expected at most " +
                              std::to_string(SpectralGrid::kMaxSize),
                          context);
    }
    for (std::size_t i = 0; i < wavelengths_um.size(); ++i) {
        const double wl = wavelengths_um[i];
        if (!std::isfinite(wl) || wl <= 0.0) {
            throw input_error("wavelength " + std::to_string(i) + " is " + format_ten_digits(wl) +
                                  ", expected a finite value > 0 µm",
                              context);
        }
        if (i > 0 && !(wl > wavelengths_um[i - 1])) {
            throw input_error("wavelength " + std::to_string(i) + " (" + format_ten_digits(wl) +
                                  ") is not greater than wavelength " + std::to_string(i - 1) +
                                  " (" + format_ten_digits(wavelengths_um[i - 1]) +
                                  "), expected strictly increasing wavelengths",
                              context);
        }
    }
}

void check_sizes(std::size_t grid_size, std::size_t values_size, const char* what) {
    if (grid_size != values_size) {
        throw input_error(std::string(what) + " has " + std::to_string(values_size) +
                          " values, expected " + std::to_string(grid_size) +
                          " (one per grid wavelength)");
    }
}

void check_wavelength(double wavelength_um) {
    if (!std::isfinite(wavelength_um) || wavelength_um <= 0.0) {
        throw input_error("wavelength " + format_ten_digits(wavelength_um) +
                          " µm is invalid, expected > 0");
    }
}

}  // namespace

// ---- SpectralGrid ------------------------------------------------------------------------

SpectralGrid SpectralGrid::regular(double min_um, double max_um, double delta_um,
                                   const ErrorContext& context) {
    if (!std::isfinite(min_um) || !std::isfinite(max_um) || !std::isfinite(delta_um)) {
        throw input_error("spectral range (" + format_ten_digits(min_um) + ", " +
                              format_ten_digits(max_um) + ", " + format_ten_digits(delta_um) +
                              ") is invalid, expected finite values",
                          context);
    }
    if (min_um <= 0.0) {
        throw input_error(
            "minimum wavelength " + format_ten_digits(min_um) + " µm is invalid, expected > 0",
            context);
    }
    if (max_um < min_um) {
        throw input_error("maximum wavelength " + format_ten_digits(max_um) +
                              " µm is below the minimum " + format_ten_digits(min_um) +
                              " µm, expected minimum <= maximum",
                          context);
    }
    if (delta_um <= 0.0) {
        throw input_error(
            "wavelength step " + format_ten_digits(delta_um) + " µm is invalid, expected > 0",
            context);
    }
    const double steps = (max_um - min_um) / delta_um;
    if (!(steps < static_cast<double>(kMaxSize))) {
        throw input_error("spectral range (" + format_ten_digits(min_um) + ", " +
                              format_ten_digits(max_um) + ", " + format_ten_digits(delta_um) +
                              ") has too many samples, expected at most " +
                              std::to_string(kMaxSize),
                          context);
    }
    const double nearest = std::round(steps);
    const bool ends_at_max = std::fabs(steps - nearest) <= 1e-6;
    const auto step_count = static_cast<std::size_t>(ends_at_max ? nearest : std::floor(steps));
    std::vector<double> wavelengths(step_count + 1);
    for (std::size_t i = 0; i <= step_count; ++i) {
        wavelengths[i] = min_um + static_cast<double>(i) * delta_um;
    }
    if (ends_at_max && step_count > 0) wavelengths.back() = max_um;
    return SpectralGrid(std::move(wavelengths), context);
}

SpectralGrid::SpectralGrid(std::vector<double> wavelengths_um, const ErrorContext& context)
    : m_wavelengths_um(std::move(wavelengths_um)) {
    check_wavelengths(m_wavelengths_um, context);
}

double SpectralGrid::wavelength_um(std::size_t index) const {
    if (index >= m_wavelengths_um.size()) {
        throw internal_error("spectral grid index " + std::to_string(index) +
                             " is out of range, the grid has " +
                             std::to_string(m_wavelengths_um.size()) + " samples");
    }
    return m_wavelengths_um[index];
}

// ---- SpectralCurve -----------------------------------------------------------------------

SpectralCurve::SpectralCurve(std::vector<double> wavelengths_um, std::vector<double> values,
                             const ErrorContext& context)
    : m_wavelengths_um(std::move(wavelengths_um)), m_values(std::move(values)) {
    if (m_wavelengths_um.size() != m_values.size()) {
        throw input_error("spectral curve has " + std::to_string(m_wavelengths_um.size()) +
                              " wavelengths and " + std::to_string(m_values.size()) +
                              " values, expected as many values as wavelengths",
                          context);
    }
    check_wavelengths(m_wavelengths_um, context);
    for (std::size_t i = 0; i < m_values.size(); ++i) {
        if (!std::isfinite(m_values[i])) {
            throw input_error("spectral curve value " + std::to_string(i) + " is " +
                                  format_ten_digits(m_values[i]) + ", expected a finite number",
                              context);
        }
    }
}

double SpectralCurve::value_at(double wavelength_um) const noexcept {
    const auto& wl = m_wavelengths_um;
    if (!(wavelength_um >= wl.front()) || !(wavelength_um <= wl.back())) return 0.0;
    // First defining wavelength >= the query; the query lies in (wl[i-1], wl[i]].
    const auto it = std::lower_bound(wl.begin(), wl.end(), wavelength_um);
    const auto i = static_cast<std::size_t>(it - wl.begin());
    if (wl[i] == wavelength_um) return m_values[i];
    const double t = (wavelength_um - wl[i - 1]) / (wl[i] - wl[i - 1]);
    return m_values[i - 1] + t * (m_values[i] - m_values[i - 1]);
}

std::vector<double> SpectralCurve::resample(const SpectralGrid& grid) const {
    std::vector<double> out(grid.size());
    const auto wavelengths = grid.wavelengths_um();
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = value_at(wavelengths[i]);
    return out;
}

// ---- Integration -------------------------------------------------------------------------

double integrate_trapezoid(const SpectralGrid& grid, std::span<const double> values) {
    check_sizes(grid.size(), values.size(), "integrand");
    const auto wl = grid.wavelengths_um();
    double sum = 0.0;
    for (std::size_t i = 1; i < wl.size(); ++i) {
        sum += 0.5 * (wl[i] - wl[i - 1]) * (values[i] + values[i - 1]);
    }
    return sum;
}

double integrate_trapezoid(const SpectralGrid& grid, std::span<const double> values,
                           std::span<const double> weights) {
    check_sizes(grid.size(), values.size(), "integrand");
    check_sizes(grid.size(), weights.size(), "weight");
    const auto wl = grid.wavelengths_um();
    double sum = 0.0;
    for (std::size_t i = 1; i < wl.size(); ++i) {
        sum +=
            0.5 * (wl[i] - wl[i - 1]) * (values[i] * weights[i] + values[i - 1] * weights[i - 1]);
    }
    return sum;
}

// ---- Units -------------------------------------------------------------------------------

double wavelength_unit_to_um(std::string_view unit_name, const ErrorContext& context) {
    std::string_view trimmed = unit_name;
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!trimmed.empty() && blank(trimmed.front())) trimmed.remove_prefix(1);
    while (!trimmed.empty() && blank(trimmed.back())) trimmed.remove_suffix(1);
    std::string lower(trimmed);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));

    if (lower == "micrometers" || lower == "micrometer" || lower == "microns" ||
        lower == "micron" || lower == "um" || lower == "\xC2\xB5m" || lower == "\xCE\xBCm") {
        return 1.0;  // "µm" with MICRO SIGN (U+00B5) or GREEK SMALL LETTER MU (U+03BC)
    }
    if (lower == "nanometers" || lower == "nanometer" || lower == "nm") return 1e-3;
    throw input_error("unknown wavelength unit '" + std::string(unit_name) +
                          "', expected micrometers, microns, um, nanometers or nm",
                      context);
}

// ---- Planck and photons ------------------------------------------------------------------

double planck_radiance_w_per_m2_sr_um(double wavelength_um, double temperature_k) {
    check_wavelength(wavelength_um);
    if (!std::isfinite(temperature_k) || temperature_k < 0.0) {
        throw input_error("temperature " + format_ten_digits(temperature_k) +
                          " K is invalid, expected >= 0");
    }
    if (temperature_k == 0.0) return 0.0;
    // With λ in µm: B = c1 · 1e24 / λ⁵ / (exp(c2 / (λ T)) − 1) in W/(m² sr µm), where
    // c1 = 2hc² in W m²/sr (λ⁵ in m⁵ = 1e-30 λ⁵ in µm⁵, and 1e-6 to go from per m to per µm).
    const double x = kPlanckC2UmK / (wavelength_um * temperature_k);
    if (x > 700.0) return 0.0;  // below 1e-270: avoids inf/inf when λ⁵ underflows
    const double denominator = std::expm1(x);
    const double wl2 = wavelength_um * wavelength_um;
    return kPlanckC1WM2PerSr * 1e24 / (wl2 * wl2 * wavelength_um) / denominator;
}

double planck_radiance_w_per_cm2_sr_um(double wavelength_um, double temperature_k) {
    return per_m2_to_per_cm2(planck_radiance_w_per_m2_sr_um(wavelength_um, temperature_k));
}

double photon_energy_j(double wavelength_um) {
    check_wavelength(wavelength_um);
    return kPlanckJS * kSpeedOfLightMPerS / um_to_m(wavelength_um);
}

double photons_per_joule(double wavelength_um) {
    check_wavelength(wavelength_um);
    return um_to_m(wavelength_um) / (kPlanckJS * kSpeedOfLightMPerS);
}

std::vector<double> watts_to_photons_per_s(const SpectralGrid& grid,
                                           std::span<const double> values_w) {
    check_sizes(grid.size(), values_w.size(), "spectrum");
    std::vector<double> out(values_w.size());
    const auto wl = grid.wavelengths_um();
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = values_w[i] * photons_per_joule(wl[i]);
    return out;
}

double gaussian_fwhm(double wavelength_um, double center_um, double fwhm_um) {
    if (!std::isfinite(fwhm_um) || fwhm_um <= 0.0) {
        throw input_error("Gaussian FWHM " + format_ten_digits(fwhm_um) +
                          " µm is invalid, expected > 0");
    }
    const double d = (wavelength_um - center_um) / fwhm_um;
    return std::exp(-4.0 * std::numbers::ln2 * d * d);
}

}  // namespace glint
