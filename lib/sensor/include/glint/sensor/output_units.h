// SPDX-License-Identifier: Apache-2.0
// Output units of the simple and raw capture methods ("Output Units" and its Table 1 in the
// DIRSIG5 BasicPlatform manual, docs/references.md): from the at-aperture spectral radiance
// L(λ) in W/(cm² sr µm) on the focal plane's bandpass grid to one value per channel in the
// units the <imagefile> and the instrument ask for, with the ENVI `data units` string that
// says exactly what the numbers are.
//
// Per channel c with response R_c(λ), gain g_c and bias b_c, on the bandpass grid (trapezoid
// weights Δ_b: Σ_b Δ_b f_b = integrate_trapezoid(grid, f), exact for piecewise-linear f):
//   S_c = g_c · k_area · k_aperture · k_time · Σ_b Δ_b R_c(λ_b) k_flux(λ_b) L(λ_b) / N_c + b_c
// with
//   k_flux   = 1 (watts), 1e3 (milliwatts), 1e6 (microwatts), λ/(h c) (photonspersecond and
//              electronspersecond: photons/s per watt at λ; for electrons R_c is the QE);
//   k_area   = 1 (cm2) or 1e4 (m2: per m² = 10⁴ × per cm²);
//   k_aperture = 1/G# (sr) when the instrument defines an aperture (focal length and
//              aperture diameter; G# = (1 + 4 F#²)/(τ π)), turning radiance into focal-plane
//              irradiance; else 1;
//   k_time   = the integration time (s) when temporal integration is on (time > 0), turning
//              rates into energies or counts; else 1;
//   N_c      = ∫ R_c dλ (µm) when the channel is normalized, else 1 (per µm comes back).
// The bias is added in the output units. docs/units.md reproduces Table 1 with these strings
// (section "Output units (Table 1)", all 80 combinations; output_units_docs_test.cpp checks it).
//
// Raw capture ("Raw Capture Method" in the manual): no spectral integration — one output band
// per bandpass sample b, S_b = k_area · k_aperture · k_time · k_flux(λ_b) L(λ_b), per µm like a
// normalized channel ("Watts/(cm2 sr um)"), the channels (if any) unused; ENVI wavelength the
// sample's, fwhm the grid spacing around it, band names its wavelength ("0.5500 um").
//
// Data units grammar: <flux>/<denominator>, with <flux> Watts, Milliwatts, Microwatts,
// Photons/s, Electrons/s (Joules, Millijoules, Microjoules, Photons, Electrons with temporal
// integration) and <denominator> the area (cm2 or m2), then "sr" without an aperture, then "um"
// when normalized, in parentheses when more than one term: "Photons/s/(cm2 sr um)", "Joules/m2".
//
// ENVI wavelength and fwhm per channel shape: gaussian: centre, FWHM = width; tophat: centre,
// FWHM = width (the full width of the box); triangle: centre, FWHM = width / 2 (half of the full
// base width); tabulated: from the table itself (piecewise linear, independent of the grid): the
// response-weighted mean ∫λR dλ / ∫R dλ, and the distance between the outermost half-peak
// crossings (linear interpolation between table points; a table end at or above half the peak
// counts as a crossing).
//
// clang-format off
// | parameter read (see glint/model/*.h) | type | unit | default |
// |---|---|---|---|
// | imagefile@fluxunits | watts, milliwatts, microwatts, photonspersecond, electronspersecond | - | watts |
// | imagefile@areaunits | cm2, m2 | - | cm2 |
// | temporalintegration/time | number >= 0 (> 0: temporal integration on) | s | 0 |
// | properties/focallength, aperturediameter, aperturethroughput | numbers (both lengths: aperture defined) | mm, m, - | none, none, 1 |
// | channel@normalize, @gain, @bias; center, width or entries | bool, number, number (output units) | -, -, output units | false, 1, 0 |
// clang-format on
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "glint/core/spectral.h"
#include "glint/model/capture.h"
#include "glint/model/instrument.h"

