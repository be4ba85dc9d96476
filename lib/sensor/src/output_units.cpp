// SPDX-License-Identifier: Apache-2.0
// The output-units map of the simple and raw capture methods: per-channel band weights
// (trapezoid weight × response × flux, area, aperture and time factors × gain / ∫R), the
// bias and the ENVI `data units` strings (Table 1's spelling); the channels' ENVI centres and
// FWHMs are the spectral response's (model::channel_center_um, channel_fwhm_um). Formulas and
// conventions are in output_units.h and docs/units.md.
#include "glint/sensor/output_units.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "glint/core/error.h"
#include "glint/core/units.h"
#include "glint/model/derived.h"

namespace glint::sensor {
namespace {

std::string number_text(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

/// A channel's band weights below this fraction of its largest are dropped (2⁻⁶⁴).
constexpr double kNegligibleWeight = 0x1p-64;

/// Trapezoid weights Δ_b (µm) of the grid: Σ_b Δ_b f_b = Σ_i ½ (λ_i − λ_{i−1}) (f_i + f_{i−1}),
/// i.e. integrate_trapezoid(grid, f) up to rounding. Δ_0 = ½(λ_1 − λ_0), Δ_last =
/// ½(λ_last − λ_{last−1}), inner Δ_b = ½(λ_b − λ_{b−1}) + ½(λ_{b+1} − λ_b) (each half-interval
/// rounded as integrate_trapezoid rounds it). A one-point grid has Δ = 0.
std::vector<double> trapezoid_weights_um(const SpectralGrid& grid) {
    const std::span<const double> wl = grid.wavelengths_um();
    std::vector<double> weights(wl.size(), 0.0);
    for (std::size_t i = 1; i < wl.size(); ++i) {
        const double half_um = 0.5 * (wl[i] - wl[i - 1]);
        weights[i - 1] += half_um;
        weights[i] += half_um;
    }
    return weights;
}

/// The flux factor at `wavelength_um`: output flux units per watt.
double flux_factor(model::FluxUnits flux, double wavelength_um) {
    switch (flux) {
        case model::FluxUnits::watts:
            return 1.0;
        case model::FluxUnits::milliwatts:
            return w_to_mw(1.0);
        case model::FluxUnits::microwatts:
            return w_to_uw(1.0);
        case model::FluxUnits::photons_per_second:
        case model::FluxUnits::electrons_per_second:  // the response is the QE
            return photons_per_joule(wavelength_um);
    }
    throw internal_error("unknown flux units");
}

const char* flux_word(model::FluxUnits flux, bool temporal_integration) {
    switch (flux) {
        case model::FluxUnits::watts:
            return temporal_integration ? "Joules" : "Watts";
        case model::FluxUnits::milliwatts:
            return temporal_integration ? "Millijoules" : "Milliwatts";
        case model::FluxUnits::microwatts:
            return temporal_integration ? "Microjoules" : "Microwatts";
        case model::FluxUnits::photons_per_second:
            return temporal_integration ? "Photons" : "Photons/s";
        case model::FluxUnits::electrons_per_second:
            return temporal_integration ? "Electrons" : "Electrons/s";
    }
    throw internal_error("unknown flux units");
}

}  // namespace

std::string data_units_string(model::FluxUnits flux, model::AreaUnits area, bool aperture,
                              bool temporal_integration, bool normalized) {
    std::string denominator = area == model::AreaUnits::m2 ? "m2" : "cm2";
    int terms = 1;
    if (!aperture) {
        denominator += " sr";
        ++terms;
    }
    if (normalized) {
        denominator += " um";
        ++terms;
    }
    if (terms > 1) denominator = "(" + denominator + ")";
    return std::string(flux_word(flux, temporal_integration)) + "/" + denominator;
}

OutputUnits::OutputUnits(const model::CaptureMethod& method,
                         const model::InstrumentProperties& properties, const SpectralGrid& grid) {
    const model::ImageFile& file = method.image_file;
    const std::vector<model::Channel>& channels = method.spectral_response.channels;
    m_channels = channels.size();
    m_bands = grid.size();

    const std::optional<double> g_number = model::g_number(properties);
    const double time_s = method.temporal_integration.time_s;
    m_description.aperture = g_number.has_value();
    m_description.temporal_integration = time_s > 0.0;
    m_description.g_number_per_sr = g_number.value_or(0.0);
    m_description.integration_time_s = m_description.temporal_integration ? time_s : 0.0;

    const double k_area = file.area_units == model::AreaUnits::m2 ? per_cm2_to_per_m2(1.0) : 1.0;
    const double k_aperture = g_number ? 1.0 / *g_number : 1.0;
    const double k_time = m_description.temporal_integration ? time_s : 1.0;
    const double k_common = k_area * k_aperture * k_time;

    if (method.type == model::CaptureMethodType::raw) {
        make_raw(file, grid, k_common);
        index_by_band();
        return;
    }
    // Δ_b · k_flux(λ_b): the part of the weight shared by every channel.
    std::vector<double> band_factor = trapezoid_weights_um(grid);
    for (std::size_t b = 0; b < m_bands; ++b) {
        band_factor[b] *= flux_factor(file.flux_units, grid.wavelengths_um()[b]);
    }

    std::vector<double> row(m_bands);
    m_bias.resize(m_channels);
    m_centers_um.resize(m_channels);
    m_fwhm_um.resize(m_channels);
    m_description.per_channel_units.reserve(m_channels);
    bool all_normalized = m_channels > 0;
    for (std::size_t c = 0; c < m_channels; ++c) {
        const model::Channel& channel = channels[c];
        const std::vector<double> response = model::channel_response(channel, grid);
        const double integral_um = integrate_trapezoid(grid, response);
        if (!(integral_um > 0.0)) {
            throw input_error("channel '" + channel.name +
                                  "': " + (channel.normalize ? "normalized channel has" : "has") +
                                  " no response on the bandpass " + number_text(grid.min_um()) +
                                  "-" + number_text(grid.max_um()) + " µm (∫ R dλ = " +
                                  number_text(integral_um) + " µm), expected a response inside it",
                              channel.where);
        }
        const double scale = channel.gain * k_common / (channel.normalize ? integral_um : 1.0);
        double peak = 0.0;
        for (std::size_t b = 0; b < m_bands; ++b) {
            row[b] = scale * response[b] * band_factor[b];
            peak = std::max(peak, std::fabs(row[b]));
        }
        // A gaussian's tails never reach 0: weights below 2⁻⁶⁴ of the channel's largest add
        // less than the sum's rounding (unless the radiance under them is 2¹² times the
        // radiance at the peak) and are dropped, so a channel weighs the few dozen bands
        // around its centre (support()), not the whole bandpass.
        for (std::size_t b = 0; b < m_bands; ++b) {
            if (std::fabs(row[b]) < peak * kNegligibleWeight) row[b] = 0.0;
        }
        add_row(row);
        m_bias[c] = channel.bias;
        m_centers_um[c] = model::channel_center_um(channel);
        m_fwhm_um[c] = model::channel_fwhm_um(channel);
        m_band_names.push_back(channel.name);
        m_description.per_channel_units.push_back(
            data_units_string(file.flux_units, file.area_units, m_description.aperture,
                              m_description.temporal_integration, channel.normalize));
        all_normalized = all_normalized && channel.normalize;
    }
    m_description.normalized = all_normalized;
    const std::vector<std::string>& each = m_description.per_channel_units;
    const bool mixed = std::any_of(each.begin(), each.end(),
                                   [&](const std::string& text) { return text != each.front(); });
    m_description.data_units =
        m_channels > 0 ? m_description.per_channel_units.front()
                       : data_units_string(file.flux_units, file.area_units, m_description.aperture,
                                           m_description.temporal_integration, false);
    if (!mixed) m_description.per_channel_units.clear();
    index_by_band();
}

void OutputUnits::apply(std::span<const double> radiance_w_per_cm2_sr_um,
                        std::span<double> out) const {
    if (radiance_w_per_cm2_sr_um.size() != m_bands || out.size() != m_channels) {
        throw internal_error("output units: " + std::to_string(radiance_w_per_cm2_sr_um.size()) +
                             " radiance bands and " + std::to_string(out.size()) +
                             " outputs, expected " + std::to_string(m_bands) + " and " +
                             std::to_string(m_channels));
    }
    // Band by band into every channel it feeds: each channel's sum takes its bands in band
    // order, as a loop over the channel's bands would (the same bits), but the channels'
    // additions do not wait for one another. Zero weights and zero radiances add nothing
    // (a finite sum plus ±0 is itself) and are skipped: a spectrally sampled pixel has few
    // bands that are not zero.
    std::fill(out.begin(), out.end(), 0.0);
    for (std::size_t b = 0; b < m_bands; ++b) {
        const double radiance = radiance_w_per_cm2_sr_um[b];
        if (radiance == 0.0) continue;
        for (std::size_t j = m_band_start[b]; j < m_band_start[b + 1]; ++j) {
            out[m_band_channel[j]] += m_band_weight[j] * radiance;
        }
    }
    for (std::size_t c = 0; c < m_channels; ++c) out[c] += m_bias[c];
}

void OutputUnits::apply(std::span<const double> radiance_w_per_cm2_sr_um,
                        std::span<const std::uint32_t> bands, std::span<double> out) const {
    if (bands.empty()) {
        apply(radiance_w_per_cm2_sr_um, out);
        return;
    }
    if (radiance_w_per_cm2_sr_um.size() != m_bands || out.size() != m_channels ||
        bands.back() >= m_bands) {
        throw internal_error("output units: " + std::to_string(radiance_w_per_cm2_sr_um.size()) +
                             " radiance bands (listed up to " + std::to_string(bands.back()) +
                             ") and " + std::to_string(out.size()) + " outputs, expected " +
                             std::to_string(m_bands) + " and " + std::to_string(m_channels));
    }
    // The listed bands in ascending order, as apply() takes the non-zero ones.
    std::fill(out.begin(), out.end(), 0.0);
    for (const std::uint32_t b : bands) {
        const double radiance = radiance_w_per_cm2_sr_um[b];
        if (radiance == 0.0) continue;
        for (std::size_t j = m_band_start[b]; j < m_band_start[b + 1]; ++j) {
            out[m_band_channel[j]] += m_band_weight[j] * radiance;
        }
    }
    for (std::size_t c = 0; c < m_channels; ++c) out[c] += m_bias[c];
}

void OutputUnits::index_by_band() {
    m_band_start.assign(m_bands + 1, 0);
    for (std::size_t c = 0; c < m_channels; ++c) {
        for (std::size_t k = 0; k < m_support[c].count; ++k) {
            if (m_weights[m_offset[c] + k] != 0.0) ++m_band_start[m_support[c].first + k + 1];
        }
    }
    for (std::size_t b = 0; b < m_bands; ++b) m_band_start[b + 1] += m_band_start[b];
    m_band_channel.resize(m_band_start[m_bands]);
    m_band_weight.resize(m_band_start[m_bands]);
    std::vector<std::size_t> next(m_band_start.begin(), m_band_start.end() - 1);
    for (std::size_t c = 0; c < m_channels; ++c) {  // ascending channels within each band
        for (std::size_t k = 0; k < m_support[c].count; ++k) {
            const double w = m_weights[m_offset[c] + k];
            if (w == 0.0) continue;
            const std::size_t j = next[m_support[c].first + k]++;
            m_band_channel[j] = static_cast<std::uint32_t>(c);
            m_band_weight[j] = w;
        }
    }
}

void OutputUnits::add_row(std::span<const double> row) {
    std::size_t first = 0;
    while (first < row.size() && row[first] == 0.0) ++first;
    std::size_t end = row.size();
    while (end > first && row[end - 1] == 0.0) --end;
    m_support.push_back(first < end ? BandRange{first, end - first} : BandRange{});
    m_offset.push_back(m_weights.size());
    m_weights.insert(m_weights.end(), row.begin() + static_cast<std::ptrdiff_t>(first),
                     row.begin() + static_cast<std::ptrdiff_t>(end));
}

double OutputUnits::channel_value(std::size_t channel, std::size_t first_band,
                                  std::span<const double> radiance_w_per_cm2_sr_um) const {
    const std::size_t count = radiance_w_per_cm2_sr_um.size();
    const BandRange needed = channel < m_channels ? support(channel) : BandRange{};
    if (channel >= m_channels || first_band > m_bands || count > m_bands - first_band ||
        (needed.count > 0 &&
         (needed.first < first_band || needed.first + needed.count > first_band + count))) {
        throw internal_error("output units: channel " + std::to_string(channel) + " from bands " +
                             std::to_string(first_band) + " + " + std::to_string(count) + " of " +
                             std::to_string(m_bands));
    }
    if (needed.count == 0) return m_bias[channel];
    // The support's bands (those outside weigh exactly 0).
    const double* w = m_weights.data() + m_offset[channel];
    const double* radiance = radiance_w_per_cm2_sr_um.data() + (needed.first - first_band);
    double sum = 0.0;
    for (std::size_t b = 0; b < needed.count; ++b) sum += w[b] * radiance[b];
    return sum + m_bias[channel];
}

void OutputUnits::make_raw(const model::ImageFile& file, const SpectralGrid& grid,
                           double k_common) {
    const std::span<const double> wl = grid.wavelengths_um();
    m_channels = m_bands;
    m_bias.assign(m_channels, 0.0);
    for (std::size_t b = 0; b < m_bands; ++b) {
        m_support.push_back({b, 1});  // band b alone
        m_offset.push_back(m_weights.size());
        m_weights.push_back(k_common * flux_factor(file.flux_units, wl[b]));
        m_centers_um.push_back(wl[b]);
        // The spacing around the sample: half the distance between its neighbours (one-sided
        // at the ends; 0 for a one-sample grid).
        const double lo = wl[b > 0 ? b - 1 : b];
        const double hi = wl[b + 1 < m_bands ? b + 1 : b];
        const double span = (b > 0 && b + 1 < m_bands) ? 0.5 * (hi - lo) : hi - lo;
        m_fwhm_um.push_back(span);
        char name[32];
        std::snprintf(name, sizeof name, "%.4f um", wl[b]);
        m_band_names.emplace_back(name);
    }
    m_description.normalized = true;
    m_description.data_units =
        data_units_string(file.flux_units, file.area_units, m_description.aperture,
                          m_description.temporal_integration, true);
}

}  // namespace glint::sensor
