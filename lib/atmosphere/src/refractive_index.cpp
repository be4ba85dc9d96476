// SPDX-License-Identifier: Apache-2.0
// The refractive index of air (glint/atmosphere/refraction.h): Ciddor's refractivity of moist
// air and the refractivity profile over a table of levels; the ray tracer through them is
// refraction.cpp.
//
// Ciddor (Applied Optics 35, 1996, 1566–1573, section 3 and appendix), σ = 1/λ in µm⁻¹:
//   (n_as − 1)·1e8 = k1/(k0 − σ²) + k3/(k2 − σ²)           dry air, 15 °C, 101325 Pa, 450 ppm CO2
//   n_axs − 1 = (n_as − 1)(1 + 0.534e-6 (x_c − 450))          CO2 of x_c ppm
//   (n_ws − 1)·1e8 = 1.022 (w0 + w1 σ² + w2 σ⁴ + w3 σ⁶)        water vapour, 20 °C, 1333 Pa
//   Z = 1 − (p/T)(a0 + a1 t + a2 t² + (b0 + b1 t) x_w + (c0 + c1 t) x_w²) + (p/T)²(d + e x_w²)
//   ρ_a = p M_a (1 − x_w)/(Z R T),  ρ_w = p M_w x_w/(Z R T)
//   n − 1 = (ρ_a/ρ_axs)(n_axs − 1) + (ρ_w/ρ_ws)(n_ws − 1)
// with p in Pa, T in K, t in °C; the molar masses and R cancel in the density ratios.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "glint/atmosphere/refraction.h"
#include "glint/core/error.h"
#include "glint/core/text.h"