namespace glint::sensor {

/// What the output values are, for the header and the docs.
struct UnitsDescription {
    bool aperture = false;              ///< divided by G#: irradiance at the focal plane
    bool temporal_integration = false;  ///< multiplied by the integration time
    bool normalized = false;            ///< every channel normalized (mixed: see data_units)
    double g_number_per_sr = 0.0;       ///< when aperture
    double integration_time_s = 0.0;    ///< when temporal_integration
    /// The ENVI `data units` string, following Table 1's spelling: e.g. "Watts/(cm2 sr)",
    /// "Watts/(cm2 sr um)", "Watts/cm2", "Joules/(cm2 sr)", "Photons/s/(cm2 sr)",
    /// "Photons/cm2", "Milliwatts/(m2 sr)", "Electrons/s/(cm2 sr)". When some channels are
    /// normalized and others not, the string of the first channel, and per_channel_units
    /// holds each channel's. (No channels: the unnormalized string.)
    std::string data_units;
    /// Each channel's data units string when the channels differ (mixed normalization);
    /// empty when every channel has `data_units`.
    std::vector<std::string> per_channel_units;
};

/// The ENVI `data units` string for one combination of options (the grammar above), e.g.
/// (watts, cm2, no aperture, no temporal integration, not normalized) → "Watts/(cm2 sr)".
std::string data_units_string(model::FluxUnits flux, model::AreaUnits area, bool aperture,
                              bool temporal_integration, bool normalized);

/// The linear map from a spectral radiance vector to the channel values.
class OutputUnits {
public:
    /// Builds the map for `method` (its spectral response's channels on `grid`, the
    /// <imagefile>'s fluxunits/areaunits, its temporal integration) and the instrument's
    /// aperture. Throws glint::Error (input, at the channel) for a channel whose response
    /// integrates to 0 over the grid when normalized, or with no response on the grid.
    OutputUnits(const model::CaptureMethod& method, const model::InstrumentProperties& properties,
                const SpectralGrid& grid);

    /// Number of channels (output bands).
    std::size_t channels() const noexcept { return m_channels; }
    /// Number of bands of the input radiance.
    std::size_t bands() const noexcept { return m_bands; }
    /// Writes one value per channel to `out` from `radiance_w_per_cm2_sr_um` (bands()
    /// values; `out` holds channels() values). Allocates nothing; throws glint::Error
    /// (internal) when a size differs.
    void apply(std::span<const double> radiance_w_per_cm2_sr_um, std::span<double> out) const;
    /// apply() for a radiance that is 0 outside `bands` (ascending band indices; empty: any
    /// band may be non-zero): reads only those bands, and gives apply()'s bits.
    void apply(std::span<const double> radiance_w_per_cm2_sr_um,
               std::span<const std::uint32_t> bands, std::span<double> out) const;
    /// The weight of band b in channel c (everything but the bias).
    double weight(std::size_t channel, std::size_t band) const noexcept {
        const BandRange r = m_support[channel];
        return band >= r.first && band - r.first < r.count
                   ? m_weights[m_offset[channel] + band - r.first]
                   : 0.0;
    }
    /// The bands channel c weighs: from its first to its last band with a non-zero weight
    /// (count 0 when it weighs none).
    BandRange support(std::size_t channel) const noexcept { return m_support[channel]; }
    /// Channel c's value from the radiance of bands first_band, first_band + 1, … (a range
    /// that holds support(c); the value equals apply()'s for the same radiance on those
    /// bands). Allocates nothing; throws glint::Error (internal) for a range that does not.
    double channel_value(std::size_t channel, std::size_t first_band,
                         std::span<const double> radiance_w_per_cm2_sr_um) const;
    /// The bias of channel c, in the output units.
    double bias(std::size_t channel) const noexcept { return m_bias[channel]; }
    /// What the values are.
    const UnitsDescription& description() const noexcept { return m_description; }

    /// Each channel's centre wavelength (µm; for tabulated channels the response-weighted
    /// mean) and FWHM (µm; tabulated: the width of the response above half its peak), for
    /// the ENVI `wavelength` and `fwhm` keys.
    const std::vector<double>& centers_um() const noexcept { return m_centers_um; }
    const std::vector<double>& fwhm_um() const noexcept { return m_fwhm_um; }
    /// Each output band's name: the channel's, or a raw band's wavelength ("0.5500 um").
    const std::vector<std::string>& band_names() const noexcept { return m_band_names; }

private:
    std::size_t m_channels = 0;
    std::size_t m_bands = 0;
    /// Each channel's weights over its support, one channel after the other (m_offset): a
    /// channel weighs a few dozen bands of a hyperspectral bandpass, a raw band one.
    std::vector<double> m_weights;
    std::vector<std::size_t> m_offset;  ///< per channel, where its weights start
    /// The same non-zero weights by band (m_band_start[b] … m_band_start[b + 1] − 1: the
    /// channels band b feeds, ascending), so apply() adds each band into every channel it
    /// feeds at once — each channel still sums its bands in band order, but the channels'
    /// sums proceed side by side instead of one after the other.
    std::vector<std::size_t> m_band_start;
    std::vector<std::uint32_t> m_band_channel;
    std::vector<double> m_band_weight;
    /// Fills the by-band copy from the rows.
    void index_by_band();
    std::vector<double> m_bias;
    std::vector<double> m_centers_um;
    std::vector<double> m_fwhm_um;
    std::vector<std::string> m_band_names;
    std::vector<BandRange> m_support;  ///< per channel, found once when the map is built
    UnitsDescription m_description;

    /// Appends channel c's weights (`row`: one per band; c = the channels stored so far): its
    /// support, from its first to its last non-zero weight.
    void add_row(std::span<const double> row);

    /// The raw capture's map (one band per grid sample).
    void make_raw(const model::ImageFile& file, const SpectralGrid& grid, double k_common);
};

}  // namespace glint::sensor
