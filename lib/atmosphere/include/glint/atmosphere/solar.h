// SPDX-License-Identifier: Apache-2.0
// The sun's top-of-atmosphere spectral irradiance: the ASTM G173-03 extraterrestrial spectrum
// (0.28–4.0 µm, data/solar/astm_g173.csv) extended beyond 4.0 µm by a 5778 K Planck tail,
// scaled by 1/d² for the Earth–Sun distance d in AU. Internal units W/(cm² µm) (irradiance
// normal to the sun's direction).
//
// The tail is E(λ) = k · B_λ(λ, 5778 K) with k (sr) chosen so that the tail equals the ASTM
// value at 4.0 µm (continuity); k comes out near the sun's solid angle at 1 AU, π(R☉/1 AU)² ≈
// 6.8e-5 sr. Below 0.28 µm the spectrum is 0. The data folder is not known to the library:
// the caller hands in the path (e.g. `<data dir>/solar/astm_g173.csv`).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "glint/core/spectral.h"

namespace glint::atmosphere {

/// The exo-atmospheric solar spectrum.
class SolarSpectrum {
public:
    /// Temperature of the Planck tail, K.
    static constexpr double kTailTemperatureK = 5778.0;
    /// Where the table ends and the tail starts, µm.
    static constexpr double kTailStartUm = 4.0;
    /// The ASTM file's path below glint's data folder.
    static constexpr const char* kAstmRelativePath = "solar/astm_g173.csv";

    /// Parses the text of an ASTM G173 CSV named `file` (two header lines, then
    /// `wavelength_nm,extraterrestrial,global,direct` in W·m⁻²·nm⁻¹; glint/inputs/data_tables.h
    /// reads it). Throws glint::Error (input with file:line for a malformed row, fewer than 2
    /// rows, wavelengths not increasing, negative values, or a table that does not end at
    /// kTailStartUm within 1 nm).
    static SolarSpectrum from_astm_g173(const std::string& text, const std::string& file);

    /// A spectrum from a table already in µm and W/(cm² µm) (the last wavelength is where the
    /// tail starts). Throws glint::Error (input) for a bad table or a last value ≤ 0.
    explicit SolarSpectrum(SpectralCurve table_w_per_cm2_um);

    /// Spectral irradiance at `wavelength_um`, W/(cm² µm), at `distance_au` from the sun
    /// (scaled by 1/d²). Throws glint::Error (input) unless distance_au is finite and > 0.
    double irradiance_w_per_cm2_um(double wavelength_um, double distance_au = 1.0) const;

    /// irradiance_w_per_cm2_um at every wavelength of `grid` (point samples).
    std::vector<double> resample(const SpectralGrid& grid, double distance_au = 1.0) const;

    /// The tail's scale factor k in sr (E_tail = k · B_λ(λ, 5778 K)).
    double tail_scale_sr() const noexcept { return m_tail_scale_sr; }
    /// The tabulated part, µm and W/(cm² µm) at 1 AU.
    const SpectralCurve& table() const noexcept { return m_table; }

private:
    SpectralCurve m_table;
    double m_tail_scale_sr = 0.0;
};

}  // namespace glint::atmosphere