namespace glint::atmosphere {
namespace refraction_detail {
namespace {

/// Ciddor's dispersion of standard dry air, µm⁻² (his eq. 1, from Peck & Reeder 1972).
constexpr double kK0 = 238.0185;
constexpr double kK1 = 5792105.0;
constexpr double kK2 = 57.362;
constexpr double kK3 = 167917.0;
/// Ciddor's dispersion of water vapour (his eq. 3) and its correction factor.
constexpr double kW0 = 295.235;
constexpr double kW1 = 2.6422;
constexpr double kW2 = -0.032380;
constexpr double kW3 = 0.004028;
constexpr double kWaterCorrection = 1.022;
/// The BIPM compressibility of moist air (Ciddor's appendix, after Davis 1992).
constexpr double kA0 = 1.58123e-6;  // K/Pa
constexpr double kA1 = -2.9331e-8;  // 1/Pa
constexpr double kA2 = 1.1043e-10;  // 1/(K Pa)
constexpr double kB0 = 5.707e-6;    // K/Pa
constexpr double kB1 = -2.051e-8;   // 1/Pa
constexpr double kC0 = 1.9898e-4;   // K/Pa
constexpr double kC1 = -2.376e-6;   // 1/Pa
constexpr double kD = 1.83e-11;     // K²/Pa²
constexpr double kE = -0.765e-8;    // K²/Pa²
/// The reference states of the two dispersion formulas.
constexpr double kDryReferencePa = 101325.0;
constexpr double kDryReferenceK = 288.15;
constexpr double kVapourReferencePa = 1333.0;
constexpr double kVapourReferenceK = 293.15;
/// The specific gas constant of water vapour, J/(kg K).
constexpr double kWaterVapourGasConstant = 461.5;
/// The shortest wavelength accepted, µm (the dry-air dispersion's pole lies at 0.132 µm).
constexpr double kMinWavelengthUm = 0.2;

/// The compressibility Z of moist air at `pressure_pa`, `temperature_k`, water mole fraction
/// `x_w`.
double compressibility(double pressure_pa, double temperature_k, double x_w) {
    const double t = temperature_k - 273.15;
    const double pt = pressure_pa / temperature_k;
    return 1.0 -
           pt *
               (kA0 + kA1 * t + kA2 * t * t + (kB0 + kB1 * t) * x_w + (kC0 + kC1 * t) * x_w * x_w) +
           pt * pt * (kD + kE * x_w * x_w);
}

/// The table of `profile`, or an input error for a table without levels.
std::span<const model::AtmosphereLevel> levels_of(const model::StandardAtmosphereProfile& profile) {
    if (profile.levels.size() < 2) {
        throw input_error(std::string("refraction needs an atmosphere profile with levels, and '") +
                          profile.name + "' has none");
    }
    return profile.levels;
}

}  // namespace
}  // namespace refraction_detail

// ---- Ciddor's refractivity ----------------------------------------------------------------

double air_refractivity(double wavelength_um, double pressure_hpa, double temperature_k,
                        double water_vapour_pressure_hpa, double co2_ppm) {
    using namespace refraction_detail;
    if (!(wavelength_um >= kMinWavelengthUm) || !std::isfinite(wavelength_um)) {
        throw input_error(
            "air refractivity: the wavelength must be at least 0.2 µm (Ciddor's dispersion has a "
            "pole at 0.132 µm), got " +
            format_ten_digits(wavelength_um) + " µm");
    }
    if (!(pressure_hpa >= 0.0) || !std::isfinite(pressure_hpa)) {
        throw input_error("air refractivity: the pressure must be >= 0 hPa, got " +
                          format_ten_digits(pressure_hpa) + " hPa");
    }
    if (!(temperature_k > 0.0) || !std::isfinite(temperature_k)) {
        throw input_error("air refractivity: the temperature must be > 0 K, got " +
                          format_ten_digits(temperature_k) + " K");
    }
    if (!(water_vapour_pressure_hpa >= 0.0 && water_vapour_pressure_hpa <= pressure_hpa)) {
        throw input_error(
            "air refractivity: the water-vapour pressure must lie in [0, pressure] = [0, " +
            format_ten_digits(pressure_hpa) + "] hPa, got " +
            format_ten_digits(water_vapour_pressure_hpa) + " hPa");
    }
    if (!(co2_ppm >= 0.0 && co2_ppm <= 1e6)) {
        throw input_error("air refractivity: the CO2 fraction must lie in [0, 1e6] ppm, got " +
                          format_ten_digits(co2_ppm) + " ppm");
    }
    const double s = 1.0 / (wavelength_um * wavelength_um);  // σ², µm⁻²
    const double n_as = 1e-8 * (kK1 / (kK0 - s) + kK3 / (kK2 - s));
    const double n_axs = n_as * (1.0 + 0.534e-6 * (co2_ppm - 450.0));
    const double n_ws = 1e-8 * kWaterCorrection * (kW0 + s * (kW1 + s * (kW2 + s * kW3)));
    const double p = 100.0 * pressure_hpa;
    if (p == 0.0) return 0.0;
    const double x_w = 100.0 * water_vapour_pressure_hpa / p;
    const double z = compressibility(p, temperature_k, x_w);
    const double z_axs = compressibility(kDryReferencePa, kDryReferenceK, 0.0);
    const double z_ws = compressibility(kVapourReferencePa, kVapourReferenceK, 1.0);
    const double per_zt = p / (z * temperature_k);
    const double dry_ratio = per_zt * (1.0 - x_w) * z_axs * kDryReferenceK / kDryReferencePa;
    const double vapour_ratio = per_zt * x_w * z_ws * kVapourReferenceK / kVapourReferencePa;
    return dry_ratio * n_axs + vapour_ratio * n_ws;
}

// ---- The profile ---------------------------------------------------------------------------

RefractiveProfile::RefractiveProfile(const model::StandardAtmosphereProfile& profile,
                                     double wavelength_um, double co2_ppm)
    : RefractiveProfile(refraction_detail::levels_of(profile), wavelength_um, co2_ppm) {}

RefractiveProfile::RefractiveProfile(std::span<const model::AtmosphereLevel> levels,
                                     double wavelength_um, double co2_ppm) {
    using namespace refraction_detail;
    if (levels.size() < 2) {
        throw input_error("refractive profile: needs at least 2 levels, got " +
                          std::to_string(levels.size()));
    }
    std::vector<double> altitudes;
    std::vector<double> refractivity;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const model::AtmosphereLevel& level = levels[i];
        const std::string where = "refractive profile: level " + std::to_string(i + 1) + " (at " +
                                  format_ten_digits(level.altitude_km) + " km): ";
        if (!std::isfinite(level.altitude_km) ||
            (i > 0 && !(level.altitude_km > levels[i - 1].altitude_km))) {
            throw input_error(where + "the altitudes must be finite and increase");
        }
        if (!(level.pressure_hpa >= 0.0) || !std::isfinite(level.pressure_hpa)) {
            throw input_error(where + "the pressure must be >= 0 hPa, got " +
                              format_ten_digits(level.pressure_hpa));
        }
        if (!(level.temperature_k > 0.0) || !std::isfinite(level.temperature_k)) {
            throw input_error(where + "the temperature must be > 0 K, got " +
                              format_ten_digits(level.temperature_k));
        }
        if (!(level.water_g_per_m3 >= 0.0) || !std::isfinite(level.water_g_per_m3)) {
            throw input_error(where + "the water-vapour density must be >= 0 g/m3, got " +
                              format_ten_digits(level.water_g_per_m3));
        }
        // e = ρ_w R_v T: g/m³ → kg/m³, Pa → hPa.
        const double vapour_hpa = std::min(
            level.water_g_per_m3 * 1e-3 * kWaterVapourGasConstant * level.temperature_k / 100.0,
            level.pressure_hpa);
        altitudes.push_back(1000.0 * level.altitude_km);
        refractivity.push_back(air_refractivity(wavelength_um, level.pressure_hpa,
                                                level.temperature_k, vapour_hpa, co2_ppm));
    }
    set_levels(std::move(altitudes), std::move(refractivity));
    m_wavelength_um = wavelength_um;
}

