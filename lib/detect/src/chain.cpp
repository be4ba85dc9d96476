// SPDX-License-Identifier: Apache-2.0
// DetectionChain: the per-pixel detector model, TDI accumulation, ADC, storage type and CFA
// selection (chain.h; the formulas are in docs/detector.md).
#include "glint/detect/chain.h"

#include <cmath>
#include <string>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/core/units.h"
#include "glint/detect/adc.h"

namespace glint::detect {

DetectionChain::DetectionChain(DetectionSettings settings, std::size_t samples)
    : m_settings(std::move(settings)), m_samples(samples) {
    if (m_samples == 0) throw input_error("a detection line needs at least one sample");
    if (m_settings.channels() == 0) throw input_error("a detection chain needs a channel");
    if (const auto& d = m_settings.detector) {
        m_electrons_per_fluence = m2_to_cm2(d->pixel_area_m2) * d->quantum_efficiency;
        m_dark_electrons = d->dark_electrons(m_settings.tdi_stages);
        if (!(m_dark_electrons <= kMaxPoissonMean)) {
            // Every pixel would fail; say why here rather than blame the first pixel.
            throw input_error(
                "the dark current gives " + format_shortest(m_dark_electrons) +
                " electrons per pixel (" + format_shortest(d->dark_current_density_a_per_m2) +
                " A/m2 over " + format_shortest(d->integration_time_s) + " s, " +
                std::to_string(m_settings.tdi_stages) +
                " stage(s)), more than the 1e15 glint can count: check the integration time "
                "and the dark current density");
        }
        m_read_sigma_e = d->read_noise_e;
        if (m_settings.tdi_mode == TdiMode::digital) {
            m_read_sigma_e *= std::sqrt(static_cast<double>(m_settings.tdi_stages));
        }
        m_adc = Adc(d->min_electrons, d->max_electrons, d->bit_depth);
    }
    if (const auto& cfa = m_settings.cfa) {
        m_cfa_period = cfa_period(cfa->pattern);
        m_cfa_channel.resize(m_cfa_period * m_cfa_period);
        for (std::size_t r = 0; r < m_cfa_period; ++r) {
            for (std::size_t c = 0; c < m_cfa_period; ++c) {
                const CfaFilter f = cfa_filter_at(cfa->pattern, cfa->phase, r, c);
                const int channel = cfa->channel_of_filter[static_cast<std::size_t>(f)];
                if (channel < 0 || static_cast<std::size_t>(channel) >= m_settings.channels()) {
                    throw input_error(std::string("the ") + cfa_pattern_name(cfa->pattern) +
                                      " pattern's " + cfa_filter_name(f) +
                                      " filter maps to no channel of focal plane \"" +
                                      m_settings.focal_plane + "\"");
                }
                m_cfa_channel[r * m_cfa_period + c] = channel;
            }
        }
    }
}

void DetectionChain::bad_value(double value, std::size_t channel, std::size_t sample) {
    throw input_error("sample " + std::to_string(sample) + ", band " + std::to_string(channel) +
                      ": photon fluence " + format_shortest(value) +
                      " per cm2 is not a finite value >= 0 (or exceeds 1e15 electrons)");
}

double DetectionChain::noisy_electrons(double mean, RandomStream& stream,
                                       std::uint64_t slot) const {
    stream.skip_to(slot << kWordsPerDrawLog2);
    // Shot noise and dark current of every stage are independent Poisson variates: their
    // sum is one Poisson variate of the summed mean. Read noise likewise: one Gaussian of
    // σ (charge-domain TDI) or σ√N (N stages each read, digital TDI).
    double electrons = static_cast<double>(sample_poisson(stream, mean));
    if (m_read_sigma_e > 0.0) electrons += m_read_sigma_e * sample_standard_normal(stream);
    return electrons;
}

double DetectionChain::finish(double electrons) const {
    if (m_settings.output == DetectOutput::electrons) return electrons;
    return stored_count(m_adc.count(electrons), m_settings.data_type);
}

double DetectionChain::detect_value(double value, RandomStream& stream, std::uint64_t pixel,
                                    std::size_t channel, std::size_t sample) const {
    if (!m_settings.detector) return value;
    const double mean = checked_mean(value, channel, sample);
    if (!m_settings.noise) return finish(mean);
    return finish(noisy_electrons(mean, stream, pixel * m_settings.channels() + channel));
}

void DetectionChain::process_line(LineKey key, std::span<const double> in,
                                  std::span<double> out) const {
    if (in.size() != input_values_per_line() || out.size() != output_values_per_line()) {
        throw internal_error("detection line of " + std::to_string(in.size()) + " -> " +
                             std::to_string(out.size()) + " values, expected " +
                             std::to_string(input_values_per_line()) + " -> " +
                             std::to_string(output_values_per_line()));
    }
    RandomStream stream(m_settings.seed, {kDetectStreamTag, key.capture_index});
    const std::size_t channels = m_settings.channels();
    const std::uint64_t first_pixel = static_cast<std::uint64_t>(key.line_in_capture) * m_samples;
    const int* cfa_row =
        m_settings.cfa ? m_cfa_channel.data() + (key.line_in_capture % m_cfa_period) * m_cfa_period
                       : nullptr;
    const std::size_t draws = cfa_row ? m_samples : m_samples * channels;
    // Draw i of the line: its sample, channel and output slot.
    auto draw_at = [&](std::size_t i, std::size_t& x, std::size_t& c) {
        if (cfa_row) {
            x = i;
            c = static_cast<std::size_t>(cfa_row[i % m_cfa_period]);
        } else {
            x = i / channels;
            c = i % channels;
        }
    };
    if (!m_settings.detector || !m_settings.noise) {
        for (std::size_t i = 0; i < draws; ++i) {
            std::size_t x = 0, c = 0;
            draw_at(i, x, c);
            out[i] = detect_value(in[x * channels + c], stream, first_pixel + x, c, x);
        }
        return;
    }
    process_noisy(stream, cfa_row, first_pixel, in, out);
}

}  // namespace glint::detect
