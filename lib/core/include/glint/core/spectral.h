// SPDX-License-Identifier: Apache-2.0
// Spectral grids and curves: wavelength grids in µm, piecewise-linear spectral curves,
// trapezoid integration over a grid, wavelength-unit names, Planck's law and photon
// conversions. Formulas and units are in docs/physics.md and docs/units.md.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "glint/core/error.h"

namespace glint {

/// A strictly increasing set of positive wavelengths in µm at which spectra are sampled.
class SpectralGrid {
public:
    /// The largest number of samples a grid may have (guards allocations from bad input).
    static constexpr std::size_t kMaxSize = 100'000'000;

    /// A regular grid min_um, min_um + delta_um, ... up to max_um. The step count
    /// (max_um - min_um) / delta_um is rounded to the nearest integer when it lies within
    /// 1e-6 of one (so (0.4, 0.7, 0.005) has 61 points and ends exactly at 0.7), otherwise
    /// truncated (the grid then ends below max_um). Throws glint::Error (input, with
    /// `context`) unless the values are finite, 0 < min_um <= max_um and delta_um > 0.
    static SpectralGrid regular(double min_um, double max_um, double delta_um,
                                const ErrorContext& context = {});

    /// A grid of arbitrary wavelengths. Throws glint::Error (input, with `context`) unless
    /// there is at least one, all are finite and positive, and they strictly increase.
    explicit SpectralGrid(std::vector<double> wavelengths_um, const ErrorContext& context = {});

    /// The number of samples.
    std::size_t size() const noexcept { return m_wavelengths_um.size(); }
    /// Wavelength of sample `index` in µm; throws glint::Error (internal) if out of range.
    double wavelength_um(std::size_t index) const;
    /// All wavelengths in µm, increasing.
    std::span<const double> wavelengths_um() const noexcept { return m_wavelengths_um; }
    /// The first (shortest) wavelength in µm.
    double min_um() const noexcept { return m_wavelengths_um.front(); }
    /// The last (longest) wavelength in µm.
    double max_um() const noexcept { return m_wavelengths_um.back(); }

private:
    std::vector<double> m_wavelengths_um;
};

/// A contiguous range of a grid's samples (bands): first, first + 1, …, first + count − 1.
struct BandRange {
    std::size_t first = 0;
    std::size_t count = 0;
};

/// A spectral quantity known at increasing wavelengths (µm) and linearly interpolated
/// between them (e.g. a reflectance, a filter transmission, a solar spectrum).
class SpectralCurve {
public:
    /// Throws glint::Error (input, with `context`) unless the two vectors have the same
    /// non-zero length, the wavelengths are finite, positive and strictly increasing, and
    /// the values are finite.
    SpectralCurve(std::vector<double> wavelengths_um, std::vector<double> values,
                  const ErrorContext& context = {});

    /// The value at `wavelength_um`, linearly interpolated. Outside [first, last]
    /// wavelength the curve is 0 (a filter passes nothing, a spectrum has no energy where
    /// it is not defined); a one-point curve is non-zero only at its own wavelength.
    double value_at(double wavelength_um) const noexcept;
    /// The curve sampled at every wavelength of `grid` (value_at, so 0 outside).
    std::vector<double> resample(const SpectralGrid& grid) const;

    /// The defining wavelengths in µm.
    std::span<const double> wavelengths_um() const noexcept { return m_wavelengths_um; }
    /// The defining values.
    std::span<const double> values() const noexcept { return m_values; }

private:
    std::vector<double> m_wavelengths_um;
    std::vector<double> m_values;
};

/// ∫ f dλ over the grid (λ in µm) by the trapezoid rule, `values[i]` = f(grid λᵢ); exact
/// for piecewise-linear f. A one-point grid integrates to 0. Throws glint::Error (input)
/// if the sizes differ.
double integrate_trapezoid(const SpectralGrid& grid, std::span<const double> values);

/// ∫ f·w dλ over the grid (λ in µm) by the trapezoid rule on the product f·w. Throws
/// glint::Error (input) if the sizes differ.
double integrate_trapezoid(const SpectralGrid& grid, std::span<const double> values,
                           std::span<const double> weights);

/// The factor that converts wavelengths in the named unit to µm: 1 for "micrometers",
/// "micrometer", "microns", "micron", "um" and "µm"; 1e-3 for "nanometers", "nanometer"
/// and "nm" (case-insensitive, surrounding blanks ignored). Throws glint::Error (input,
/// with `context`) for any other name, listing the accepted ones.
double wavelength_unit_to_um(std::string_view unit_name, const ErrorContext& context = {});

/// Planck's spectral radiance of a blackbody, B_λ(λ, T) = 2hc²/λ⁵ / (exp(hc/(λ k T)) − 1),
/// in W/(m² sr µm). Temperature 0 K gives 0. Throws glint::Error (input) unless
/// wavelength_um > 0 and temperature_k >= 0, both finite.
double planck_radiance_w_per_m2_sr_um(double wavelength_um, double temperature_k);

/// Planck's spectral radiance in the internal units W/(cm² sr µm) (1e-4 × the per-m² value).
double planck_radiance_w_per_cm2_sr_um(double wavelength_um, double temperature_k);

/// The energy of one photon, h c / λ, in J. Throws glint::Error (input) unless
/// wavelength_um is finite and > 0.
double photon_energy_j(double wavelength_um);

/// Photons per joule at the given wavelength, λ / (h c).
double photons_per_joule(double wavelength_um);

/// A spectrum in watts per unit (e.g. W/(cm² sr µm)) sampled on `grid`, converted to
/// photons/s per the same unit (e.g. photons/(s cm² sr µm)). Throws glint::Error (input)
/// if the sizes differ.
std::vector<double> watts_to_photons_per_s(const SpectralGrid& grid,
                                           std::span<const double> values_w);

/// A Gaussian of peak 1 at center_um with full width at half maximum fwhm_um:
/// exp(−4 ln 2 (λ − center)² / fwhm²). Throws glint::Error (input) unless fwhm_um > 0.
double gaussian_fwhm(double wavelength_um, double center_um, double fwhm_um);

}  // namespace glint