RefractiveProfile RefractiveProfile::from_refractivity(std::span<const double> altitudes_m,
                                                       std::span<const double> refractivity) {
    if (altitudes_m.size() != refractivity.size() || altitudes_m.size() < 2) {
        throw input_error(
            "refractive profile: needs at least 2 altitudes and as many "
            "refractivities, got " +
            std::to_string(altitudes_m.size()) + " and " + std::to_string(refractivity.size()));
    }
    for (std::size_t i = 0; i < altitudes_m.size(); ++i) {
        if (!std::isfinite(altitudes_m[i]) || (i > 0 && !(altitudes_m[i] > altitudes_m[i - 1]))) {
            throw input_error(
                "refractive profile: the altitudes must be finite and increase, got " +
                format_ten_digits(altitudes_m[i]) + " m at level " + std::to_string(i + 1));
        }
        if (!(refractivity[i] >= 0.0) || !std::isfinite(refractivity[i])) {
            throw input_error("refractive profile: n - 1 must be finite and >= 0, got " +
                              format_ten_digits(refractivity[i]) + " at level " +
                              std::to_string(i + 1));
        }
    }
    RefractiveProfile profile;
    profile.set_levels({altitudes_m.begin(), altitudes_m.end()},
                       {refractivity.begin(), refractivity.end()});
    return profile;
}

void RefractiveProfile::set_levels(std::vector<double> altitudes_m,
                                   std::vector<double> refractivity) {
    m_altitudes_m = std::move(altitudes_m);
    m_refractivity = std::move(refractivity);
    const std::size_t segments = m_altitudes_m.size() - 1;
    m_slope_per_m.assign(segments, 0.0);
    m_linear.assign(segments, 0);
    for (std::size_t k = 0; k < segments; ++k) {
        const double dh = m_altitudes_m[k + 1] - m_altitudes_m[k];
        const double lower = m_refractivity[k];
        const double upper = m_refractivity[k + 1];
        if (lower > 0.0 && upper > 0.0) {
            m_slope_per_m[k] = std::log(upper / lower) / dh;
        } else {
            m_linear[k] = 1;
            m_slope_per_m[k] = (upper - lower) / dh;
        }
    }
}

std::size_t RefractiveProfile::segment_of(double altitude_m) const noexcept {
    const auto above = std::upper_bound(m_altitudes_m.begin(), m_altitudes_m.end(), altitude_m);
    const std::size_t index = above == m_altitudes_m.begin()
                                  ? 0
                                  : static_cast<std::size_t>(above - m_altitudes_m.begin()) - 1;
    return std::min(index, m_altitudes_m.size() - 2);
}

double RefractiveProfile::refractivity(double altitude_m) const noexcept {
    if (altitude_m > m_altitudes_m.back()) return 0.0;
    const std::size_t k = segment_of(altitude_m);
    const double dh = altitude_m - m_altitudes_m[k];
    if (m_linear[k]) return std::max(m_refractivity[k] + m_slope_per_m[k] * dh, 0.0);
    return m_refractivity[k] * std::exp(m_slope_per_m[k] * dh);
}

double RefractiveProfile::refractivity_change(double altitude_m, double rise_m) const noexcept {
    const double to_m = altitude_m + rise_m;
    const std::size_t k = segment_of(altitude_m);
    const bool same_segment = to_m <= m_altitudes_m.back() && segment_of(to_m) == k;
    if (!same_segment || m_linear[k]) return refractivity(to_m) - refractivity(altitude_m);
    return refractivity(altitude_m) * std::expm1(m_slope_per_m[k] * rise_m);
}

double RefractiveProfile::refractivity_gradient_per_m(double altitude_m) const noexcept {
    if (altitude_m >= m_altitudes_m.back()) return 0.0;
    const std::size_t k = segment_of(altitude_m);
    const double dh = altitude_m - m_altitudes_m[k];
    if (m_linear[k]) {
        return m_refractivity[k] + m_slope_per_m[k] * dh > 0.0 ? m_slope_per_m[k] : 0.0;
    }
    return m_slope_per_m[k] * m_refractivity[k] * std::exp(m_slope_per_m[k] * dh);
}

}  // namespace glint::atmosphere
